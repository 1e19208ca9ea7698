// Edge-mark fragment shader: a coloured index tab (a little lighter towards its tip, with a darker
// rim about a pixel wide so neighbouring tabs stay apart) or a search tick (its colour, solid).

in vec2 vMarkUv;
in vec3 vMarkColor;

out vec4 outColor;

void main() {
    // Distance to the nearest side in pixels, from how fast u and v change across a pixel.
    vec2 toSide = min(vMarkUv, 1.0 - vMarkUv) / max(fwidth(vMarkUv), vec2(1e-6));
    float rim = 1.0 - smoothstep(0.5, 1.5, min(toSide.x, toSide.y));
    vec3 color = vMarkColor * mix(0.92, 1.08, vMarkUv.x);
    outColor = vec4(mix(color, vMarkColor * 0.6, rim), 1.0);
}
