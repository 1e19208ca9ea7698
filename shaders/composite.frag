// Copies a texture over the whole canvas (used where a blit cannot write: a multisampled canvas): the
// cached resting spread, texel for pixel (its filter is nearest), so every sample of the pixel gets the
// cached, already resolved colour; or a moving frame drawn at a smaller scale, filtered up (linear).

uniform sampler2D uCache;
uniform vec2 uViewportInverse;  // 1 / canvas size: gl_FragCoord to texture coordinates

out vec4 outColor;

void main() {
    outColor = texture(uCache, gl_FragCoord.xy * uViewportInverse);
}
