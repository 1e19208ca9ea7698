// Book state machine: leaves, turns in flight, and the composition of a frame from them.
#include "book.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "book_stacks.hpp"
#include "cone_deform.hpp"

namespace conecurl {
namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kHeldCatchUpSeconds = 0.05;
constexpr double kHeldSnapRadians = 0.08;
constexpr double kHeldSnapApexLog = 0.25;
// Single display: how far the view moves towards the turned side while a leaf stands on its spine, a
// share of the page width. The page fills the view there, so without it a turning leaf leaves the
// canvas a quarter of the way through its turn; with it the curl stays in view (issue 40).
constexpr double kSingleTurnRoom = 0.5;
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
        const Turn& turn = turns_[i];
        if (turn.leaf == leaf) return true;
        // Leaves a riffling leaf carries along are in flight with it, out of either stack.
        if (turn.carriedTo >= 0 && leaf >= std::min(turn.leaf, turn.carriedTo) && leaf <= std::max(turn.leaf, turn.carriedTo)) {
            return true;
        }
    }
    return false;
}

bool Book::startTurn(TurnDirection direction) {
    // A held leaf lies on top of the stack it came from: nothing may turn over it until it is let go.
    if (turnCount_ >= kMaxTurnsInFlight || holding()) return false;
    const bool forward = direction == TurnDirection::Forward;
    if (forward ? position_ >= lastPosition() : position_ <= 0) return false;
    const int leaf = forward ? position_ : position_ - 1;
    if (inFlight(leaf)) return false;
    turns_[turnCount_++] = Turn{leaf, direction, 0.0};
    position_ += forward ? 1 : -1;
    return true;
}

bool Book::riffleTo(int target) {
    target = std::clamp(target, 0, lastPosition());
    const int distance = std::abs(target - position_);
    if (turnCount_ > 0 || distance <= 1) return false;
    const bool forward = target > position_;
    // Leaves turned, in the order they go: forward p .. target-1, backward p-1 down to target.
    const int first = forward ? position_ : position_ - 1;
    const int step = forward ? 1 : -1;
    const int count = std::min(distance, kMaxTurnsInFlight);
    // Each leaf turns in kRiffleLeafTurn of a turn's time; their starts spread over the rest of the span.
    constexpr double kRiffleLeafTurn = 0.75;
    const double stagger = std::min(0.25, (kRiffleSpan - kRiffleLeafTurn) / (count - 1));
    int carriedFrom = first;
    for (int i = 0; i < count; ++i) {
        // Evenly spread: the first leaf is the top of the stack, the last the one that lands at target.
        const int offset = static_cast<int>(std::lround(static_cast<double>(i) * (distance - 1) / (count - 1)));
        const int leaf = first + step * offset;
        Turn turn{leaf, forward ? TurnDirection::Forward : TurnDirection::Backward, 0.0};
        turn.speed = 1.0 / kRiffleLeafTurn;
        turn.progress = -static_cast<double>(i) * stagger * turn.speed;  // waits: lies flat until then
        turn.carriedTo = carriedFrom;  // the leaves between the previous one and this travel with it
        turns_[turnCount_++] = turn;
        carriedFrom = leaf + step;
    }
    position_ = target;
    return true;
}

void Book::setLatestTurnProgress(double progress) {
    if (turnCount_ == 0) return;
    turns_[turnCount_ - 1].progress = std::clamp(std::isnan(progress) ? 0.0 : progress, 0.0, 1.0);
}

bool Book::moving() const {
    for (int i = 0; i < turnCount_; ++i) {
        const Turn& turn = turns_[i];
        if (!turn.held) return true;
        if (turn.heldPose.theta != turn.heldTarget.theta || turn.heldPose.apexY != turn.heldTarget.apexY ||
            turn.heldPose.rho != turn.heldTarget.rho) {
            return true;
        }
    }
    return false;
}

