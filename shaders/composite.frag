// Lays a texture over the canvas's pixels with a triangle: the cached resting spread each frame of a
// turn, darkened by the lifted leaves' shadow (the mask's alpha, one bilinear tap: its edge is soft as
// drawn, shadow.frag), so the shadow costs no pass of its own; or, with no shadow, a moving frame drawn
// at a smaller scale, filtered up to the canvas (linear). Colour is multiplied, alpha kept. The cache
// may lie a whole number of pixels away (the camera slid along the page plane since it was drawn).

uniform sampler2D uCache;
uniform sampler2D uShadowMask;
uniform vec2 uViewportInverse;  // 1 / target size: gl_FragCoord to texture coordinates (cache and mask alike)
uniform float uShadowStrength;  // 1: darken by the mask; 0: copy
uniform vec2 uCacheOffset;      // where the cache's origin lies on the target, in pixels

out vec4 outColor;

void main() {
    vec2 at = gl_FragCoord.xy * uViewportInverse;
    vec2 cached = (gl_FragCoord.xy - uCacheOffset) * uViewportInverse;
    // Past the cache's edge lies nothing that rests (clamping would smear its edge texels).
    vec4 color = vec4(0.0);
    if (all(greaterThanEqual(cached, vec2(0.0))) && all(lessThanEqual(cached, vec2(1.0)))) color = texture(uCache, cached);
    // A branch, not a product: a copy reads one texture (a software rasterizer pays for each).
    if (uShadowStrength > 0.5) color.rgb *= 1.0 - texture(uShadowMask, at).a;
    outColor = color;
}
