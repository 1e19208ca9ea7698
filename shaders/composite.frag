// Copies the cached resting spread texel for pixel (used where a blit cannot write: a multisampled
// canvas), so every sample of the pixel gets the cached, already resolved colour.

uniform sampler2D uCache;

out vec4 outColor;

void main() {
    outColor = texelFetch(uCache, ivec2(gl_FragCoord.xy), 0);
}
