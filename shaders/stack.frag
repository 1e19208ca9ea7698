// Stack-edge fragment shader: the paper's edge (a little darker than its face, with a faint line
// between leaves while they are a few pixels apart) or a board's, lit by the pages' light.

uniform vec3 uLightDirection;  // unit, towards the light
uniform float uLighting;       // 0 or 1
uniform vec3 uPaper;

in float vLeaves;
in vec3 vNormal;

out vec4 outColor;

const float kAmbient = 0.35;
const vec3 kBoard = vec3(0.36, 0.31, 0.27);  // the edge of a cover's board

float diffuse(vec3 n) { return kAmbient + (1.0 - kAmbient) * max(dot(n, uLightDirection), 0.0); }

void main() {
    vec3 color = kBoard;
    if (vLeaves >= 0.0) {
        // 1 on a boundary between leaves, 0 halfway; the line is about a pixel wide and fades out
        // once leaves come closer than two pixels (it would only alias).
        float step = fwidth(vLeaves);
        float boundary = abs(fract(vLeaves) - 0.5) * 2.0;
        float line = smoothstep(1.0 - 2.0 * step, 1.0, boundary) * (1.0 - smoothstep(0.25, 0.5, step));
        color = uPaper * (0.9 - 0.2 * line);
    }
    // Lit like the pages (relative to a flat page); without lighting a fixed shade still sets it off.
    vec3 n = normalize(vNormal);
    float light = mix(0.9, diffuse(n) / diffuse(vec3(0.0, 0.0, 1.0)), uLighting);
    outColor = vec4(color * light, 1.0);
}
