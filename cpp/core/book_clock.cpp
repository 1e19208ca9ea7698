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

namespace {
const LeafDraw* inFlightLeaf(const BookFrame& frame, int leaf) {
    for (int i = 0; i < frame.count; ++i) {
        if (!frame.leaves[i].resting && frame.leaves[i].leaf == leaf) return &frame.leaves[i];
    }
    return nullptr;
}

// The fastest leaf in flight in both frames, `seconds` apart. A leaf that changed direction between
// them (a backward turn is posed mirrored) has no comparable pose and does not count.
void measureSpeed(const BookFrame& previous, const BookFrame& now, double seconds, LeafMotion& motion) {
    if (!(seconds > 0.0) || !std::isfinite(seconds)) return;
    for (int i = 0; i < now.count; ++i) {
        const LeafDraw& draw = now.leaves[i];
        if (draw.resting) continue;
        const LeafDraw* before = inFlightLeaf(previous, draw.leaf);
        if (before == nullptr || before->mirrored != draw.mirrored) continue;
        const double speed = std::abs(draw.curl.rho - before->curl.rho) / seconds;
        if (speed > motion.speed) {
            motion.speed = speed;
            motion.hard = draw.hard;
        }
    }
}

// Leaves in flight before an advance that no longer are: landed, or fallen back flat.
void countLandings(const BookFrame& before, const BookFrame& after, LeafMotion& motion) {
    for (int i = 0; i < before.count; ++i) {
        const LeafDraw& draw = before.leaves[i];
        if (draw.resting || inFlightLeaf(after, draw.leaf) != nullptr) continue;
        ++motion.landings;
        motion.landedHard = motion.landedHard || draw.hard;
    }
}
}  // namespace

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
    motion_ = LeafMotion{};
    BookFrame beforeAdvance;
    const bool advancing = running_ && book.moving();
    if (advancing) {
        beforeAdvance = book.frame();
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
    const BookFrame previous = frame_;
    frame_ = book.frame();
    if (lastTickSeconds_ >= 0.0) measureSpeed(previous, frame_, nowSeconds - lastTickSeconds_, motion_);
    if (advancing) countLandings(beforeAdvance, frame_, motion_);
    if (std::isfinite(nowSeconds)) lastTickSeconds_ = nowSeconds;
    const PagesOnScreen pages = pagesOnScreen(frame_);
    if (!havePages_ || !(pages == lastPages_)) flags |= kTickPagesChanged;
    lastPages_ = pages;
    havePages_ = true;
    return flags;
}

}  // namespace conecurl
