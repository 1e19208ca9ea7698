// The frame clock of a Book: capped steps, queued turns and the flags a frame reports.
#include "book_clock.hpp"

#include <algorithm>
#include <cmath>

namespace conecurl {
namespace {
constexpr double kHalfPi = 1.57079632679489661923;
}

bool PagesOnScreen::operator==(const PagesOnScreen& o) const {
    return count == o.count && std::equal(pages.begin(), pages.begin() + count, o.pages.begin());
}

PagesOnScreen pagesOnScreen(const BookFrame& frame) {
    PagesOnScreen out;
    auto add = [&out](int page) {
        if (page < 0 || std::find(out.pages.begin(), out.pages.begin() + out.count, page) != out.pages.begin() + out.count) return;
        out.pages[out.count++] = page;
    };
    for (int i = 0; i < frame.count; ++i) {
        const LeafDraw& draw = frame.leaves[i];
        // A resting leaf shows one side: its front while unturned, its back once turned over.
        const bool turnedOver = draw.resting && draw.curl.rho > kHalfPi;
        if (!draw.resting || !turnedOver) add(draw.frontPage);
        if (!draw.resting || turnedOver) add(draw.backPage);
    }
    return out;
}

TurnRequest BookClock::requestTurn(Book& book, TurnDirection direction, double nowSeconds) {
    // Turns keep their order: one asked for behind a waiting one waits too.
    if (queued_ == 0 && book.startTurn(direction)) {
        run(nowSeconds);
        return TurnRequest::Started;
    }
    if (!book.animating() || queued_ >= kMaxQueuedTurns) return TurnRequest::Refused;
    queue_[queued_++] = direction;
    run(nowSeconds);
    return TurnRequest::Queued;
}

int BookClock::tick(Book& book, double nowSeconds) {
    int flags = 0;
    if (running_ && book.moving()) {
        const double step = lastSeconds_ >= 0.0 && std::isfinite(nowSeconds) && std::isfinite(lastSeconds_)
                                ? std::clamp(nowSeconds - lastSeconds_, 0.0, kMaxStepSeconds)
                                : 0.0;
        book.advance(step);
        int started = 0;
        while (started < queued_ && book.startTurn(queue_[started])) ++started;
        std::copy(queue_.begin() + started, queue_.begin() + queued_, queue_.begin());
        queued_ -= started;
    }
    if (running_ && book.moving()) {
        lastSeconds_ = nowSeconds;
        flags |= kTickMoving;
    } else {
        lastSeconds_ = -1.0;
        if (!book.holding()) {  // a held leaf lying still: the next pointer move runs the clock again
            running_ = false;
            queued_ = 0;  // what is left could never start (the end of the book)
            flags |= kTickSettled;
        }
    }
    frame_ = book.frame();
    const PagesOnScreen pages = pagesOnScreen(frame_);
    if (!havePages_ || !(pages == lastPages_)) flags |= kTickPagesChanged;
    lastPages_ = pages;
    havePages_ = true;
    return flags;
}

}  // namespace conecurl
