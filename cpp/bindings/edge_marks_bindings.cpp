// Thin Embind functions for the marks on the fore-edge: marks are checked here and refused with a
// TypeError naming them; the rule lives in cpp/core/edge_marks.cpp.
#include "edge_marks_bindings.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "book_camera.hpp"
#include "edge_marks.hpp"
#include "js_values.hpp"

namespace conecurl::bindings {

using emscripten::val;

namespace {

std::vector<EdgeMark> marksOf(const val& marks) {
    if (!val::global("Array").call<bool>("isArray", marks)) {
        js::throwError("TypeError", "edge marks must be an array of { page, kind: 'tab' | 'tick' }");
    }
    std::vector<EdgeMark> out;
    const int length = marks["length"].as<int>();
    out.reserve(static_cast<size_t>(length));
    for (int i = 0; i < length; ++i) {
        const val mark = marks[i];
        const std::string name = "edge marks[" + js::digits(i) + "]";
        if (mark.isNull() || mark.typeOf().as<std::string>() != "object") js::throwError("TypeError", name + " must be an object");
        const val page = mark["page"];
        const double index = page.isNumber() ? page.as<double>() : -1.0;
        if (!(index >= 0.0 && index <= kMaxPages) || index != std::floor(index)) {
            js::throwError("TypeError", name + ".page must be a page index (a whole number from 0)");
        }
        const val kind = mark["kind"];
        const std::string kindName = kind.isString() ? kind.as<std::string>() : "";
        if (kindName != "tab" && kindName != "tick") js::throwError("TypeError", name + ".kind must be 'tab' or 'tick'");
        out.push_back(EdgeMark{static_cast<int>(index), kindName == "tab" ? EdgeMarkKind::Tab : EdgeMarkKind::Tick});
    }
    return out;
}

}  // namespace

void setEdgeMarks(BookRenderer& renderer, val marks) {
    renderer.edgeMarks().setMarks(marksOf(marks));
    renderer.invalidateRestingSpread();  // the marks rest with the page blocks, in the kept spread
}

val edgeMarkPlaces(const Book& book, val marks, double width, double height) {
    if (!(width >= 1.0 && height >= 1.0 && width < 1e5 && height < 1e5)) {
        js::throwError("RangeError", "canvas size must be at least 1x1 pixels");
    }
    const std::vector<EdgeMark> given = marksOf(marks);
    // The camera as turns in flight land, like openPagePlaces: the overlay shows at rest.
    const BookCamera camera = bookCamera(book, static_cast<int>(width), static_cast<int>(height), true);
    val out = val::array();
    for (const EdgeMarkPlace& place : edgeMarkPlaces(book, camera, given)) {
        val item = val::object();
        item.set("mark", place.mark);
        item.set("page", given[static_cast<size_t>(place.mark)].page);
        item.set("kind", std::string(place.kind == EdgeMarkKind::Tab ? "tab" : "tick"));
        item.set("turned", place.turned);
        item.set("x", place.rect.x);
        item.set("y", place.rect.y);
        item.set("width", place.rect.width);
        item.set("height", place.rect.height);
        out.call<void>("push", item);
    }
    return out;
}

}  // namespace conecurl::bindings
