// Embind exposure of the book model (state, turns, frames). Thin: options are checked here and
// refused with a TypeError that names them; all behaviour lives in cpp/core/book.cpp.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "book.hpp"
#include "book_camera.hpp"
#include "edge_marks_bindings.hpp"
#include "js_values.hpp"
#include "page_drag.hpp"

namespace {

using namespace conecurl;
using emscripten::val;

double positiveNumber(const val& options, const char* name, double fallback) {
    const val value = options[name];
    if (value.isUndefined()) return fallback;
    const double number = value.isNumber() ? value.as<double>() : NAN;
    if (!(number > 0.0) || !std::isfinite(number)) {
        js::throwError("TypeError", std::string(name) + " must be a positive finite number");
    }
    return number;
}

int pageCountOf(const val& count) {
    if (!count.isNumber() || count.as<double>() < 0 || count.as<double>() != std::floor(count.as<double>()) ||
        count.as<double>() > kMaxPages) {
        js::throwError("TypeError", "pageCount must be a whole number from 0 to " + std::to_string(kMaxPages));
    }
    return count.as<int>();
}

// hardPages: [page indices], each below pageCount; as Book's per-page flags.
std::vector<bool> hardPagesOf(const val& hard, int pageCount) {
    if (!val::global("Array").call<bool>("isArray", hard)) js::throwError("TypeError", "hardPages must be an array of page indices");
    std::vector<bool> flags(static_cast<size_t>(pageCount), false);
    const int length = hard["length"].as<int>();
    for (int i = 0; i < length; ++i) {
        const val page = hard[i];
        const double index = page.isNumber() ? page.as<double>() : -1.0;
        if (index < 0 || index >= pageCount || index != std::floor(index)) {
            js::throwError("TypeError", "hardPages[" + js::digits(i) + "] is not a page index");
        }
        flags[static_cast<size_t>(index)] = true;
    }
    return flags;
}

// A leaf's thickness as a fraction of the page width: true the default one, false or 0 none, or a
// number up to kMaxLeafThickness.
double leafThicknessOf(const val& thickness) {
    if (thickness.isTrue() || thickness.isFalse()) return thickness.isTrue() ? kDefaultLeafThickness : 0.0;
    const bool number = thickness.typeOf().as<std::string>() == "number";
    const double value = number ? thickness.as<double>() : -1.0;
    static_assert(kMaxLeafThickness == 0.02, "the message below names the largest thickness");
    if (!(value >= 0.0 && value <= kMaxLeafThickness)) {  // NaN fails too
        js::throwError("RangeError", "thickness must be true, false or a number from 0 to 0.02 (a leaf, of the page width)");
    }
    return value;
}

// { pageCount, display: 'single'|'double', binding: 'left'|'right'|'top', pageWidth, pageHeight,
//   turnSeconds, hardPages: [page indices], schedule: 'paper'|'smooth', center: boolean,
//   thickness: boolean | number }
Book createBook(val options) {
    if (!options.isUndefined() && options.typeOf().as<std::string>() != "object") {
        js::throwError("TypeError", "book options must be an object");
    }
    BookConfig config;
    config.pageCount = pageCountOf(options["pageCount"]);
    const val display = options["display"];
    if (!display.isUndefined()) {
        const std::string name = display.isString() ? display.as<std::string>() : "";
        if (name != "single" && name != "double") js::throwError("TypeError", "display must be 'single' or 'double'");
        config.display = name == "single" ? Display::Single : Display::Double;
    }
    const val binding = options["binding"];
    if (!binding.isUndefined()) {
        config.binding = js::bindingFromString(binding.isString() ? binding.as<std::string>() : "");
    }
    config.pageWidth = positiveNumber(options, "pageWidth", config.pageWidth);
    config.pageHeight = positiveNumber(options, "pageHeight", config.pageHeight);
    config.turnSeconds = positiveNumber(options, "turnSeconds", config.turnSeconds);
    const val schedule = options["schedule"];
    if (!schedule.isUndefined()) {
        const std::string name = schedule.isString() ? schedule.as<std::string>() : "";
        if (name != "paper" && name != "smooth") js::throwError("TypeError", "schedule must be 'paper' or 'smooth'");
        config.schedule.smooth = name == "smooth";
    }
    if (!options["thickness"].isUndefined()) config.leafThickness = leafThicknessOf(options["thickness"]);
    const val center = options["center"];
    if (!center.isUndefined()) {
        if (!center.isTrue() && !center.isFalse()) js::throwError("TypeError", "center must be true or false");
        config.center = center.isTrue();
    }
    const val hard = options["hardPages"];
    if (!hard.isUndefined()) config.hardPages = hardPagesOf(hard, config.pageCount);
    return Book(config);
}

// setPages(pageCount, hardPages?): the pages of a live book changed (Book::setPages).
void setPages(Book& book, val count, val hard) {
    const int pageCount = pageCountOf(count);
    book.setPages(pageCount, hard.isUndefined() ? std::vector<bool>{} : hardPagesOf(hard, pageCount));
}

bool startTurn(Book& book, val directionValue) {
    const std::string direction = directionValue.isString() ? directionValue.as<std::string>() : "";
    if (direction != "forward" && direction != "backward") {
        js::throwError("TypeError", "direction must be 'forward' or 'backward', got '" + direction + "'");
    }
    return book.startTurn(direction == "forward" ? TurnDirection::Forward : TurnDirection::Backward);
}

#ifdef CONECURL_TEST_BINDINGS
val frameToJs(const Book& book) {
    const BookFrame frame = book.frame();
    val leaves = val::array();
    for (int i = 0; i < frame.count; ++i) leaves.call<void>("push", frame.leaves[i]);
    return leaves;
}
#endif

// --- dragging: canvas pixels of the drawing buffer, grips as plain JS objects ------------------------

// `settled`: the camera once turns in flight land (a closed book slides to the middle as it turns).
BookCamera cameraOf(const Book& book, double width, double height, bool settled = false) {
    if (!(width >= 1.0 && height >= 1.0 && width < 1e5 && height < 1e5)) {
        js::throwError("RangeError", "canvas size must be at least 1x1 pixels");
    }
    return bookCamera(book, static_cast<int>(width), static_cast<int>(height), settled);
}

glm::dvec2 pixelOf(double x, double y) {
    if (!std::isfinite(x) || !std::isfinite(y)) js::throwError("RangeError", "pointer position must be finite");
    return {x, y};
}

val gripToJs(const Grip& grip) {
    val out = val::object();
    out.set("backward", grip.backward);
    out.set("flippedY", grip.flippedY);
    out.set("x", grip.pagePoint.x);
    out.set("y", grip.pagePoint.y);
    out.set("nearCorner", grip.nearCorner);
    return out;
}

Grip gripFromJs(const val& grip) {
    if (grip.isNull() || grip.isUndefined() || !grip["x"].isNumber() || !grip["y"].isNumber()) {
        js::throwError("TypeError", "grip must be an object from gripAt()");
    }
    Grip out;
    out.backward = grip["backward"].isTrue();
    out.flippedY = grip["flippedY"].isTrue();
    out.pagePoint = {grip["x"].as<double>(), grip["y"].as<double>()};
    out.nearCorner = grip["nearCorner"].isTrue();
    return out;
}

val gripAtPixel(const Book& book, double x, double y, double width, double height) {
    const std::optional<Grip> grip = gripAt(book, cameraOf(book, width, height), pixelOf(x, y));
    return grip ? gripToJs(*grip) : val::null();
}

bool startHeld(Book& book, val grip) {
    const Grip g = gripFromJs(grip);
    return book.startHeldTurn(g.backward ? TurnDirection::Backward : TurnDirection::Forward, g.flippedY);
}

// Solves the pose that keeps the grip under the pointer and makes it the held leaf's target; returns
// the distance in pixels left between them (0 where the pointer is within reach).
double dragHeld(Book& book, val grip, double x, double y, double width, double height) {
    if (!book.holding()) js::throwError("Error", "no held turn to drag (startHeldTurn first)");
    cameraOf(book, width, height);  // checks the size
    const DragPose solved = solveSlidingDragPose(book, static_cast<int>(width), static_cast<int>(height), gripFromJs(grip),
                                                 pixelOf(x, y), book.heldTarget());
    book.setHeldTarget(solved.pose);
    return solved.errorPixels;
}

// Lets the held turn go, completing it or letting it fall back; returns true if it completes.
bool releaseHeld(Book& book, val grip, double x, double y, double vx, double vy, double width, double height) {
    if (!book.holding()) return false;
    const bool complete = shouldCompleteTurn(book, cameraOf(book, width, height), gripFromJs(grip), pixelOf(x, y),
                                             std::isfinite(vx) && std::isfinite(vy) ? glm::dvec2(vx, vy) : glm::dvec2(0.0));
    book.releaseHeldTurn(complete);
    return complete;
}

void hintHeld(Book& book, val grip, double amount) {
    if (!book.holding()) return;
    book.setHeldPose(hoverHintPose(book, gripFromJs(grip), std::isfinite(amount) ? amount : 0.0));
}

#ifdef CONECURL_TEST_BINDINGS
val gripPixelNow(const Book& book, val grip, double width, double height) {
    const glm::dvec2 p = gripPixel(book, cameraOf(book, width, height), gripFromJs(grip), book.heldPose());
    val out = val::array();
    out.call<void>("push", p.x);
    out.call<void>("push", p.y);
    return out;
}
#endif

// Sets x, y, width and height of a canvas rectangle on `out` (a val is a handle: the caller's object).
val withRect(val out, const PixelRect& r) {
    out.set("x", r.x);
    out.set("y", r.y);
    out.set("width", r.width);
    out.set("height", r.height);
    return out;
}

// Where the resting pages lie on the canvas, in drawing-buffer pixels (book_camera.hpp).
val restingRectOf(const Book& book, double width, double height) {
    return withRect(val::object(), restingRect(cameraOf(book, width, height, true), book.config()));
}

// The pages lying open and where, in drawing-buffer pixels under the zoom: [{ page, turned, x, y, width, height }],
// the turned side first, page -1 for a blank back (book_camera.hpp).
val openPagePlacesOf(const Book& book, double width, double height) {
    const OpenPages open = openPagePlaces(book, cameraOf(book, width, height, true));
    val out = val::array();
    for (int i = 0; i < open.count; ++i) {
        val item = val::object();
        item.set("page", open.places[i].page);
        item.set("turned", open.places[i].turned);
        out.call<void>("push", withRect(item, open.places[i].rect));
    }
    return out;
}

// Zooms to `scale` keeping the table point under the pixel where it is; returns the scale kept.
double zoomAboutPixel(Book& book, val scale, double x, double y, double width, double height) {
    static_assert(kMaxZoom == 4.0, "the range in the message below");
    const double s = js::finiteNumber(scale, "zoom", 1.0, kMaxZoom, "1 to 4");
    cameraOf(book, width, height);  // checks the size
    book.setZoom(zoomAbout(book.zoom(), s, pixelOf(x, y), static_cast<int>(width), static_cast<int>(height)));
    return book.zoom().scale;
}

// Moves the zoomed picture by (dx, dy) canvas pixels, as far as the pages still fill the view.
void panByPixels(Book& book, double dx, double dy, double width, double height) {
    cameraOf(book, width, height);  // checks the size
    book.setZoom(panBy(book.zoom(), pixelOf(dx, dy), static_cast<int>(width), static_cast<int>(height)));
}

#ifdef CONECURL_TEST_BINDINGS
val viewProjection(const Book& book, double width, double height) {
    const BookCamera camera = cameraOf(book, width, height);
    val out = val::global("Float64Array").new_(16);
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) out.set(c * 4 + r, camera.viewProjection[c][r]);
    }
    return out;
}
#endif

}  // namespace

