// The cone deformation in GLSL ES 3.00, the float32 twin of cpp/core/cone_deform.cpp (same forms,
// same guards). Prepended to page.vert by the renderer; uniforms arrive already sanitized by C++.

const float kPi = 3.14159265358979;
const float kHalfPi = 1.57079632679490;
const float kTwoPi = 6.28318530717959;

// GLSL ES leaves the precision of sin/cos/atan unspecified; SwiftShader's are off by ~1e-5, which
// R * sin(beta) with R ~ 16 turns into 1e-4 of the page. These stay within a few float32 ulps.
float preciseSin(float x) {
    x -= kTwoPi * floor(x / kTwoPi + 0.5);         // to [-pi, pi]
    if (x > kHalfPi) x = kPi - x;                    // sin(pi - x) = sin(x): to [-pi/2, pi/2]
    else if (x < -kHalfPi) x = -kPi - x;
    float x2 = x * x;                                // odd Taylor polynomial to x^13: error < 1e-9
    return x * (1.0 + x2 * (-1.0 / 6.0 + x2 * (1.0 / 120.0 + x2 * (-1.0 / 5040.0 + x2 * (1.0 / 362880.0
             + x2 * (-1.0 / 39916800.0 + x2 * (1.0 / 6227020800.0)))))));
}

float preciseCos(float x) { return preciseSin(kHalfPi - x); }

// atan(x, d) for d > 0: one Newton step on f(a) = d sin a - x cos a squares the built-in's error
// away; f' = d cos a + x sin a ~ |(x, d)| never vanishes near the root.
float preciseAtan(float x, float d) {
    float a = atan(x, d);
    float s = preciseSin(a);
    float c = preciseCos(a);
    return a - (d * s - x * c) / (d * c + x * s);
}

// 1 - cos(b) without cancellation when the page is nearly flat.
float oneMinusCos(float b) {
    float s = preciseSin(0.5 * b);
    return 2.0 * s * s;
}

// The cone's apex height and (sin theta, cos theta), which are the same for every vertex and so come
// from C++. Returns the point on the cone before the spine rotation; beta out.
vec3 deformOntoCone(vec2 q, float apexY, vec2 sinCosTheta, out float beta) {
    float sinT = sinCosTheta.x;
    float cosT = sinCosTheta.y;
    float R = length(vec2(q.x, q.y - apexY));
    // asin(x / R) as atan(x, y - Ay): the same angle with the apex below the page, and exact near x = R.
    beta = clamp(preciseAtan(q.x, q.y - apexY) / sinT, -kPi, kPi);
    float r = R * sinT;
    float omc = oneMinusCos(beta);
    // R + Ay as (R^2 - Ay^2) / (R - Ay): no cancellation for a far apex.
    float heightAboveApexMinusAy = (q.x * q.x + q.y * (q.y - 2.0 * apexY)) / (R - apexY);
    return vec3(r * preciseSin(beta), heightAboveApexMinusAy - r * omc * sinT, r * omc * cosT);
}

// sinCosRho = (sin rho, cos rho).
vec3 rotateAboutSpine(vec3 v, vec2 sinCosRho) {
    float s = sinCosRho.x;
    float c = sinCosRho.y;
    return vec3(v.x * c - v.z * s, v.y, v.x * s + v.z * c);
}

// trig = (sin theta, cos theta, sin rho, cos rho) of the leaf's curl.
vec3 curlPoint(vec2 q, float apexY, vec4 trig) {
    float beta;
    return rotateAboutSpine(deformOntoCone(q, apexY, trig.xy, beta), trig.zw);
}
