// Embind exposure of the book model (state, turns, frames). Thin: options are checked here and
// refused with a TypeError that names them; all behaviour lives in cpp/core/book.cpp.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cmath>
#include <string>

#include "book.hpp"
#include "js_values.hpp"

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

// { pageCount, display: 'single'|'double', binding: 'left'|'right'|'top', pageWidth, pageHeight,
//   turnSeconds, hardPages: [page indices] }
Book createBook(val options) {
    if (!options.isUndefined() && options.typeOf().as<std::string>() != "object") {
        js::throwError("TypeError", "book options must be an object");
    }
    BookConfig config;
    const val count = options["pageCount"];
    if (!count.isNumber() || count.as<double>() < 0 || count.as<double>() != std::floor(count.as<double>()) ||
        count.as<double>() > 1e6) {
        js::throwError("TypeError", "pageCount must be a whole number from 0 to 1000000");
    }
    config.pageCount = count.as<int>();
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
    const val hard = options["hardPages"];
    if (!hard.isUndefined()) {
        if (!val::global("Array").call<bool>("isArray", hard)) js::throwError("TypeError", "hardPages must be an array of page indices");
        config.hardPages.assign(static_cast<size_t>(config.pageCount), false);
        const int length = hard["length"].as<int>();
        for (int i = 0; i < length; ++i) {
            const val page = hard[i];
            const double index = page.isNumber() ? page.as<double>() : -1.0;
            if (index < 0 || index >= config.pageCount || index != std::floor(index)) {
                js::throwError("TypeError", "hardPages[" + std::to_string(i) + "] is not a page index");
            }
            config.hardPages[static_cast<size_t>(index)] = true;
        }
    }
    return Book(config);
}

bool startTurn(Book& book, const std::string& direction) {
    if (direction != "forward" && direction != "backward") {
        js::throwError("TypeError", "direction must be 'forward' or 'backward', got '" + direction + "'");
    }
    return book.startTurn(direction == "forward" ? TurnDirection::Forward : TurnDirection::Backward);
}

val frameToJs(const Book& book) {
    const BookFrame frame = book.frame();
    val leaves = val::array();
    for (int i = 0; i < frame.count; ++i) leaves.call<void>("push", frame.leaves[i]);
    return leaves;
}

}  // namespace

EMSCRIPTEN_BINDINGS(conecurl_book) {
    using namespace emscripten;
    value_object<LeafDraw>("LeafDraw")
        .field("leaf", &LeafDraw::leaf)
        .field("frontPage", &LeafDraw::frontPage)
        .field("backPage", &LeafDraw::backPage)
        .field("curl", &LeafDraw::curl)
        .field("mirrored", &LeafDraw::mirrored)
        .field("hard", &LeafDraw::hard)
        .field("resting", &LeafDraw::resting);

    class_<Book>("Book")
        .class_function("create", &createBook)
        .function("pageCount", optional_override([](const Book& b) { return b.config().pageCount; }))
        .function("binding", optional_override([](const Book& b) { return std::string(js::toString(b.config().binding)); }))
        .function("isSingle", optional_override([](const Book& b) { return b.config().display == Display::Single; }))
        .function("pageWidth", optional_override([](const Book& b) { return b.config().pageWidth; }))
        .function("pageHeight", optional_override([](const Book& b) { return b.config().pageHeight; }))
        .function("leafCount", &Book::leafCount)
        .function("position", &Book::position)
        .function("lastPosition", &Book::lastPosition)
        .function("positionOfPage", &Book::positionOfPage)
        .function("firstVisiblePage", &Book::firstVisiblePage)
        .function("startTurn", &startTurn)
        .function("setLatestTurnProgress", &Book::setLatestTurnProgress)
        .function("advance", &Book::advance)
        .function("animating", &Book::animating)
        .function("jumpTo", &Book::jumpTo)
        .function("frame", &frameToJs);
}
