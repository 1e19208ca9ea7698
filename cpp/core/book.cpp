// Book state machine: leaves, turns in flight, and the composition of a frame from them.
#include "book.hpp"

#include <algorithm>
#include <cmath>

#include "cone_deform.hpp"

namespace conecurl {
namespace {
constexpr double kPi = 3.14159265358979323846;
}

CurlParams rigidTurnAt(double progress, double pageHeight) {
    const double p = std::clamp(std::isnan(progress) ? 0.0 : progress, 0.0, 1.0);
    const CurlSchedule rest;
    return CurlParams{rest.thetaRest, rest.apexRest * pageHeight, kPi * 0.5 * (1.0 - std::cos(kPi * p))};
}

Book::Book(BookConfig config) : config_(std::move(config)) {
    config_.pageCount = std::max(0, config_.pageCount);
    if (!(config_.turnSeconds > 0.0)) config_.turnSeconds = 1.0;
}

int Book::leafCount() const {
    const int n = config_.pageCount;
    return config_.display == Display::Double ? (n + 1) / 2 : n;
}

int Book::lastPosition() const {
    // Double: one spread per leaf boundary. Single: the last page is the last place to stop.
    return config_.display == Display::Double ? leafCount() : std::max(0, leafCount() - 1);
}

int Book::positionOfPage(int page) const {
    page = std::clamp(page, 0, std::max(0, config_.pageCount - 1));
    return config_.display == Display::Double ? (page + 1) / 2 : page;
}

int Book::firstVisiblePage() const {
    if (config_.pageCount == 0) return kNoPage;
    if (config_.display == Display::Single) return position_;
    return position_ == 0 ? 0 : std::min(2 * position_ - 1, config_.pageCount - 1);
}

int Book::frontPageOf(int leaf) const {
    const int page = config_.display == Display::Double ? 2 * leaf : leaf;
    return page < config_.pageCount ? page : kNoPage;
}

int Book::backPageOf(int leaf) const {
    if (config_.display == Display::Single) return kNoPage;
    const int page = 2 * leaf + 1;
    return page < config_.pageCount ? page : kNoPage;
}

bool Book::isHardLeaf(int leaf) const {
    auto hard = [&](int page) {
        return page >= 0 && page < static_cast<int>(config_.hardPages.size()) && config_.hardPages[page];
    };
    return hard(frontPageOf(leaf)) || hard(backPageOf(leaf));
}

bool Book::inFlight(int leaf) const {
    for (int i = 0; i < turnCount_; ++i) {
        if (turns_[i].leaf == leaf) return true;
    }
    return false;
}

bool Book::startTurn(TurnDirection direction) {
    if (turnCount_ >= kMaxTurnsInFlight) return false;
    const bool forward = direction == TurnDirection::Forward;
    if (forward ? position_ >= lastPosition() : position_ <= 0) return false;
    const int leaf = forward ? position_ : position_ - 1;
    if (inFlight(leaf)) return false;
    turns_[turnCount_++] = Turn{leaf, direction, 0.0};
    position_ += forward ? 1 : -1;
    return true;
}

void Book::setLatestTurnProgress(double progress) {
    if (turnCount_ == 0) return;
    turns_[turnCount_ - 1].progress = std::clamp(std::isnan(progress) ? 0.0 : progress, 0.0, 1.0);
}

bool Book::advance(double seconds) {
    if (!(seconds > 0.0)) return animating();
    const double step = seconds / config_.turnSeconds;
    int kept = 0;
    for (int i = 0; i < turnCount_; ++i) {
        Turn turn = turns_[i];
        turn.progress += step;
        if (turn.progress < 1.0) turns_[kept++] = turn;  // the rest land
    }
    turnCount_ = kept;
    return animating();
}

void Book::jumpTo(int position) {
    turnCount_ = 0;
    position_ = std::clamp(position, 0, lastPosition());
}

LeafDraw Book::restingLeaf(int leaf, bool turned) const {
    LeafDraw draw;
    draw.leaf = leaf;
    draw.frontPage = frontPageOf(leaf);
    draw.backPage = backPageOf(leaf);
    draw.curl = rigidTurnAt(turned ? 1.0 : 0.0, config_.pageHeight);
    draw.hard = isHardLeaf(leaf);
    draw.resting = true;
    return draw;
}

BookFrame Book::frame() const {
    BookFrame frame;
    // Resting stacks: the top turned leaf and the top unturned leaf that are not in flight.
    int leftTop = -1;
    for (int leaf = position_ - 1; leaf >= 0; --leaf) {
        if (!inFlight(leaf)) {
            leftTop = leaf;
            break;
        }
    }
    int rightTop = -1;
    for (int leaf = position_; leaf < leafCount(); ++leaf) {
        if (!inFlight(leaf)) {
            rightTop = leaf;
            break;
        }
    }
    // In single display the turned side lies outside the view: nothing to draw there.
    if (leftTop >= 0 && config_.display == Display::Double) frame.leaves[frame.count++] = restingLeaf(leftTop, true);
    if (rightTop >= 0) frame.leaves[frame.count++] = restingLeaf(rightTop, false);

    for (int i = 0; i < turnCount_; ++i) {
        const Turn& turn = turns_[i];
        LeafDraw draw;
        draw.leaf = turn.leaf;
        draw.frontPage = frontPageOf(turn.leaf);
        draw.backPage = backPageOf(turn.leaf);
        draw.hard = isHardLeaf(turn.leaf);
        draw.mirrored = turn.direction == TurnDirection::Backward;
        draw.curl = draw.hard ? rigidTurnAt(turn.progress, config_.pageHeight)
                              : sanitize(curlAt(turn.progress, config_.schedule, config_.pageHeight));
        frame.leaves[frame.count++] = draw;
    }
    return frame;
}

}  // namespace conecurl
