// Page fragment shader: picks the front or the back texture by which way the normal faces the eye
// (Samuel, sec. 2.2); the back is sampled with u mirrored so it reads correctly once turned.

uniform sampler2D uFrontTexture;
uniform sampler2D uBackTexture;
uniform vec3 uEye;             // camera position in world space
uniform float uShading;        // 0: flat colour, 1: full diffuse from the normal

in vec3 vWorldPosition;
in vec3 vNormal;
in vec2 vTexCoord;

out vec4 outColor;

void main() {
    vec3 n = normalize(vNormal);
    vec3 toEye = normalize(uEye - vWorldPosition);
    float facing = dot(n, toEye);
    vec4 color = facing >= 0.0
        ? texture(uFrontTexture, vTexCoord)
        : texture(uBackTexture, vec2(1.0 - vTexCoord.x, vTexCoord.y));
    // Light from the eye: a curl darkens as it turns away, so its shape reads as 3D.
    float diffuse = abs(facing);
    float light = mix(1.0, 0.55 + 0.45 * diffuse, uShading);
    outColor = vec4(color.rgb * light, 1.0);
}
