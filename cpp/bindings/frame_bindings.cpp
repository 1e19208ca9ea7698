// Embind exposure of a book's frame loop: one JS->wasm call per animation frame advances the book,
// starts queued turns, composes the frame and draws it, and returns TickFlags. Thin: the clock is
// cpp/core/book_clock, the drawing cpp/renderer/book_renderer.
#include <emscripten/bind.h>
#include <emscripten/em_macros.h>
#include <emscripten/val.h>

#include <string>

#include "book_clock.hpp"
#include "book_renderer.hpp"
#include "js_values.hpp"

namespace {

using namespace conecurl;
using emscripten::val;

// The Book and renderer it drives belong to the JS side, which deletes this first.
struct FrameLoop {
    FrameLoop(Book* b, BookRenderer* r) : book(b), renderer(r) {}
    Book* book;
    BookRenderer* renderer;
    BookClock clock;
};

TurnDirection directionOf(const val& value) {
    const std::string direction = value.isString() ? value.as<std::string>() : "";
    if (direction != "forward" && direction != "backward") {
        js::throwError("TypeError", "direction must be 'forward' or 'backward', got '" + direction + "'");
    }
    return direction == "forward" ? TurnDirection::Forward : TurnDirection::Backward;
}

// tick(nowMs, draw): nowMs is the animation frame's timestamp; draw false advances without drawing
// (a context handed back or lost). Plain numbers: JS passes requestAnimationFrame's own arguments.
int tick(FrameLoop& loop, double nowMs, bool draw) {
    int flags = loop.clock.tick(*loop.book, nowMs / 1000.0);
    if (draw) {
        loop.renderer->draw(*loop.book, loop.clock.frame());
        flags |= kTickDrew;
    }
    return flags;
}

// { speed (rad/s), hard, landings, landedHard } built here: one JS->wasm call, where a value_object
// would call back into wasm for each field.
val motionOf(const FrameLoop& loop) {
    const LeafMotion& m = loop.clock.motion();
    val out = val::object();
    out.set("speed", m.speed);
    out.set("hard", m.hard);
    out.set("landings", m.landings);
    out.set("landedHard", m.landedHard);
    return out;
}

val pagesOnScreenOf(const Book& book) {
    const PagesOnScreen pages = pagesOnScreen(book.frame());
    val out = val::array();
    for (int i = 0; i < pages.count; ++i) out.call<void>("push", pages.pages[i]);
    return out;
}

}  // namespace

#ifdef CONECURL_TEST_BINDINGS
// The test build only: the per-frame call through a plain C ABI instead of Embind, so that
// scripts/bench/embind-call.mjs can weigh Embind's cost on the one call a frame makes.
extern "C" EMSCRIPTEN_KEEPALIVE int conecurl_frame_tick(FrameLoop* loop, double nowMs, int draw) {
    return tick(*loop, nowMs, draw != 0);
}
// And a call that does next to nothing (queuedTurns), to weigh the call alone.
extern "C" EMSCRIPTEN_KEEPALIVE int conecurl_frame_queued_turns(const FrameLoop* loop) { return loop->clock.queuedTurns(); }
#endif

EMSCRIPTEN_BINDINGS(conecurl_frame) {
    using namespace emscripten;
    constant("TICK_MOVING", static_cast<int>(kTickMoving));
    constant("TICK_SETTLED", static_cast<int>(kTickSettled));
    constant("TICK_PAGES_CHANGED", static_cast<int>(kTickPagesChanged));
    constant("TICK_DREW", static_cast<int>(kTickDrew));
    class_<FrameLoop>("FrameLoop")
        .constructor<Book*, BookRenderer*>(allow_raw_pointers())
        .function("tick", &tick)
        // requestTurn(direction, nowMs): 0 started, 1 waits behind a leaf in flight, 2 refused (end
        // of the book, queue full). nowMs: performance.now() when asked, the frames' clock.
        .function("requestTurn", optional_override([](FrameLoop& l, val direction, double nowMs) {
                      return static_cast<int>(l.clock.requestTurn(*l.book, directionOf(direction), nowMs / 1000.0));
                  }))
        // motion(): how the leaves moved in the last tick. Not part of the frame's one call: BookView
        // asks only while a page sound listens (page-sound.js), and it is one call (no field getters).
        .function("motion", &motionOf)
        .function("queuedTurns", optional_override([](const FrameLoop& l) { return l.clock.queuedTurns(); }))
        .function("clearQueue", optional_override([](FrameLoop& l) { l.clock.clearQueue(); }))
        .function("run", optional_override([](FrameLoop& l, double nowMs) { l.clock.run(nowMs / 1000.0); }))
        .function("stop", optional_override([](FrameLoop& l) { l.clock.stop(); }))
        .function("running", optional_override([](const FrameLoop& l) { return l.clock.running(); }))
        .function("forgetLastTick", optional_override([](FrameLoop& l) { l.clock.forgetLastTick(); }));
    function("pagesOnScreen", &pagesOnScreenOf);
}
