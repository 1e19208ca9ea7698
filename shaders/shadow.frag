// Shadow-mask fragment shader: a lifted leaf flattened onto the page plane writes how dark its
// shadow is there; strong where the leaf is just above the page, fainter as it rises. Its edges are
// soft as drawn, so the mask needs no blur and the pages take it with one bilinear tap (composite.frag):
// - at the leaf's free edges the leaf was drawn grown past them (page.vert), and each point knows how
//   far it lies from them; the penumbra there widens with the edge's height above the page;
// - where the curled paper runs along the light (the outline of a fold, seen from the light) the ray
//   grazes the paper: the shadow fades out as the paper turns edge-on, over a band on the page that is
//   wider the higher the fold stands (the projection spreads it).

uniform float uShadowStrength;     // darkening right under a leaf that has just lifted
uniform vec2 uPageSize;
uniform float uPenumbra;           // the half penumbra at the page, a fraction of the page width
uniform vec3 uLightDirection;      // unit, towards the light

in vec3 vWorldPosition;
in vec3 vNormal;
in vec2 vPagePoint;                // page point of the grown leaf: beyond the page by up to the widest half penumbra

out vec4 outColor;

const float kPenumbraGrowth = 3.0;  // as page.vert: the half penumbra of an edge half a page width up or more
const float kGrazing = 0.35;        // |n . light| below this fades the shadow towards the fold's outline

void main() {
    float width = uPageSize.x;
    float height = max(vWorldPosition.z, 0.0);
    float contact = smoothstep(0.0, 0.015 * width, height);  // no shadow where it touches
    float fade = 1.0 - 0.6 * clamp(height / width, 0.0, 1.0);
    // The free edges: the fore-edge, the head and the foot (the spine's side lies on the page).
    float toEdge = min(width - vPagePoint.x, min(vPagePoint.y, uPageSize.y - vPagePoint.y));
    float penumbra = uPenumbra * width * mix(1.0, kPenumbraGrowth, clamp(2.0 * height / width, 0.0, 1.0));
    float soft = smoothstep(-penumbra, penumbra, toEdge);
    float graze = smoothstep(0.0, kGrazing, abs(dot(normalize(vNormal), uLightDirection)));
    outColor = vec4(0.0, 0.0, 0.0, uShadowStrength * contact * fade * soft * graze);
}
