// Edge-mark vertex shader: tabs and ticks on the page blocks' fore-edge come from C++
// (cpp/core/edge_marks.cpp, coloured in cpp/renderer/edge_marks_renderer.cpp) already in the world.

uniform mat4 uViewProjection;

layout(location = 3) in vec4 aMarkPoint;  // world x y z, then u: across the mark, 0 to 1
layout(location = 4) in vec4 aMarkColor;  // v: along the mark, 0 to 1, then r g b

out vec2 vMarkUv;
out vec3 vMarkColor;

void main() {
    vMarkUv = vec2(aMarkPoint.w, aMarkColor.x);
    vMarkColor = aMarkColor.yzw;
    gl_Position = uViewProjection * vec4(aMarkPoint.xyz, 1.0);
}