EMSCRIPTEN_BINDINGS(conecurl_book) {
    using namespace emscripten;
    const auto& book = class_<Book>("Book")
        .class_function("create", &createBook)
        .function("pageCount", optional_override([](const Book& b) { return b.config().pageCount; }))
        .function("binding", optional_override([](const Book& b) { return std::string(js::toString(b.config().binding)); }))
        .function("isSingle", optional_override([](const Book& b) { return b.config().display == Display::Single; }))
        .function("pageWidth", optional_override([](const Book& b) { return b.config().pageWidth; }))
        .function("pageHeight", optional_override([](const Book& b) { return b.config().pageHeight; }))
        .function("leafCount", &Book::leafCount)
        .function("position", &Book::position)
        .function("lastPosition", &Book::lastPosition)
        .function("positionOfPage", optional_override([](const Book& b, val page) {
                      return b.positionOfPage(js::wholeNumber(page, "page", 0, std::max(0, b.config().pageCount - 1)));
                  }))
        .function("firstVisiblePage", &Book::firstVisiblePage)
        .function("startTurn", &startTurn)
        .function("setLatestTurnProgress", optional_override([](Book& b, val progress) {
                      b.setLatestTurnProgress(js::finiteNumber(progress, "progress", 0.0, 1.0, "0 to 1"));
                  }))
        .function("advance", optional_override([](Book& b, val seconds) {
                      return b.advance(js::finiteNumber(seconds, "seconds", 0.0, 1e9, "0 to 1e9"));
                  }))
        .function("animating", &Book::animating)
        .function("moving", &Book::moving)
        .function("gripAt", &gripAtPixel)
        .function("startHeldTurn", &startHeld)
        .function("holding", &Book::holding)
        .function("dragHeldTurn", &dragHeld)
        .function("releaseHeldTurn", &releaseHeld)
        .function("cancelHeldTurn", optional_override([](Book& b) { b.releaseHeldTurn(false); }))
        .function("completeHeldTurn", optional_override([](Book& b) { b.releaseHeldTurn(true); }))
        .function("hintHeldTurn", &hintHeld)
        .function("restingRect", &restingRectOf)
        .function("openPagePlaces", &openPagePlacesOf)
        .function("edgeMarkPlaces", &bindings::edgeMarkPlaces)
        .function("zoomAbout", &zoomAboutPixel)
        .function("panBy", &panByPixels)
        .function("zoom", optional_override([](const Book& b) {
                      val out = val::object();
                      out.set("scale", b.zoom().scale);
                      out.set("offsetX", b.zoom().offsetX);
                      out.set("offsetY", b.zoom().offsetY);
                      return out;
                  }))
        .function("resetZoom", optional_override([](Book& b) { b.setZoom(ViewZoom{}); }))
        .function("setDisplay", optional_override([](Book& b, val display) {
                      const std::string name = display.isString() ? display.as<std::string>() : "";
                      if (name != "single" && name != "double") js::throwError("TypeError", "display must be 'single' or 'double'");
                      b.setDisplay(name == "single" ? Display::Single : Display::Double);
                  }))
        .function("setThickness", optional_override([](Book& b, val thickness) { b.setLeafThickness(leafThicknessOf(thickness)); }))
        .function("riffleTo", optional_override([](Book& b, val position) {
                      return b.riffleTo(js::wholeNumber(position, "position", 0, b.lastPosition()));
                  }))
        .function("setPages", &setPages)
        .function("jumpTo", optional_override([](Book& b, val position) {
                      b.jumpTo(js::wholeNumber(position, "position", 0, b.lastPosition()));
                  }));
#ifdef CONECURL_TEST_BINDINGS
    // The test build (dist/test/, see CMakeLists.txt): the frame as JS objects for the reference checks,
    // the camera matrix and a grip's pixel. The package's JS reads none of them.
    value_object<LeafDraw>("LeafDraw")
        .field("leaf", &LeafDraw::leaf)
        .field("frontPage", &LeafDraw::frontPage)
        .field("backPage", &LeafDraw::backPage)
        .field("curl", &LeafDraw::curl)
        .field("mirrored", &LeafDraw::mirrored)
        .field("flippedY", &LeafDraw::flippedY)
        .field("hard", &LeafDraw::hard)
        .field("resting", &LeafDraw::resting);
    book.function("frame", &frameToJs)
        .function("viewProjection", &viewProjection)
        .function("gripPixel", &gripPixelNow);
#else
    (void)book;
#endif
}
