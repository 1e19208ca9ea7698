// The cached resting spread laid over the whole drawing buffer: one triangle that covers it, from
// gl_VertexID alone (no buffer is read).

void main() {
    vec2 corner = vec2(float((gl_VertexID & 1) << 2), float((gl_VertexID & 2) << 1));  // (0,0) (4,0) (0,4)
    gl_Position = vec4(corner - 1.0, 0.0, 1.0);
}
