// Embind side of the marks on the fore-edge: JS marks [{ page, kind: 'tab' | 'tick' }] to the core's,
// for BookRenderer.setEdgeMarks and Book.edgeMarkPlaces (registered with their classes).
#pragma once

#include <emscripten/val.h>

#include "book.hpp"
#include "book_renderer.hpp"

namespace conecurl::bindings {

// BookRenderer.setEdgeMarks(marks): the marks drawn from the next frame on.
void setEdgeMarks(BookRenderer& renderer, emscripten::val marks);
// Book.edgeMarkPlaces(marks, width, height): where the marks that show lie on a canvas of that size,
// in drawing-buffer pixels: [{ mark (index into marks), page, kind, turned, x, y, width, height }],
// ticks first; marks on leaves in flight or out of view are left out.
emscripten::val edgeMarkPlaces(const Book& book, emscripten::val marks, double width, double height);

}  // namespace conecurl::bindings
