// The lifted leaves' soft shadow on the resting pages, drawn over the cached resting spread each frame
// of a turn: the pages' flat geometry (flat_page.vert) with blending that multiplies what is there by
// this output (BookRenderer: blend func ZERO, SRC_COLOR for colour; alpha kept). The mask's edge is
// soft as drawn (shadow.frag), so one bilinear tap takes it.

uniform sampler2D uShadowMask;     // alpha of the lifted leaves' shadow, in screen space
uniform vec2 uViewportInverse;     // 1 / drawing buffer size: gl_FragCoord to mask coordinates

in vec2 vPagePoint;

out vec4 outColor;

void main() {
    outColor = vec4(vec3(1.0 - texture(uShadowMask, gl_FragCoord.xy * uViewportInverse).a), 1.0);
}
