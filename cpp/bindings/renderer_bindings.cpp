// Embind exposure of the WebGL2 book renderer. Thin: it converts JS values at the boundary, checks
// them, and turns failures into JS Errors with a clear message; drawing logic stays in the renderer.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <memory>
#include <string>

#include "book_renderer.hpp"
#include "edge_marks_bindings.hpp"
#include "js_values.hpp"

namespace {

using namespace conecurl;
using emscripten::val;

// create(canvasTarget, antialias?): antialias is a boolean, true when left out.
std::unique_ptr<BookRenderer> createRenderer(const std::string& canvasTarget, val antialias) {
    if (!antialias.isUndefined() && !antialias.isTrue() && !antialias.isFalse()) {
        js::throwError("TypeError", "antialias must be true or false");
    }
    auto renderer = std::make_unique<BookRenderer>(canvasTarget, !antialias.isFalse());
    if (!renderer->ok()) {
        const std::string message = renderer->error();
        const bool noContext = !renderer->hasContext();
        renderer.reset();  // release the context before the JS exception skips C++ destructors
        if (noContext) {
            js::throwErrorWithCode("webgl2-unavailable",
                                   "WebGL2 is not available (not supported by this browser or GPU, switched off, "
                                   "or too many WebGL contexts are live)");
        }
        js::throwError("Error", message);
    }
    return renderer;
}

// { lighting, shadows, gutter }: booleans; movingScale: a number in (0, 1]; showThrough: a number in
// [0, 1]; missing keys keep their
// value. (The paper's thickness is the Book's: Book.setThickness.)
void setOptions(BookRenderer& r, val options) {
    RenderOptions next = r.options();
    auto flag = [&options](const char* name, bool& out) {
        const val value = options[name];
        if (value.isUndefined()) return;
        if (!value.isTrue() && !value.isFalse()) js::throwError("TypeError", std::string(name) + " must be true or false");
        out = value.isTrue();
    };
    flag("lighting", next.lighting);
    flag("shadows", next.shadows);
    flag("gutter", next.gutter);
    const val scale = options["movingScale"];
    if (!scale.isUndefined()) {
        const double value = scale.isNumber() ? scale.as<double>() : 0.0;
        if (!(value > 0.0 && value <= 1.0)) js::throwError("RangeError", "movingScale must be a number above 0, at most 1");
        next.movingScale = value;
    }
    const val through = options["showThrough"];
    if (!through.isUndefined()) {
        const double value = through.isNumber() ? through.as<double>() : -1.0;
        if (!(value >= 0.0 && value <= 1.0)) js::throwError("RangeError", "showThrough must be a number from 0 to 1");
        next.showThrough = value;
    }
    r.setOptions(next);
}

// An upload's refusal as JS sees WebGL's: a tainted source is a SecurityError DOMException.
void throwIfRefused(const std::string& problem) {
    if (problem == BookRenderer::kTaintedSource) {
        val::global("DOMException")
            .new_(val("conecurl: page image is cross-origin without CORS, so its pixels cannot be read"),
                  val("SecurityError"))
            .throw_();
    }
    if (!problem.empty()) js::throwError("Error", problem);
}

// `source` is a browser image (ImageBitmap, canvas, <img>, ImageData, video) `width` x `height`
// pixels big, uploaded by the browser straight into the page's texture (no copy through the heap).
// A source the page may not read throws a SecurityError DOMException, as WebGL itself would.
void setPageImage(BookRenderer& r, val pageValue, val source, val widthValue, val heightValue) {
    const int page = js::wholeNumber(pageValue, "page", 0, kMaxPages);
    const int width = js::wholeNumber(widthValue, "image width", 1, 65536);
    const int height = js::wholeNumber(heightValue, "image height", 1, 65536);
    if (source.isNull() || source.typeOf().as<std::string>() != "object") {
        js::throwError("TypeError", "page image must be an ImageBitmap, canvas, image, ImageData or video");
    }
    const std::string problem = r.setPageImage(page, width, height, source.as_handle());
    throwIfRefused(problem);
}

// Rows [y, y + rows) of the page's image in bands (BookRenderer::setPageImageRows): checked and refused
// as setPageImage's whole upload is.
void setPageImageRows(BookRenderer& r, val pageValue, val source, val widthValue, val heightValue, val yValue, val rowsValue) {
    const int page = js::wholeNumber(pageValue, "page", 0, kMaxPages);
    const int width = js::wholeNumber(widthValue, "image width", 1, 65536);
    const int height = js::wholeNumber(heightValue, "image height", 1, 65536);
    const int y = js::wholeNumber(yValue, "band row", 0, height - 1);
    const int rows = js::wholeNumber(rowsValue, "band rows", 1, height - y);
    if (source.isNull() || source.typeOf().as<std::string>() != "object") {
        js::throwError("TypeError", "page image must be an ImageBitmap, canvas, image, ImageData or video");
    }
    const std::string problem = r.setPageImageRows(page, width, height, y, rows, source.as_handle());
    throwIfRefused(problem);
}

#ifdef CONECURL_TEST_BINDINGS
val copyToFloat32Array(const std::vector<float>& data) {
    return val::global("Float32Array").new_(emscripten::typed_memory_view(data.size(), data.data()));
}

#endif

val readPixels(BookRenderer& r) {
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
    const auto& renderer = class_<BookRenderer>("BookRenderer")
        .class_function("create", &createRenderer)
        .function("setOptions", &setOptions)
        .function("setPageImage", &setPageImage)
        .function("setPageImageRows", &setPageImageRows)
        .function("releasePageImage", optional_override([](BookRenderer& r, val page) {
                      r.releasePageImage(js::wholeNumber(page, "page", 0, kMaxPages));
                  }))
        .function("splicePageImages", optional_override([](BookRenderer& r, val at, val removed, val inserted) {
                      r.splicePageImages(js::wholeNumber(at, "at", 0, kMaxPages), js::wholeNumber(removed, "removed", 0, kMaxPages),
                                         js::wholeNumber(inserted, "inserted", 0, kMaxPages));
                  }))
        .function("hasPageImage", optional_override([](BookRenderer& r, val page) {
                      return r.hasPageImage(js::wholeNumber(page, "page", 0, kMaxPages));
                  }))
        .function("residentPageImages", &BookRenderer::residentPageImages)
        .function("draw", select_overload<void(const Book&)>(&BookRenderer::draw))
        .function("framesDrawn", &BookRenderer::framesDrawn)
        .function("lastFrameScale", &BookRenderer::lastFrameScale)
        .function("restingSpreadDraws", &BookRenderer::restingSpreadDraws)
        .function("readPixels", &readPixels)
        .function("gridColumns", optional_override([](BookRenderer& r) { return r.grid().columns; }))
        .function("gridRows", optional_override([](BookRenderer& r) { return r.grid().rows; }))
        .function("setGridRows", optional_override([](BookRenderer& r, val rows) {
                      r.setGridRows(js::wholeNumber(rows, "rows", 0, 512));  // 0: chosen from the canvas
                  }))
        .function("gridErrorPixels", &BookRenderer::gridErrorPixels)
        .function("maxTextureSize", &BookRenderer::maxTextureSize)
        .function("anisotropy", &BookRenderer::anisotropy)
        .function("setEdgeMarks", &bindings::setEdgeMarks)
        .function("finishFirstView", &BookRenderer::finishFirstView)
        .function("prepareTurn", &BookRenderer::prepareTurn)
        .function("recreateGpuObjects", &BookRenderer::recreateGpuObjects);
#ifdef CONECURL_TEST_BINDINGS
    // The test build only: the vertex shader's output read back, and the grid's points.
    renderer.function("captureLeaf", optional_override([](BookRenderer& r, const Book& book, val index) {
                      // An index past the frame's leaves is refused, not answered with an empty array.
                      const int leaves = book.frame().count;
                      if (leaves == 0) js::throwError("RangeError", "leaf draw index: the book's frame has no leaves");
                      return copyToFloat32Array(r.captureLeaf(book, js::wholeNumber(index, "leaf draw index", 0, leaves - 1)));
                  }))
        .function("gridPoints", optional_override([](BookRenderer& r) { return copyToFloat32Array(r.grid().points); }));
#else
    (void)renderer;
#endif
}
