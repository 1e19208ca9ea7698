// The cone deformation of Hong et al. / Nuon: a flat page point wrapped around a cone whose apex sits
// on the spine below the page, then rotated about the spine. Double precision reference for the shader.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "curl_schedule.hpp"

namespace conecurl {

// Parameter guards (docs/cone-curl-math.md at the repository root, "Parameter guards"); the shader
// (shaders/cone_curl.glsl) receives parameters already passed through them.
inline constexpr double kThetaFloor = 0.001;       // radians; sin(theta) divides beta
inline constexpr double kApexCeiling = -1.0e-4;    // apex stays strictly below the page (y >= 0)
inline constexpr double kApexFloor = -1.0e6;       // farther is flat anyway; keeps R - Ay finite

// Clamps parameters into the domain where the map is defined and finite: a NaN theta or apex
// becomes its resting value (pi/2, Nuon's -15), theta in [kThetaFloor, pi/2], apexY in
// [kApexFloor, kApexCeiling], a non-finite rho becomes 0.
CurlParams sanitize(const CurlParams& params);

// Angle around the cone, asin(x / R) / sin(theta), clamped to [-pi, pi] so a page never wraps
// through itself. Evaluated as atan2(x, y - Ay): the same angle while the apex is below the page,
// and exact where x / R rounds towards 1 (asin's slope is infinite there).
double coneBeta(glm::dvec2 pagePoint, const CurlParams& params);

// Flat point (x, y) (spine at x = 0, bottom edge at y = 0) onto the cone, before the spine rotation.
glm::dvec3 deformOntoCone(glm::dvec2 pagePoint, const CurlParams& params);

// Rotation about the spine (the y axis) by rho; positive rho lifts +x towards +z and on to -x.
glm::dvec3 rotateAboutSpine(glm::dvec3 v, double rho);

// Deformation followed by rotation: where the page point is drawn.
glm::dvec3 curlPoint(glm::dvec2 pagePoint, const CurlParams& params);

// Unit normal of the front face at the curled point, from the closed form.
glm::dvec3 curlNormalAnalytic(glm::dvec2 pagePoint, const CurlParams& params);

// Unit normal as in the paper: cross product of forward differences a `delta` step along x and y.
glm::dvec3 curlNormalFiniteDifference(glm::dvec2 pagePoint, const CurlParams& params, double delta);

}  // namespace conecurl
