// The three-phase cone schedule (Nuon 2010): cone angle theta, apex Ay and spine rotation rho as a
// function of turn time t in [0, 1]. Pure math, no GL: the renderer and the tests both read it.
#pragma once

namespace conecurl {

// The cone's state at one instant; what the vertex shader receives as uniforms.
struct CurlParams {
    double theta;  // cone half-angle in radians; pi/2 leaves the page flat
    double apexY;  // y of the cone apex on the spine line, in page units (negative: below the page)
    double rho;    // rotation of the deformed page about the spine, 0 (resting right) .. pi (resting left)
};

// The schedule's constants as data. Defaults are Nuon's, for a page 1 unit tall; apex values are
// multiplied by the page height in curlAt().
struct CurlSchedule {
    double phase1End = 0.15;  // end of the sharp corner curl
    double phase2End = 0.40;  // end of the broad curve; the rest settles flat

    double thetaRest = 1.5707963267948966;   // 90 deg: flat
    double thetaPhase1 = 0.13962634015954636; // 8 deg
    double thetaPhase2 = 0.10471975511965977; // 6 deg

    double apexRest = -15.0;
    double apexPhase1 = -2.5;
    double apexPhase2 = -3.5;

    // Exponents k of ease(dt, k) = sin(pi/2 * dt^k).
    double thetaEasePhase1 = 0.05;
    double apexEasePhase1 = 0.5;
    double thetaEasePhase3 = 10.0;
    double apexEasePhase3 = 2.0;

    // false: the paper's three phases (values continuous, slopes not: theta and Ay jolt at phase1End
    // and phase2End). true: the same four key poses (rest, phase 1 end, phase 2 end, rest) joined by
    // monotone cubic Hermite curves, so theta and Ay also have continuous slopes, zero at both rests,
    // and never leave the range between neighbouring key poses. rho = pi t either way.
    bool smooth = false;
};

// Sinusoidal easing of the paper: sin(pi/2 * dt^k), dt clamped to [0, 1].
double easeSine(double dt, double k);

// Cone parameters at time t (clamped to [0, 1]) for a page `pageHeight` units tall; schedule.smooth
// picks the smooth joins (see CurlSchedule).
CurlParams curlAt(double t, const CurlSchedule& schedule = CurlSchedule{}, double pageHeight = 1.0);

}  // namespace conecurl