bool Book::advance(double seconds) {
    if (!(seconds > 0.0)) return animating();
    const double step = seconds / config_.turnSeconds;
    // A held pose catches up with its target with this time constant, and snaps when close.
    const double follow = 1.0 - std::exp(-seconds / kHeldCatchUpSeconds);
    int kept = 0;
    for (int i = 0; i < turnCount_; ++i) {
        Turn turn = turns_[i];
        if (turn.held) {
            CurlParams& pose = turn.heldPose;
            const CurlParams& target = turn.heldTarget;
            pose.theta += (target.theta - pose.theta) * follow;
            pose.apexY += (target.apexY - pose.apexY) * follow;
            pose.rho += (target.rho - pose.rho) * follow;
            if (std::abs(target.theta - pose.theta) < 1e-4 && std::abs(target.rho - pose.rho) < 1e-4 &&
                std::abs(target.apexY - pose.apexY) < 1e-4 * config_.pageHeight) {
                pose = target;
            }
        }
        if (!turn.held) turn.progress += (turn.fallingBack ? -step : step) * turn.speed;
        if (turn.fallingBack ? turn.progress > 0.0 : turn.progress < 1.0) turns_[kept++] = turn;  // the rest land
    }
    turnCount_ = kept;
    return animating();
}

int Book::heldIndex() const {
    for (int i = 0; i < turnCount_; ++i) {
        if (turns_[i].held) return i;
    }
    return -1;
}

bool Book::holding() const { return heldIndex() >= 0; }

TurnDirection Book::heldDirection() const {
    const int i = heldIndex();
    return i >= 0 ? turns_[i].direction : TurnDirection::Forward;
}

bool Book::heldFlippedY() const {
    const int i = heldIndex();
    return i >= 0 && turns_[i].flippedY;
}

int Book::heldLeaf() const {
    const int i = heldIndex();
    return i >= 0 ? turns_[i].leaf : -1;
}

bool Book::startHeldTurn(TurnDirection direction, bool flippedY) {
    if (!startTurn(direction)) return false;
    Turn& turn = turns_[turnCount_ - 1];
    turn.held = true;
    turn.flippedY = flippedY;
    turn.heldPose = scheduledPose(turn.leaf, 0.0);
    turn.heldTarget = turn.heldPose;
    return true;
}

void Book::setHeldPose(const CurlParams& pose) {
    const int i = heldIndex();
    if (i < 0) return;
    CurlParams clean = sanitize(pose);
    clean.rho = std::clamp(clean.rho, 0.0, kPi);
    turns_[i].heldPose = clean;
    turns_[i].heldTarget = clean;
}

void Book::setHeldTarget(const CurlParams& pose) {
    const int i = heldIndex();
    if (i < 0) return;
    CurlParams clean = sanitize(pose);
    clean.rho = std::clamp(clean.rho, 0.0, kPi);
    Turn& turn = turns_[i];
    turn.heldTarget = clean;
    // Small steps (a pointer followed move by move) show at once; a jump is eased by advance().
    const CurlParams& shown = turn.heldPose;
    if (std::abs(clean.theta - shown.theta) < kHeldSnapRadians && std::abs(clean.rho - shown.rho) < kHeldSnapRadians &&
        std::abs(std::log(clean.apexY / shown.apexY)) < kHeldSnapApexLog) {
        turn.heldPose = clean;
    }
}

CurlParams Book::heldTarget() const {
    const int i = heldIndex();
    return i >= 0 ? turns_[i].heldTarget : scheduledPose(0, 0.0);
}

CurlParams Book::heldPose() const {
    const int i = heldIndex();
    return i >= 0 ? turns_[i].heldPose : scheduledPose(0, 0.0);
}

