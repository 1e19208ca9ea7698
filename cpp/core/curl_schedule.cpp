// Evaluates the three-phase schedule; docs/cone-curl-math.md ("The three-phase schedule") has the table.
#include "curl_schedule.hpp"

#include <algorithm>
#include <cmath>

namespace conecurl {
namespace {

constexpr double kPi = 3.14159265358979323846;

double lerp(double f, double a, double b) { return a + (b - a) * f; }

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
    if (t <= s.phase1End) {
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
