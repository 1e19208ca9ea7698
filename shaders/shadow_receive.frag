// The lifted leaves' soft shadow on the resting pages, drawn over the cached resting spread each frame
// of a turn: the pages' flat geometry (flat_page.vert) with blending that multiplies what is there by
// this output (BookRenderer: blend func ZERO, SRC_COLOR for colour; alpha kept).

uniform sampler2D uShadowMask;     // alpha of the lifted leaves' shadow, in screen space
uniform vec2 uShadowTexel;         // 1 / mask size
uniform vec2 uViewportInverse;     // 1 / drawing buffer size: gl_FragCoord to mask coordinates

in vec2 vPagePoint;

out vec4 outColor;

void main() {
    // Four bilinear taps a texel and a half off each way: a tent blur about 5 mask texels wide
    // (10 screen pixels) that softens the projected edge for the price of four samples.
    vec2 at = gl_FragCoord.xy * uViewportInverse;
    vec2 d = 1.5 * uShadowTexel;
    float shadow = texture(uShadowMask, at + vec2(-d.x, -d.y)).a + texture(uShadowMask, at + vec2(d.x, -d.y)).a
                 + texture(uShadowMask, at + vec2(-d.x, d.y)).a + texture(uShadowMask, at + vec2(d.x, d.y)).a;
    outColor = vec4(vec3(1.0 - 0.25 * shadow), 1.0);
}