void Book::releaseHeldTurn(bool complete) {
    const int i = heldIndex();
    if (i < 0) return;
    Turn& turn = turns_[i];
    const CurlParams pose = turn.heldPose;  // from where it is seen, not where it was heading
    // The progress whose rotation is the pose's: rho = pi t (soft), rho = pi/2 (1 - cos pi t) (hard).
    const double r = std::clamp(pose.rho / kPi, 0.0, 1.0);
    const double from = isHardLeaf(turn.leaf) ? std::acos(1.0 - 2.0 * r) / kPi : r;
    const CurlParams scheduled = scheduledPose(turn.leaf, from);
    turn.held = false;
    turn.progress = from;
    turn.blendFrom = from;
    turn.released = true;
    turn.releasedPose = pose;
    if (!complete) {
        turn.fallingBack = true;
        position_ += turn.direction == TurnDirection::Forward ? -1 : 1;
    }
    // A turn released at its very end (or start) lands in the next advance.
    if (complete ? from >= 1.0 : from <= 0.0) turn.progress = complete ? 1.0 - 1e-9 : 1e-9;
}

CurlParams Book::scheduledPose(int leaf, double progress) const {
    return isHardLeaf(leaf) ? rigidTurnAt(progress, config_.pageHeight)
                            : sanitize(curlAt(progress, config_.schedule, config_.pageHeight));
}

CurlParams Book::poseOf(const Turn& turn) const {
    if (turn.held) return turn.heldPose;
    CurlParams pose = scheduledPose(turn.leaf, std::clamp(turn.progress, 0.0, 1.0));  // a riffle's waiting leaves: < 0
    if (!turn.released) return pose;
    // The pose the pointer left eases into the schedule's by the end the turn is heading to. Between the
    // two, not offset from the schedule: an offset taken at release and added later, where the schedule's
    // cone is tighter, can leave the domain (theta below 0, the apex above the page) and roll the page
    // into a tube of hundreds of turns, seconds a frame for a software rasteriser.
    const double span = turn.fallingBack ? turn.blendFrom : 1.0 - turn.blendFrom;
    const double left = turn.fallingBack ? turn.progress : 1.0 - turn.progress;
    const double f = span > 0.0 ? std::clamp(left / span, 0.0, 1.0) : 0.0;
    const double w = f * f * (3.0 - 2.0 * f);
    const CurlParams& from = turn.releasedPose;
    pose.theta += w * (from.theta - pose.theta);
    // The apex's distance below the page in log space: near apexes (tight cones) weigh as far ones do.
    pose.apexY = -std::exp(std::log(-pose.apexY) + w * (std::log(-from.apexY) - std::log(-pose.apexY)));
    return sanitize(pose);
}

ViewZoom clampZoom(const ViewZoom& zoom) {
    const double scale = std::clamp(std::isfinite(zoom.scale) ? zoom.scale : 1.0, 1.0, kMaxZoom);
    const double reach = scale - 1.0;
    return ViewZoom{scale, std::clamp(std::isfinite(zoom.offsetX) ? zoom.offsetX : 0.0, -reach, reach),
                    std::clamp(std::isfinite(zoom.offsetY) ? zoom.offsetY : 0.0, -reach, reach)};
}

void Book::setZoom(const ViewZoom& zoom) { zoom_ = clampZoom(zoom); }

void Book::jumpTo(int position) {
    turnCount_ = 0;
    position_ = std::clamp(position, 0, lastPosition());
}

void Book::setDisplay(Display display) {
    if (display == config_.display) return;
    const int page = std::max(0, firstVisiblePage());
    config_.display = display;
    jumpTo(positionOfPage(page));
}

int Book::stackTop(bool turned) const {
    // Leaves in flight (riffles included) lie next to the position: a few steps at most.
    if (turned) {
        int leaf = position_ - 1;
        while (leaf >= 0 && inFlight(leaf)) --leaf;
        return leaf;
    }
    int leaf = position_;
    while (leaf < leafCount() && inFlight(leaf)) ++leaf;
    return leaf;
}

double Book::centerShift() const { return shiftOf(frame()); }

double Book::centerShiftHolding(const CurlParams& pose) const {
    BookFrame f = frame();
    const int held = heldLeaf();
    for (int i = 0; i < f.count; ++i) {
        if (!f.leaves[i].resting && f.leaves[i].leaf == held) f.leaves[i].curl = pose;
    }
    return shiftOf(f);
}

