// Shadow-mask fragment shader: a lifted leaf flattened onto the page plane writes how dark its
// shadow is there; strong where the leaf is just above the page, fainter as it rises. Its edge is
// soft already: the leaf was drawn grown by a half penumbra past its free edges (page.vert), and each
// point knows from the leaf's own geometry how far it lies from them, so the shadow fades across the
// edge and the mask needs no blur: the pages take it with one bilinear tap (shadow_receive.frag).

uniform float uShadowStrength;     // darkening right under a leaf that has just lifted
uniform vec2 uPageSize;
uniform float uPenumbra;           // the half penumbra, a fraction of the page width (page.vert grew the leaf by it)

in vec3 vWorldPosition;
in vec3 vNormal;
in vec2 vPagePoint;                // page point of the grown leaf: beyond the page by up to a half penumbra

out vec4 outColor;

void main() {
    float width = uPageSize.x;
    float height = max(vWorldPosition.z, 0.0);
    float contact = smoothstep(0.0, 0.015 * width, height);  // no shadow where it touches
    float fade = 1.0 - 0.6 * clamp(height / width, 0.0, 1.0);
    // The free edges: the fore-edge, the head and the foot (the spine's side lies on the page).
    float toEdge = min(width - vPagePoint.x, min(vPagePoint.y, uPageSize.y - vPagePoint.y));
    float soft = smoothstep(-uPenumbra * width, uPenumbra * width, toEdge);
    outColor = vec4(0.0, 0.0, 0.0, uShadowStrength * contact * fade * soft);
}
