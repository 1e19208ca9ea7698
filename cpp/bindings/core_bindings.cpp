// Embind exposure of the math core: the schedule and the deformation, for JS and for the Node tests
// that hold the wasm build to the same reference values as the native tests. Thin: no logic here.
#include <emscripten/bind.h>
#include <malloc.h>

#include "cone_deform.hpp"
#include "curl_schedule.hpp"
#include "js_values.hpp"
#include "leaf_placement.hpp"

namespace {

using namespace conecurl;

struct Vec3Value {
    double x, y, z;
};

// A curled page point and its (analytic) front normal, as JS sees it: {x, y, z, normal: {x, y, z}}.
struct CurledPoint {
    double x, y, z;
    Vec3Value normal;
};

Vec3Value toValue(glm::dvec3 v) { return {v.x, v.y, v.z}; }

CurlParams curlAtDefault(double t) { return curlAt(t); }

CurlParams curlAtWith(double t, const CurlSchedule& schedule, double pageHeight) {
    return curlAt(t, schedule, pageHeight);
}

CurledPoint curlPagePoint(double x, double y, const CurlParams& params) {
    const glm::dvec3 p = curlPoint({x, y}, params);
    return {p.x, p.y, p.z, toValue(curlNormalAnalytic({x, y}, params))};
}

#ifdef CONECURL_TEST_BINDINGS
Vec3Value finiteDifferenceNormal(double x, double y, const CurlParams& params, double delta) {
    return toValue(curlNormalFiniteDifference({x, y}, params, delta));
}

double beta(double x, double y, const CurlParams& params) { return coneBeta({x, y}, params); }

// The C++ reference of where the shader puts page point (x, y) of a leaf drawn as `draw`.
Vec3Value leafToWorld(const LeafDraw& draw, const std::string& binding, double pageHeight, double x, double y) {
    return toValue(leafPointToWorld(draw, js::bindingFromString(binding), pageHeight, {x, y}));
}

Vec3Value leafNormal(const LeafDraw& draw, const std::string& binding, double pageHeight, double x, double y) {
    return toValue(leafNormalToWorld(draw, js::bindingFromString(binding), pageHeight, {x, y}));
}

#endif

}  // namespace

EMSCRIPTEN_BINDINGS(conecurl_core) {
    using namespace emscripten;

    value_object<CurlParams>("CurlParams")
        .field("theta", &CurlParams::theta)
        .field("apexY", &CurlParams::apexY)
        .field("rho", &CurlParams::rho);

    value_object<CurlSchedule>("CurlSchedule")
        .field("phase1End", &CurlSchedule::phase1End)
        .field("phase2End", &CurlSchedule::phase2End)
        .field("thetaRest", &CurlSchedule::thetaRest)
        .field("thetaPhase1", &CurlSchedule::thetaPhase1)
        .field("thetaPhase2", &CurlSchedule::thetaPhase2)
        .field("apexRest", &CurlSchedule::apexRest)
        .field("apexPhase1", &CurlSchedule::apexPhase1)
        .field("apexPhase2", &CurlSchedule::apexPhase2)
        .field("thetaEasePhase1", &CurlSchedule::thetaEasePhase1)
        .field("apexEasePhase1", &CurlSchedule::apexEasePhase1)
        .field("thetaEasePhase3", &CurlSchedule::thetaEasePhase3)
        .field("apexEasePhase3", &CurlSchedule::apexEasePhase3)
        .field("smooth", &CurlSchedule::smooth);

    value_object<Vec3Value>("Vec3").field("x", &Vec3Value::x).field("y", &Vec3Value::y).field("z", &Vec3Value::z);

    value_object<CurledPoint>("CurledPoint")
        .field("x", &CurledPoint::x)
        .field("y", &CurledPoint::y)
        .field("z", &CurledPoint::z)
        .field("normal", &CurledPoint::normal);

    function("defaultSchedule", optional_override([]() { return CurlSchedule{}; }));
    function("curlAt", &curlAtDefault);
    function("curlAtWith", &curlAtWith);
    function("sanitizeCurlParams", &sanitize);
    function("curlPoint", &curlPagePoint);
#ifdef CONECURL_TEST_BINDINGS
    // The test build only: the references the GPU and Node tests compare with.
    function("curlNormalFiniteDifference", &finiteDifferenceNormal);
    function("coneBeta", &beta);
    function("leafPointToWorld", &leafToWorld);
    function("leafNormalToWorld", &leafNormal);
    // Bytes of the wasm heap malloc has handed out and not had back: tests hold it flat over many
    // books made and destroyed (the heap's own size, memory.buffer.byteLength, never shrinks).
    function("heapBytesInUse", optional_override([]() { return static_cast<double>(mallinfo().uordblks); }));
#endif
}
