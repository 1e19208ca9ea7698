// Stack-edge vertex shader: the stacks' edge faces come from C++ (book_stacks.cpp) already in the
// world, rebuilt only when the leaves on a side change; here they are only projected.

uniform mat4 uViewProjection;

layout(location = 1) in vec4 aStackPoint;   // world x y z, then s: depth in leaves (-1 on a board)
layout(location = 2) in vec4 aStackNormal;  // world normal of the face, towards the eye; w unused

out float vLeaves;
out vec3 vNormal;

void main() {
    vLeaves = aStackPoint.w;
    vNormal = aStackNormal.xyz;
    gl_Position = uViewProjection * vec4(aStackPoint.xyz, 1.0);
}
