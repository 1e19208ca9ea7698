// Lays a texture over the canvas's pixels with a triangle: the cached resting spread each frame of a
// turn, darkened by the lifted leaves' shadow (the mask's alpha, one bilinear tap: its edge is soft as
// drawn, shadow.frag), so the shadow costs no pass of its own; or, with no shadow, a moving frame drawn
// at a smaller scale, filtered up to the canvas (linear). Colour is multiplied, alpha kept.

uniform sampler2D uCache;
uniform sampler2D uShadowMask;
uniform vec2 uViewportInverse;  // 1 / target size: gl_FragCoord to texture coordinates (cache and mask alike)
uniform float uShadowStrength;  // 1: darken by the mask; 0: copy

out vec4 outColor;

void main() {
    vec2 at = gl_FragCoord.xy * uViewportInverse;
    vec4 color = texture(uCache, at);
    // A branch, not a product: a copy reads one texture (a software rasterizer pays for each).
    if (uShadowStrength > 0.5) color.rgb *= 1.0 - texture(uShadowMask, at).a;
    outColor = color;
}
