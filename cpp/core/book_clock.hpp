// Runs a Book on wall-clock time, one tick per animation frame: how far each frame advances, turns
// asked for while the leaf they need is still in flight, and what a frame changed. Pure C++: the
// per-frame work JS used to do in several calls happens in one (see cpp/bindings/frame_bindings.cpp).
#pragma once

#include <array>

#include "book.hpp"

namespace conecurl {

// What a tick did, as bits of the number it returns to JS.
enum TickFlags : int {
    kTickMoving = 1,        // time still changes the frame: ask for another tick
    kTickSettled = 2,       // nothing moves and no leaf is held: promises waiting for the turns resolve
    kTickPagesChanged = 4,  // the pages drawn differ from the previous tick's (residency needs a look)
    kTickDrew = 8,          // a frame was drawn (set by the caller that draws)
};

// A turn asked for: started now, waiting behind a leaf in flight, or refused (end of book, queue full).
enum class TurnRequest { Started = kTurnStarted, Queued = kTurnQueued, Refused = kTurnRefused };

// The pages a frame shows, in draw order, without duplicates or blank sides (kNoPage).
struct PagesOnScreen {
    std::array<int, 2 * kMaxLeafDraws> pages{};
    int count = 0;
    bool operator==(const PagesOnScreen& o) const;
};
PagesOnScreen pagesOnScreen(const BookFrame& frame);

// How the leaves moved in the last tick, for a page sound that follows the hand (web/src/book/page-sound.js).
struct LeafMotion {
    double speed = 0.0;       // |d rho / dt| of the fastest leaf in flight, rad/s, since the previous tick
    bool hard = false;        // that leaf turns rigidly (a cover)
    int landings = 0;         // leaves in flight before the tick's advance that lie flat after it
    bool landedHard = false;  // one of them is a hard leaf
};

class BookClock {
public:
    // A frame advances the clock by the time since the last one, up to this much: turns keep their
    // duration down to 4 frames a second (software WebGL), and a stall (a hidden tab) does not jump.
    static constexpr double kMaxStepSeconds = 0.25;
    static constexpr int kMaxQueuedTurns = 16;

    // `nowSeconds` is when the turn was asked for, on the frames' clock: the first frame after it
    // advances by the time since then, so a turn does not lose the frame it waited for.
    TurnRequest requestTurn(Book& book, TurnDirection direction, double nowSeconds);
    int queuedTurns() const { return queued_; }
    void clearQueue() { queued_ = 0; }

    // The clock runs from the next tick on (a turn started, a held pose changed), advancing by the
    // time since `nowSeconds` unless it was running already.
    void run(double nowSeconds) {
        if (!running_ || lastSeconds_ < 0.0) lastSeconds_ = nowSeconds;
        running_ = true;
    }
    // An exact pose is shown: time stops changing the frame until run() again.
    void stop() {
        running_ = false;
        lastSeconds_ = -1.0;
    }
    // The next tick advances nothing (after a lost context, or any pause of the frames).
    void forgetLastTick() { lastSeconds_ = -1.0; }
    bool running() const { return running_; }

    // Advances the book by the time since the previous tick (capped), starts queued turns that can
    // start now, composes the frame, and says what changed. `nowSeconds` is the frame's timestamp.
    int tick(Book& book, double nowSeconds);
    // The frame the last tick composed (what a renderer draws after it).
    const BookFrame& frame() const { return frame_; }
    // How the leaves moved in the last tick: a leaf counts from the second tick it is in flight in (its
    // pose the previous tick drew is the start of the step), whether time or a held pointer moved it.
    const LeafMotion& motion() const { return motion_; }

private:
    std::array<TurnDirection, kMaxQueuedTurns> queue_{};
    int queued_ = 0;
    bool running_ = false;
    double lastSeconds_ = -1.0;
    BookFrame frame_{};
    LeafMotion motion_{};
    double lastTickSeconds_ = -1.0;  // the previous tick's timestamp, running or not (motion's dt)
    PagesOnScreen lastPages_{};
    bool havePages_ = false;
};

}  // namespace conecurl
