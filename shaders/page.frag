// Leaf fragment shader: shows the side of the leaf that faces the eye, found from the normal
// (Samuel, sec. 2.2), each side with its own texture mapping so it reads the right way round; then
// diffuse light from that side's own normal, gutter shading at the spine, and the soft shadow that
// lifted leaves cast on resting pages.

uniform sampler2D uFacingTexture;  // the +z side in page space
uniform sampler2D uAwayTexture;
uniform mat3 uFacingUv;            // (x / w, y / h, 1) -> image (u, v) for each side
uniform mat3 uAwayUv;
uniform vec2 uPageSize;
uniform vec3 uEye;
uniform vec3 uLightDirection;      // unit, towards the light
uniform float uLighting;           // 0 or 1
uniform float uGutter;             // 0 off; 1 paper curving into the binding; 2 a hard board's hinge
uniform vec2 uLeaf;                // x: page.vert's (a flat resting leaf); y: 1 where it receives the shadow mask
uniform sampler2D uShadowMask;     // alpha of the lifted leaves' shadow, in screen space
uniform vec2 uShadowTexel;         // 1 / mask size
uniform vec2 uViewportInverse;     // 1 / drawing buffer size: gl_FragCoord to mask coordinates
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
    // Paper curves down into the binding: darker within a few percent of the width of the spine
    // (beyond a quarter of the width the term is below 1/1000 and is skipped). A board stays flat: its
    // hinge is a groove pressed in parallel to the spine, a shaded furrow with a lit lip beside it.
    if (uGutter > 1.5) {
        if (st.x < 0.12) {
            float groove = (st.x - 0.05) / 0.009;
            float lip = (st.x - 0.068) / 0.006;
            light *= 1.0 - 0.38 * exp(-groove * groove) + 0.12 * exp(-lip * lip);
        }
    } else if (uGutter > 0.0 && st.x < 0.25) {
        light *= 1.0 - 0.22 * exp(-st.x / 0.045);
    }

    if (uLeaf.y > 0.0) {
        // Four bilinear taps a texel and a half off each way: a tent blur about 5 mask texels wide
        // (10 screen pixels) that softens the projected edge for the price of four samples.
        vec2 at = gl_FragCoord.xy * uViewportInverse;
        vec2 d = 1.5 * uShadowTexel;
        float shadow = texture(uShadowMask, at + vec2(-d.x, -d.y)).a + texture(uShadowMask, at + vec2(d.x, -d.y)).a
                     + texture(uShadowMask, at + vec2(-d.x, d.y)).a + texture(uShadowMask, at + vec2(d.x, d.y)).a;
        light *= 1.0 - 0.25 * shadow;
    }
    outColor = vec4(color * light, 1.0);
}
