// Evaluates the three-phase schedule; docs/cone-curl-math.md ("The three-phase schedule") has the table.
#include "curl_schedule.hpp"

#include <algorithm>
#include <cmath>

namespace conecurl {
namespace {

constexpr double kPi = 3.14159265358979323846;

double lerp(double f, double a, double b) { return a + (b - a) * f; }

// Monotone cubic Hermite interpolation (Fritsch-Carlson) through four keys (x[i], y[i]) with zero
// slope at both ends: C1, and each piece stays between its two keys (no overshoot past a key pose).
double smoothThrough(const double (&x)[4], const double (&y)[4], double t) {
    double secant[3];
    for (int i = 0; i < 3; ++i) secant[i] = (y[i + 1] - y[i]) / (x[i + 1] - x[i]);
    double slope[4] = {0.0, 0.0, 0.0, 0.0};
    for (int i = 1; i < 3; ++i) {
        const double a = secant[i - 1];
        const double b = secant[i];
        if (a * b <= 0.0) continue;  // a turning key: flat there
        // Weighted harmonic mean of the secants (Fritsch-Butland), within the monotone region.
        const double h0 = x[i] - x[i - 1];
        const double h1 = x[i + 1] - x[i];
        const double w0 = 2.0 * h1 + h0;
        const double w1 = h1 + 2.0 * h0;
        slope[i] = (w0 + w1) / (w0 / a + w1 / b);
    }
    int i = t <= x[1] ? 0 : (t <= x[2] ? 1 : 2);
    const double h = x[i + 1] - x[i];
    const double u = std::clamp((t - x[i]) / h, 0.0, 1.0);
    const double u2 = u * u;
    const double u3 = u2 * u;
    return (2.0 * u3 - 3.0 * u2 + 1.0) * y[i] + (u3 - 2.0 * u2 + u) * h * slope[i] +
           (-2.0 * u3 + 3.0 * u2) * y[i + 1] + (u3 - u2) * h * slope[i + 1];
}

}  // namespace

double easeSine(double dt, double k) {
    dt = std::clamp(dt, 0.0, 1.0);
    return std::sin(kPi / 2.0 * std::pow(dt, k));
}

CurlParams curlAt(double t, const CurlSchedule& s, double pageHeight) {
    // NaN compares false everywhere: map it to the resting state rather than poisoning the shader.
    if (!(t >= 0.0)) t = 0.0;
    if (t > 1.0) t = 1.0;

    double theta;
    double apex;
    if (s.smooth) {
        const double keys[4] = {0.0, s.phase1End, s.phase2End, 1.0};
        theta = smoothThrough(keys, {s.thetaRest, s.thetaPhase1, s.thetaPhase2, s.thetaRest}, t);
        apex = smoothThrough(keys, {s.apexRest, s.apexPhase1, s.apexPhase2, s.apexRest}, t);
    } else if (t <= s.phase1End) {
        const double dt = t / s.phase1End;
        theta = lerp(easeSine(dt, s.thetaEasePhase1), s.thetaRest, s.thetaPhase1);
        apex = lerp(easeSine(dt, s.apexEasePhase1), s.apexRest, s.apexPhase1);
    } else if (t <= s.phase2End) {
        const double dt = (t - s.phase1End) / (s.phase2End - s.phase1End);
        theta = lerp(dt, s.thetaPhase1, s.thetaPhase2);
        apex = lerp(dt, s.apexPhase1, s.apexPhase2);
    } else {
        const double dt = (t - s.phase2End) / (1.0 - s.phase2End);
        theta = lerp(easeSine(dt, s.thetaEasePhase3), s.thetaPhase2, s.thetaRest);
        apex = lerp(easeSine(dt, s.apexEasePhase3), s.apexPhase2, s.apexRest);
    }
    return CurlParams{theta, apex * pageHeight, kPi * t};
}

}  // namespace conecurl
