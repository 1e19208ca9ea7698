// Shadow-mask fragment shader: a lifted leaf flattened onto the page plane writes how dark its
// shadow is there; strong where the leaf is just above the page, fainter as it rises.

uniform float uShadowStrength;     // darkening right under a leaf that has just lifted
uniform float uPageWidth;

in vec3 vWorldPosition;
in vec3 vNormal;
in vec2 vPagePoint;

out vec4 outColor;

void main() {
    float height = max(vWorldPosition.z, 0.0);
    float contact = smoothstep(0.0, 0.015 * uPageWidth, height);  // no shadow where it touches
    float fade = 1.0 - 0.6 * clamp(height / uPageWidth, 0.0, 1.0);
    outColor = vec4(0.0, 0.0, 0.0, uShadowStrength * contact * fade);
}
