// Page vertex shader: the static grid holds flat page coordinates; the cone deformation and the
// paper's finite-difference normal are computed here from the curl uniforms. The renderer prepends
// "#version 300 es", precision and cone_curl.glsl.

uniform vec3 uCurl;            // theta, apexY, rho (sanitized in C++)
uniform vec2 uPageSize;        // width, height in world units
uniform float uNormalStep;     // finite-difference step, ~1e-3 of the page height
uniform mat4 uViewProjection;

in vec2 aPagePoint;            // flat page coordinates: x from the spine, y from the bottom edge

out vec3 vWorldPosition;       // also captured by transform feedback for the GPU-vs-C++ test
out vec3 vNormal;              // front-face normal; also captured
out vec2 vTexCoord;            // front texture coordinates (u across from the spine, v down)

void main() {
    vec3 p = curlPoint(aPagePoint, uCurl);
    // Samuel, eqs. (1)-(3): project two neighbours a small step away and cross the differences.
    vec3 ps = curlPoint(aPagePoint + vec2(uNormalStep, 0.0), uCurl);
    vec3 pt = curlPoint(aPagePoint + vec2(0.0, uNormalStep), uCurl);
    vNormal = normalize(cross(ps - p, pt - p));
    vWorldPosition = p;
    vTexCoord = vec2(aPagePoint.x / uPageSize.x, 1.0 - aPagePoint.y / uPageSize.y);
    gl_Position = uViewProjection * vec4(p, 1.0);
}
