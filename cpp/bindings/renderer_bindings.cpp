// Embind exposure of the WebGL2 page renderer. Thin: it converts JS values at the boundary, checks
// them, and turns failures into JS Errors with a clear message; drawing logic stays in the renderer.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <memory>
#include <string>

#include "page_renderer.hpp"

namespace {

using namespace conecurl;
using emscripten::val;

[[noreturn]] void throwError(const std::string& message) {
    val::global("Error").new_(val("conecurl: " + message)).throw_();
}

std::unique_ptr<PageRenderer> createRenderer(const std::string& canvasTarget) {
    auto renderer = std::make_unique<PageRenderer>(canvasTarget);
    if (!renderer->ok()) {
        const std::string message = renderer->error();
        renderer.reset();  // release the context before the JS exception skips C++ destructors
        throwError(message);
    }
    return renderer;
}

void setPageSize(PageRenderer& r, double width, double height) {
    if (!(width > 0.0) || !(height > 0.0) || !std::isfinite(width) || !std::isfinite(height)) {
        throwError("page size must be two positive finite numbers");
    }
    r.setPageSize(width, height);
}

// `pixels` is any array-like of width * height * 4 bytes (Uint8Array, Uint8ClampedArray).
void setPageImage(PageRenderer& r, int side, int width, int height, val pixels) {
    if (side != 0 && side != 1) throwError("side must be 0 (front) or 1 (back)");
    const double expected = static_cast<double>(width) * height * 4.0;
    if (width <= 0 || height <= 0 || pixels["length"].as<double>() != expected) {
        throwError("page image must be width * height * 4 RGBA bytes");
    }
    std::string problem;
    {
        std::vector<std::uint8_t> bytes(static_cast<size_t>(expected));
        val(emscripten::typed_memory_view(bytes.size(), bytes.data())).call<void>("set", pixels);
        problem = r.setPageImage(static_cast<PageSide>(side), width, height, bytes.data());
    }
    if (!problem.empty()) throwError(problem);
}

void drawAt(PageRenderer& r, double t) {
    if (!std::isfinite(t)) throwError("turn time t must be a finite number in [0, 1]");
    r.drawAt(t);
}

val copyToFloat32Array(const std::vector<float>& data) {
    return val::global("Float32Array").new_(emscripten::typed_memory_view(data.size(), data.data()));
}

val captureCurledVertices(PageRenderer& r, const CurlParams& params) {
    return copyToFloat32Array(r.captureCurledVertices(params));
}

val gridPoints(PageRenderer& r) { return copyToFloat32Array(r.grid().points); }

val readPixels(PageRenderer& r) {
    const RgbaImage image = r.readPixels();
    val result = val::object();
    result.set("width", image.width);
    result.set("height", image.height);
    result.set("data", val::global("Uint8ClampedArray")
                           .new_(emscripten::typed_memory_view(image.pixels.size(), image.pixels.data())));
    return result;
}

}  // namespace

EMSCRIPTEN_BINDINGS(conecurl_renderer) {
    using namespace emscripten;
    class_<PageRenderer>("PageRenderer")
        .class_function("create", &createRenderer)
        .function("setPageSize", &setPageSize)
        .function("pageWidth", &PageRenderer::pageWidth)
        .function("pageHeight", &PageRenderer::pageHeight)
        .function("setSchedule", &PageRenderer::setSchedule)
        .function("schedule", &PageRenderer::schedule)
        .function("setShading", &PageRenderer::setShading)
        .function("setPageImage", &setPageImage)
        .function("paramsAt", &PageRenderer::paramsAt)
        .function("drawAt", &drawAt)
        .function("draw", &PageRenderer::draw)
        .function("readPixels", &readPixels)
        .function("captureCurledVertices", &captureCurledVertices)
        .function("gridPoints", &gridPoints)
        .function("gridColumns", optional_override([](PageRenderer& r) { return r.grid().columns; }))
        .function("gridRows", optional_override([](PageRenderer& r) { return r.grid().rows; }))
        .function("maxTextureSize", &PageRenderer::maxTextureSize);
}
