// Leaf vertex shader: the static grid holds flat page coordinates; the cone deformation and the
// paper's finite-difference normal are computed here from the curl uniforms, then the leaf is placed
// in the world (spine position, mirroring for backward turns). The renderer prepends
// "#version 300 es", precision, and cone_curl.glsl; with SHADOW_PASS defined the leaf, grown by its
// shadow's half penumbra past its free edges, is instead flattened onto the page plane along the light,
// for the shadow mask (shadow.frag fades it out across its edges and where the paper runs along the
// light, so it needs the normal too).

uniform vec3 uCurl;            // theta, apexY, rho (sanitized in C++)
uniform vec4 uCurlTrig;        // sin theta, cos theta, sin rho, cos rho: the same for every vertex, so from C++
uniform vec2 uLeaf;            // x: 1 for a resting leaf, flat (theta 90 deg): no cone to evaluate; y: unused
uniform float uNormalStep;     // finite-difference step, ~1e-3 of the page height
uniform mat4 uPageToWorld;     // rigid placement of the leaf (may mirror)
uniform mat4 uViewProjection;
#ifdef SHADOW_PASS
uniform vec3 uLightDirection;  // unit, towards the light
uniform vec2 uPageSize;
uniform float uPenumbra;       // the shadow's half penumbra at the page, a fraction of the page width
const float kPenumbraGrowth = 3.0;  // the half penumbra of a leaf's edge high above the page (shadow.frag)
#endif

layout(location = 0) in vec2 aPagePoint;  // flat page coordinates: x from the spine, y along it

out vec3 vWorldPosition;       // also captured by transform feedback for the GPU-vs-C++ test
out vec3 vNormal;              // world normal of the +z side; also captured
out vec2 vPagePoint;

void main() {
    vec2 q = aPagePoint;
#ifdef SHADOW_PASS
    // Stretched so the fore-edge, head and foot lie the widest half penumbra out (the spine stays).
    float grow = kPenumbraGrowth * uPenumbra * uPageSize.x;
    q = vec2(q.x * (1.0 + grow / uPageSize.x), (q.y - 0.5 * uPageSize.y) * (1.0 + 2.0 * grow / uPageSize.y) + 0.5 * uPageSize.y);
#endif
    vec3 p;
    vec3 n = vec3(0.0, 0.0, 1.0);
    if (uLeaf.x > 0.5) {
        // A flat page is its own cone at theta = 90 deg: only the turn about the spine is left.
        p = rotateAboutSpine(vec3(q, 0.0), uCurlTrig.zw);
        n = rotateAboutSpine(n, uCurlTrig.zw);
    } else {
        p = curlPoint(q, uCurl.y, uCurlTrig);
        // Samuel, eqs. (1)-(3): project two neighbours a small step away and cross the differences.
        vec3 ps = curlPoint(q + vec2(uNormalStep, 0.0), uCurl.y, uCurlTrig);
        vec3 pt = curlPoint(q + vec2(0.0, uNormalStep), uCurl.y, uCurlTrig);
        n = normalize(cross(ps - p, pt - p));
    }
    // n is the normal of the +z side, found before any mirroring: placing it keeps it on that side.
    vNormal = mat3(uPageToWorld) * n;
    vec4 world = uPageToWorld * vec4(p, 1.0);
    vWorldPosition = world.xyz;
    vPagePoint = q;
#ifdef SHADOW_PASS
    // Where the light ray through this point meets the page plane: the farther up, the farther away.
    world.xy -= uLightDirection.xy * (world.z / uLightDirection.z);
    world.z = 0.0;
#endif
    gl_Position = uViewProjection * world;
}
