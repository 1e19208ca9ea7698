// Cone deformation in forms that stay accurate when the page is nearly flat (theta -> pi/2, beta -> 0)
// and when the apex is far away (R large): the shader uses the same forms in float32.
#include "cone_deform.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace conecurl {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kHalfPi = kPi / 2.0;

// 1 - cos(b) without cancellation for small b.
double oneMinusCos(double b) {
    const double s = std::sin(0.5 * b);
    return 2.0 * s * s;
}

}  // namespace

CurlParams sanitize(const CurlParams& p) {
    CurlParams out = p;
    out.theta = std::isnan(p.theta) ? kHalfPi : std::clamp(p.theta, kThetaFloor, kHalfPi);
    out.apexY = std::isnan(p.apexY) ? CurlSchedule{}.apexRest : std::clamp(p.apexY, kApexFloor, kApexCeiling);
    out.rho = std::isfinite(p.rho) ? p.rho : 0.0;
    return out;
}

double coneBeta(glm::dvec2 q, const CurlParams& raw) {
    const CurlParams p = sanitize(raw);
    // asin(x / R) with R = |(x, y - Ay)|; y - Ay > 0 on the page, so atan2 gives the same angle.
    return std::clamp(std::atan2(q.x, q.y - p.apexY) / std::sin(p.theta), -kPi, kPi);
}

glm::dvec3 deformOntoCone(glm::dvec2 q, const CurlParams& raw) {
    const CurlParams p = sanitize(raw);
    const double sinT = std::sin(p.theta);
    const double cosT = std::cos(p.theta);
    const double dy = q.y - p.apexY;
    const double R = std::hypot(q.x, dy);
    if (R == 0.0) return {q.x, q.y, 0.0};

    const double beta = coneBeta(q, p);
    const double r = R * sinT;
    const double omc = oneMinusCos(beta);
    // R + Ay, rewritten as (R^2 - Ay^2) / (R - Ay) so a far apex (|Ay| ~ 15) loses no digits.
    const double heightAboveApexMinusAy = (q.x * q.x + q.y * (q.y - 2.0 * p.apexY)) / (R - p.apexY);
    return {
        r * std::sin(beta),
        heightAboveApexMinusAy - r * omc * sinT,
        r * omc * cosT,
    };
}

glm::dvec3 rotateAboutSpine(glm::dvec3 v, double rho) {
    const double c = std::cos(rho);
    const double s = std::sin(rho);
    return {v.x * c - v.z * s, v.y, v.x * s + v.z * c};
}

glm::dvec3 curlPoint(glm::dvec2 q, const CurlParams& raw) {
    const CurlParams p = sanitize(raw);
    return rotateAboutSpine(deformOntoCone(q, p), p.rho);
}

glm::dvec3 curlNormalAnalytic(glm::dvec2 q, const CurlParams& raw) {
    const CurlParams p = sanitize(raw);
    const double sinT = std::sin(p.theta);
    const double cosT = std::cos(p.theta);
    const double beta = coneBeta(q, p);
    const double omc = oneMinusCos(beta);
    // (-cos t sin b, sin t cos t (1 - cos b), sin^2 t + cos^2 t cos b); the last is 1 - cos^2 t (1 - cos b).
    const glm::dvec3 n{-cosT * std::sin(beta), sinT * cosT * omc, 1.0 - cosT * cosT * omc};
    return rotateAboutSpine(n, p.rho);
}

glm::dvec3 curlNormalFiniteDifference(glm::dvec2 q, const CurlParams& raw, double delta) {
    const CurlParams p = sanitize(raw);
    const glm::dvec3 v0 = curlPoint(q, p);
    const glm::dvec3 vs = curlPoint({q.x + delta, q.y}, p);
    const glm::dvec3 vt = curlPoint({q.x, q.y + delta}, p);
    return glm::normalize(glm::cross(vs - v0, vt - v0));
}

}  // namespace conecurl
