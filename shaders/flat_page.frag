// Fragment shader of a flat page: its normal is constant, so which side is seen and how the light
// falls on it are worked out once per page in C++ (BookRenderer::drawFlatPage); here only the texture,
// the paper under transparent texels and the gutter (paper_light.glsl, prepended). Same output as
// page.frag for a flat page, for a fraction of its work.

uniform sampler2D uFacingTexture;  // the side seen
uniform mat3 uFacingUv;            // (x / w, y / h, 1) -> image (u, v) of that side
uniform vec2 uPageSize;
uniform float uFlatLight;          // the side's diffuse light relative to a flat page (1 without lighting)
uniform float uGutter;             // 0 off; 1 paper curving into the binding; 2 a hard board's hinge
uniform vec3 uPaper;               // colour under transparent texels

in vec2 vPagePoint;

out vec4 outColor;

void main() {
    vec2 st = vPagePoint / uPageSize;
    vec4 texel = texture(uFacingTexture, (uFacingUv * vec3(st, 1.0)).xy);
    vec3 color = mix(uPaper, texel.rgb, texel.a);
    outColor = vec4(color * gutterLight(uFlatLight, st.x, uGutter), 1.0);
}
