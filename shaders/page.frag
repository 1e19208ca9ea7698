// Leaf fragment shader of a leaf in flight: shows the side of the leaf that faces the eye, found from
// the normal (Samuel, sec. 2.2), each side with its own texture mapping so it reads the right way
// round; then diffuse light from that side's own normal and gutter shading at the spine (paper_light.glsl,
// prepended). A blank side (single display's back) is paper with the other side's print faintly through
// it, mirrored as thin paper shows it. Flat pages take flat_page.frag.

uniform sampler2D uFacingTexture;  // the +z side in page space
uniform sampler2D uAwayTexture;
uniform mat3 uFacingUv;            // (x / w, y / h, 1) -> image (u, v) for each side
uniform mat3 uAwayUv;
uniform vec2 uPageSize;
uniform vec3 uEye;
uniform vec3 uLightDirection;      // unit, towards the light
uniform float uLighting;           // 0 or 1
uniform float uGutter;             // 0 off; 1 paper curving into the binding; 2 a hard board's hinge
uniform vec3 uPaper;               // colour under transparent texels
uniform vec2 uShowThrough;         // (+z side seen, -z side seen): how much of the other side's print shows
uniform vec2 uMirrorLight;         // (+z side seen, -z side seen): 1 where that side takes uMirroredLight
uniform vec3 uMirroredLight;       // uLightDirection mirrored across the spine's plane

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
    vec4 through = vec4(0.0);  // the other side's texel at the same point of the paper
    float showThrough = facing ? uShowThrough.x : uShowThrough.y;
    if (facing) {
        texel = texture(uFacingTexture, (uFacingUv * vec3(st, 1.0)).xy);
        if (showThrough > 0.0) through = texture(uAwayTexture, (uAwayUv * vec3(st, 1.0)).xy);
    } else {
        texel = texture(uAwayTexture, (uAwayUv * vec3(st, 1.0)).xy);
        if (showThrough > 0.0) through = texture(uFacingTexture, (uFacingUv * vec3(st, 1.0)).xy);
    }
    vec3 color = mix(uPaper, texel.rgb, texel.a);
    color = mix(color, mix(uPaper, through.rgb, through.a), showThrough);

    // The side seen is lit by its own normal (a back is lit as a back), relative to a flat page so
    // resting pages keep their true colours. A blank back in single display takes the light mirrored
    // across the spine: the eye looks from the page's middle, so a leaf rising over the spine turns its
    // back away from the upper-left light, and the paper would read as a grey slab; it is lit as the
    // front is at the same angle.
    vec3 sideNormal = facing ? n : -n;
    vec3 lightFrom = (facing ? uMirrorLight.x : uMirrorLight.y) > 0.5 ? uMirroredLight : uLightDirection;
    float lit = kAmbient + (1.0 - kAmbient) * max(dot(sideNormal, lightFrom), 0.0);
    float light = mix(1.0, lit / diffuse(vec3(0.0, 0.0, 1.0)), uLighting);
    light = gutterLight(light, st.x, uGutter);
    outColor = vec4(color * light, 1.0);
}