double Book::shiftOf(const BookFrame& f) const {
    if (config_.display == Display::Single) {
        // Room on the spine's side as a leaf rises over it: the most any leaf in flight stands up.
        double standing = 0.0;
        for (int i = 0; i < f.count; ++i) {
            if (!f.leaves[i].resting) standing = std::max(standing, std::sin(f.leaves[i].curl.rho));
        }
        return -kSingleTurnRoom * config_.pageWidth * standing;
    }
    if (!config_.center) return 0.0;
    // How much of a page lies on each side, leaf by leaf: a leaf turned by rho covers the turned side
    // by (1 - cos rho) / 2 of its width. A backward turn is posed mirrored: its rho runs the other way.
    double turnedSide = 0.0;
    double unturnedSide = 0.0;
    for (int i = 0; i < f.count; ++i) {
        const double over = 0.5 * (1.0 - std::cos(f.leaves[i].curl.rho));
        const double turned = f.leaves[i].mirrored ? 1.0 - over : over;
        turnedSide = std::max(turnedSide, turned);
        unturnedSide = std::max(unturnedSide, 1.0 - turned);
    }
    return shiftFor(unturnedSide, turnedSide, bookStacks(config_, stackLeaves(*this), config_.leafThickness));
}

double Book::settledCenterShift() const {
    if (!config_.center || config_.display == Display::Single) return 0.0;
    const double turnedSide = position_ > 0 ? 1.0 : 0.0;
    const double unturnedSide = position_ < leafCount() ? 1.0 : 0.0;
    if (turnedSide == unturnedSide) return 0.0;
    // The stacks once the turns in flight land: a copy of the book with none.
    Book landed = *this;
    landed.jumpTo(position_);
    return shiftFor(unturnedSide, turnedSide, bookStacks(config_, stackLeaves(landed), config_.leafThickness));
}

double Book::shiftFor(double unturnedSide, double turnedSide, const Stacks& stacks) const {
    // What is in view reaches out a page width plus the edge band of the stack under it (as deep as
    // the stack: its faces go down at 45 degrees) on the side that holds more of it.
    const double band = unturnedSide >= turnedSide ? stacks.unturned.total() : stacks.turned.total();
    return 0.5 * (config_.pageWidth + band) * (unturnedSide - turnedSide);
}

void Book::setLeafThickness(double leafThickness) {
    config_.leafThickness = std::isnan(leafThickness) ? 0.0 : std::clamp(leafThickness, 0.0, kMaxLeafThickness);
}

void Book::setPages(int pageCount, std::vector<bool> hardPages) {
    const int page = std::max(0, firstVisiblePage());
    config_.pageCount = std::max(0, pageCount);
    config_.hardPages = std::move(hardPages);
    if (static_cast<int>(config_.hardPages.size()) > config_.pageCount) config_.hardPages.resize(config_.pageCount);
    jumpTo(positionOfPage(page));
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
    const int leftTop = stackTop(true);
    const int rightTop = stackTop(false);
    // In single display the turned side lies outside the view: nothing to draw there.
    if (leftTop >= 0 && config_.display == Display::Double) frame.leaves[frame.count++] = restingLeaf(leftTop, true);
    if (rightTop < leafCount()) frame.leaves[frame.count++] = restingLeaf(rightTop, false);

    for (int i = 0; i < turnCount_; ++i) {
        const Turn& turn = turns_[i];
        LeafDraw draw;
        draw.leaf = turn.leaf;
        draw.frontPage = frontPageOf(turn.leaf);
        draw.backPage = backPageOf(turn.leaf);
        draw.hard = isHardLeaf(turn.leaf);
        draw.mirrored = turn.direction == TurnDirection::Backward;
        draw.flippedY = turn.flippedY;
        draw.curl = poseOf(turn);
        frame.leaves[frame.count++] = draw;
    }
    return frame;
}

}  // namespace conecurl
