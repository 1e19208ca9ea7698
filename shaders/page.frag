// Leaf fragment shader of a leaf in flight: shows the side of the leaf that faces the eye, found from
// the normal (Samuel, sec. 2.2), each side with its own texture mapping so it reads the right way
// round; then diffuse light from that side's own normal and gutter shading at the spine (paper_light.glsl,
// prepended). Flat pages take flat_page.frag; the shadow on them is shadow_receive.frag's.

uniform sampler2D uFacingTexture;  // the +z side in page space
uniform sampler2D uAwayTexture;
uniform mat3 uFacingUv;            // (x / w, y / h, 1) -> image (u, v) for each side
uniform mat3 uAwayUv;
uniform vec2 uPageSize;
uniform vec3 uEye;
uniform vec3 uLightDirection;      // unit, towards the light
uniform float uLighting;           // 0 or 1
uniform float uGutter;             // 0 off; 1 paper curving into the binding; 2 a hard board's hinge
uniform vec3 uPaper;               // colour under transparent texels

in vec3 vWorldPosition;
in vec3 vNormal;
in vec2 vPagePoint;

out vec4 outColor;

const float kAmbient = 0.35;

float diffuse(vec3 n) { return kAmbient + (1.0 - kAmbient) * max(dot(n, uLightDirection), 0.0); }

void main() {
    vec3 n = normalize(vNormal);
    bool facing = dot(n, uEye - vWorldPosition) >= 0.0;
    vec2 st = vPagePoint / uPageSize;
    // A branch, not ?: — a select would sample both textures (software rasterizers pay for both).
    vec4 texel;
    if (facing) {
        texel = texture(uFacingTexture, (uFacingUv * vec3(st, 1.0)).xy);
    } else {
        texel = texture(uAwayTexture, (uAwayUv * vec3(st, 1.0)).xy);
    }
    vec3 color = mix(uPaper, texel.rgb, texel.a);

    // The side seen is lit by its own normal (a back is lit as a back), relative to a flat page so
    // resting pages keep their true colours.
    vec3 sideNormal = facing ? n : -n;
    float light = mix(1.0, diffuse(sideNormal) / diffuse(vec3(0.0, 0.0, 1.0)), uLighting);
    light = gutterLight(light, st.x, uGutter);
    outColor = vec4(color * light, 1.0);
}
