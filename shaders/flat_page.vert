// Vertex shader of a flat page (a resting leaf): no cone and no normal, only the turn about the spine
// (0 or 180 degrees) and the leaf's placement, the very operations of page.vert's resting path, so a
// flat page lands on the same pixels either way. cone_curl.glsl is prepended (rotateAboutSpine).

uniform vec4 uCurlTrig;        // sin theta, cos theta, sin rho, cos rho (only rho's are read)
uniform mat4 uPageToWorld;     // rigid placement of the leaf (may mirror)
uniform mat4 uViewProjection;

layout(location = 0) in vec2 aPagePoint;  // flat page coordinates: x from the spine, y along it

out vec2 vPagePoint;

void main() {
    vec3 p = rotateAboutSpine(vec3(aPagePoint, 0.0), uCurlTrig.zw);
    vPagePoint = aPagePoint;
    gl_Position = uViewProjection * (uPageToWorld * vec4(p, 1.0));
}
