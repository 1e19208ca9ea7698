// Grip finding and the pose solve for dragging; see page_drag.hpp. The solve is a small bounded
// Levenberg-Marquardt over (cos theta, log apex distance, rho) with the schedule as a weak prior.
#include "page_drag.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "cone_deform.hpp"
#include "leaf_placement.hpp"

namespace conecurl {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kEdgeSlack = 0.04;           // of the page: a press just outside the edge still takes hold
constexpr double kSingleBackBand = 0.25;      // single display: this much of the page from the spine goes back
constexpr double kCornerReach = 0.16;         // hover hint within this fraction of the page width of a corner
constexpr double kMinTheta = 0.08;            // radians: tighter cones roll the page into a tube
constexpr double kApexNearest = 0.05;         // apex distance below the page, in page heights
constexpr double kApexFarthest = 15.0;
constexpr double kPriorPixelsPerUnit = 2.0;   // weak: the pointer decides, the schedule breaks ties
constexpr double kMaxWrap = 2.6;              // radians round the cone; the schedule's corner peaks at 2.2253
constexpr double kWrapPixelsPerRadian = 400.0;
constexpr int kVisibilitySamples = 48;        // along the grabbed point's row, for the hidden-point test
constexpr double kApexWeight = 0.5;           // log apex distance counts half in the shape prior
constexpr double kFollowPixels = 0.5;         // a pose this close to the pointer follows it
constexpr int kScreenIterations = 6;          // steps each restart gets before the best few are refined
constexpr size_t kRefined = 4;
// Progress values of the schedule's poses a lost solve restarts from: dense where the corner lifts.
constexpr double kRestartProgress[] = {0.0025, 0.005, 0.01, 0.015, 0.02, 0.03, 0.04, 0.06, 0.08, 0.1,
                                       0.15, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
constexpr double kFlingPagesPerSecond = 0.8;  // a release faster than this decides by its direction
constexpr double kHintLift = 0.08;            // the hover hint lifts the corner this much of the page height
constexpr double kHintApex = 0.15;            // ... on a cone whose apex is this far below the page

struct Unknowns {
    double c;    // cos theta: 0 flat, towards 1 tightly curled
    double b;    // log(-apexY / pageHeight)
    double rho;
};

struct Bounds {
    Unknowns lo, hi;
    bool rotateOnly;  // hard leaves
};

Bounds boundsFor(bool hard) {
    if (hard) return {{0.0, std::log(kApexFarthest), 0.0}, {0.0, std::log(kApexFarthest), kPi}, true};
    return {{0.0, std::log(kApexNearest), 0.0}, {std::cos(kMinTheta), std::log(kApexFarthest), kPi}, false};
}

Unknowns clampTo(const Bounds& bounds, Unknowns u) {
    u.c = std::clamp(u.c, bounds.lo.c, bounds.hi.c);
    u.b = std::clamp(u.b, bounds.lo.b, bounds.hi.b);
    u.rho = std::clamp(u.rho, bounds.lo.rho, bounds.hi.rho);
    return u;
}

CurlParams toParams(const Unknowns& u, double h) {
    return CurlParams{std::acos(std::clamp(u.c, 0.0, 1.0)), -h * std::exp(u.b), u.rho};
}

Unknowns toUnknowns(const CurlParams& raw, double h) {
    const CurlParams p = sanitize(raw);
    return Unknowns{std::cos(p.theta), std::log(std::max(-p.apexY / h, 1e-9)), p.rho};
}

LeafPlacement placementOf(const Book& book, const Grip& grip) {
    const BookConfig& c = book.config();
    return placeLeaf(c.binding, grip.backward, c.pageHeight, grip.flippedY);
}

int gripLeaf(const Book& book, const Grip& grip) {
    // The held leaf if there is one; else the leaf a new turn that way would take.
    if (book.holding()) return book.heldLeaf();
    return grip.backward ? book.position() - 1 : book.position();
}

class PoseProblem {
public:
    // `cameraShift`: the centre shift `camera` was made with, for a book that slides as the leaf turns
    // (a closed book's cover): each pose is then seen through the camera it would have. NaN: a camera
    // that stays where it is.
    PoseProblem(const Book& book, const BookCamera& camera, const Grip& grip, glm::dvec2 target,
                double cameraShift = std::nan(""))
        : book_(book), camera_(camera), grip_(grip), target_(target), placement_(placementOf(book, grip)),
          leaf_(gripLeaf(book, grip)), bounds_(boundsFor(book.isHardLeaf(leaf_))), cameraShift_(cameraShift),
          slide_(glm::dvec3(unturnedSide(book.config().binding), 0.0)) {
        // The shapes the schedule passes through, (cos theta, weighted log apex distance), densest
        // near the start where theta falls fastest. The prior is the distance from this curve: a
        // dragged page may take any of the schedule's shapes at any rotation.
        for (int i = 0; i < kShapeSamples; ++i) {
            const double f = static_cast<double>(i) / (kShapeSamples - 1);
            const Unknowns u = toUnknowns(book.scheduledPose(leaf_, f * f * f), height());
            shapes_[i] = glm::dvec2(u.c, kApexWeight * u.b);
        }
    }

    const Bounds& bounds() const { return bounds_; }
    double height() const { return book_.config().pageHeight; }

    glm::dvec3 worldOf(glm::dvec2 pagePoint, const CurlParams& pose) const {
        const glm::dvec3 world(placement_.pageToWorld * glm::dvec4(curlPoint(pagePoint, pose), 1.0));
        if (std::isnan(cameraShift_)) return world;
        // The camera moving by the pose's shift is the world moving the other way past this camera.
        return world - (book_.centerShiftHolding(pose) - cameraShift_) * slide_;
    }

    glm::dvec2 pixelOf(const CurlParams& pose) const { return worldToPixel(camera_, worldOf(grip_.pagePoint, pose)); }

    // Samples the leaf along the grabbed point's row (the curl's cross-section there): hidden if one
    // lies on the line of sight in front of it. Neighbours within two samples are part of the point.
    bool visible(const CurlParams& pose) const {
        const double w = book_.config().pageWidth;
        const double spacing = w / kVisibilitySamples;
        const glm::dvec3 target = worldOf(grip_.pagePoint, pose);
        const glm::dvec3 sight = target - camera_.eye;
        const double length2 = glm::dot(sight, sight);
        for (int k = 0; k <= kVisibilitySamples; ++k) {
            const double x = spacing * k;
            if (std::abs(x - grip_.pagePoint.x) <= 2.0 * spacing) continue;
            const glm::dvec3 q = worldOf({x, grip_.pagePoint.y}, pose);
            const double along = glm::dot(q - camera_.eye, sight) / length2;
            if (along <= 0.0 || along >= 1.0) continue;  // behind the eye or beyond the point
            if (glm::length(q - (camera_.eye + sight * along)) < 0.6 * spacing) return false;
        }
        return true;
    }

    std::array<double, 5> residuals(const Unknowns& u) const {
        const CurlParams pose = toParams(u, height());
        const glm::dvec2 d = pixelOf(pose) - target_;
        if (bounds_.rotateOnly) return {d.x, d.y, 0.0, 0.0, 0.0};
        const glm::dvec2 shape(u.c, kApexWeight * u.b);
        const glm::dvec2 off = shape - nearestScheduleShape(shape);
        // No part of the leaf may wrap further round the cone than kMaxWrap: beyond pi it would fold
        // through itself (the guards clamp it there, collapsing the page onto a line). The free corner
        // at the apex end wraps furthest.
        const double wrap = coneBeta({book_.config().pageWidth, 0.0}, pose);
        return {d.x, d.y, kPriorPixelsPerUnit * off.x, kPriorPixelsPerUnit * off.y,
                kWrapPixelsPerRadian * std::max(0.0, wrap - kMaxWrap)};
    }

    static double cost(const std::array<double, 5>& r) {
        double sum = 0.0;
        for (double v : r) sum += v * v;
        return sum;
    }

    // Bounded Levenberg-Marquardt from `u`.
    Unknowns solve(Unknowns u, int iterations = 40) const {
        u = clampTo(bounds_, u);
        std::array<double, 5> r = residuals(u);
        double current = cost(r);
        double damping = 1e-3;
        for (int iteration = 0; iteration < iterations && current > 1e-8; ++iteration) {
            // Jacobian by central differences, one-sided at a bound.
            double jacobian[5][3] = {};
            for (int k = 0; k < 3; ++k) {
                if (bounds_.rotateOnly && k < 2) continue;
                const double step = 1e-6;
                Unknowns plus = u;
                Unknowns minus = u;
                (k == 0 ? plus.c : k == 1 ? plus.b : plus.rho) += step;
                (k == 0 ? minus.c : k == 1 ? minus.b : minus.rho) -= step;
                plus = clampTo(bounds_, plus);
                minus = clampTo(bounds_, minus);
                const double span = (k == 0 ? plus.c - minus.c : k == 1 ? plus.b - minus.b : plus.rho - minus.rho);
                if (span <= 0.0) continue;
                const std::array<double, 5> rp = residuals(plus);
                const std::array<double, 5> rm = residuals(minus);
                for (int i = 0; i < 5; ++i) jacobian[i][k] = (rp[i] - rm[i]) / span;
            }
            glm::dmat3 normal(0.0);  // J^T J, column-major
            glm::dvec3 gradient(0.0);
            for (int i = 0; i < 5; ++i) {
                for (int a = 0; a < 3; ++a) {
                    gradient[a] += jacobian[i][a] * r[i];
                    for (int b = 0; b < 3; ++b) normal[b][a] += jacobian[i][a] * jacobian[i][b];
                }
            }
            bool improved = false;
            while (damping < 1e12) {
                glm::dmat3 damped = normal;
                for (int a = 0; a < 3; ++a) damped[a][a] += damping * (normal[a][a] + 1e-9) + 1e-12;
                const glm::dvec3 delta = -(glm::inverse(damped) * gradient);
                const Unknowns next = clampTo(bounds_, Unknowns{u.c + delta.x, u.b + delta.y, u.rho + delta.z});
                const std::array<double, 5> rn = residuals(next);
                const double nextCost = cost(rn);
                if (std::isfinite(nextCost) && nextCost < current) {
                    const double moved = std::abs(next.c - u.c) + std::abs(next.b - u.b) + std::abs(next.rho - u.rho);
                    u = next;
                    r = rn;
                    current = nextCost;
                    damping = std::max(damping / 3.0, 1e-9);
                    improved = moved > 1e-12;
                    break;
                }
                damping *= 4.0;
            }
            if (!improved) break;
        }
        return u;
    }

private:
    static constexpr int kShapeSamples = 48;

    glm::dvec2 nearestScheduleShape(glm::dvec2 p) const {
        glm::dvec2 nearest = shapes_[0];
        double least = 1e300;
        for (int i = 0; i + 1 < kShapeSamples; ++i) {
            const glm::dvec2 a = shapes_[i];
            const glm::dvec2 ab = shapes_[i + 1] - a;
            const double len2 = ab.x * ab.x + ab.y * ab.y;
            const double f = len2 > 0.0 ? std::clamp(((p.x - a.x) * ab.x + (p.y - a.y) * ab.y) / len2, 0.0, 1.0) : 0.0;
            const glm::dvec2 q = a + ab * f;
            const double d2 = (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y);
            if (d2 < least) {
                least = d2;
                nearest = q;
            }
        }
        return nearest;
    }

    std::array<glm::dvec2, kShapeSamples> shapes_{};
    const Book& book_;
    const BookCamera& camera_;
    const Grip& grip_;
    glm::dvec2 target_;
    LeafPlacement placement_;
    int leaf_;
    Bounds bounds_;
    double cameraShift_;
    glm::dvec3 slide_;  // world direction the camera moves in as the shift grows
};

}  // namespace

std::optional<Grip> gripAt(const Book& book, const BookCamera& camera, glm::dvec2 pixel) {
    const BookConfig& c = book.config();
    const double w = c.pageWidth;
    const double h = c.pageHeight;
    const glm::dvec3 world = pixelToTable(camera, pixel);
    // The point of the leaf at rest (unturned, or turned when mirrored) under the pixel.
    auto restingPoint = [&](bool mirrored) {
        return glm::dvec2(glm::inverse(placeLeaf(c.binding, mirrored, h).pageToWorld) * glm::dvec4(world, 1.0));
    };
    auto onPage = [&](glm::dvec2 q) {
        return q.x >= 0.0 && q.x <= w * (1.0 + kEdgeSlack) && q.y >= -kEdgeSlack * h && q.y <= h * (1.0 + kEdgeSlack);
    };
    auto gripFor = [&](bool backward, glm::dvec2 q) {
        Grip grip;
        grip.backward = backward;
        grip.flippedY = q.y > 0.5 * h;
        grip.pagePoint = {std::clamp(q.x, 0.0, w), std::clamp(grip.flippedY ? h - q.y : q.y, 0.0, h)};
        const glm::dvec2 fromCorner = grip.pagePoint - glm::dvec2(w, 0.0);
        grip.nearCorner = std::hypot(fromCorner.x, fromCorner.y) <= kCornerReach * w;
        return grip;
    };
    const bool canForward = book.position() < book.lastPosition();
    const bool canBackward = book.position() > 0;
    const glm::dvec2 unturned = restingPoint(false);
    if (onPage(unturned)) {
        if (c.display == Display::Single && unturned.x < kSingleBackBand * w) {
            if (!canBackward) return std::nullopt;
            // The previous leaf lies outside the view: take it by its free edge at this height.
            Grip grip = gripFor(true, {w, unturned.y});
            const double fromSpine = unturned.x;
            const double fromEnd = std::min(unturned.y, h - unturned.y);
            grip.nearCorner = std::hypot(fromSpine, fromEnd) <= kCornerReach * w;
            return grip;
        }
        return canForward ? std::optional<Grip>(gripFor(false, unturned)) : std::nullopt;
    }
    if (c.display == Display::Double && canBackward) {
        const glm::dvec2 turned = restingPoint(true);
        if (onPage(turned)) return gripFor(true, turned);
    }
    return std::nullopt;
}

bool gripVisible(const Book& book, const BookCamera& camera, const Grip& grip, const CurlParams& pose) {
    return PoseProblem(book, camera, grip, {0.0, 0.0}).visible(pose);
}

glm::dvec2 gripPixel(const Book& book, const BookCamera& camera, const Grip& grip, const CurlParams& pose) {
    return PoseProblem(book, camera, grip, {0.0, 0.0}).pixelOf(pose);
}

namespace {

DragPose solvePose(const PoseProblem& problem, const Book& book, const Grip& grip, const CurlParams& start) {
    const double h = problem.height();
    const Unknowns from = toUnknowns(start, h);
    auto pixelError = [&](const Unknowns& u) {
        const std::array<double, 5> r = problem.residuals(u);
        return std::hypot(r[0], r[1]);
    };
    auto change = [&](const Unknowns& u) {
        return std::abs(u.c - from.c) + 0.3 * std::abs(u.b - from.b) + std::abs(u.rho - from.rho);
    };
    // Continue from the previous pose: the page moves with the pointer and never jumps between
    // branches while that pose still follows it (and shows the point it holds).
    Unknowns best = problem.solve(from);
    double bestError = pixelError(best);
    const bool bestVisible = problem.visible(toParams(best, h));
    if (bestError > kFollowPixels || !bestVisible) {
        // Lost the pointer (a fast move, or one the pose in hand cannot follow without a jump, as
        // when a flat page is first pulled inwards), or the point went inside the curl. Screen a
        // spread of starts with a few steps each: the schedule's poses, and tight, middling and loose
        // cones about the present rotation; refine the most promising, and of the visible ones that
        // follow the pointer as well as any, take the one nearest the pose in hand.
        std::vector<Unknowns> starts;
        for (const double t : kRestartProgress) starts.push_back(toUnknowns(book.scheduledPose(gripLeaf(book, grip), t), h));
        for (const double c : {0.5, 0.9, 0.99}) {
            for (const double apex : {0.2, 1.0, 3.0}) {
                for (const double dr : {-0.4, 0.0, 0.4}) starts.push_back(Unknowns{c, std::log(apex), from.rho + dr});
            }
        }
        std::vector<std::pair<double, Unknowns>> screened;
        for (const Unknowns& start : starts) {
            const Unknowns u = problem.solve(start, kScreenIterations);
            screened.emplace_back(PoseProblem::cost(problem.residuals(u)), u);
        }
        std::sort(screened.begin(), screened.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        std::vector<std::pair<Unknowns, double>> found;
        if (bestVisible) found.emplace_back(best, bestError);
        double leastError = 1e300;
        for (const auto& [u, error] : found) leastError = std::min(leastError, error);
        for (size_t i = 0; i < screened.size() && found.size() < kRefined + 1; ++i) {
            const Unknowns u = problem.solve(screened[i].second);
            if (!problem.visible(toParams(u, h))) continue;
            found.emplace_back(u, pixelError(u));
            leastError = std::min(leastError, found.back().second);
        }
        if (!found.empty() && (!bestVisible || leastError < bestError - kFollowPixels)) {
            double nearest = 1e300;
            for (const auto& [u, error] : found) {
                if (error <= leastError + kFollowPixels && change(u) < nearest) {
                    nearest = change(u);
                    best = u;
                    bestError = error;
                }
            }
        }
    }
    return DragPose{sanitize(toParams(best, h)), bestError};
}

}  // namespace

DragPose solveDragPose(const Book& book, const BookCamera& camera, const Grip& grip, glm::dvec2 pixel,
                       const CurlParams& start) {
    return solvePose(PoseProblem(book, camera, grip, pixel), book, grip, start);
}

DragPose solveSlidingDragPose(const Book& book, int width, int height, const Grip& grip, glm::dvec2 pixel,
                              const CurlParams& start) {
    const double shift = book.centerShift();  // the camera of the frame shown now
    const BookCamera camera = bookCamera(book.config(), width, height, book.zoom(), shift);
    return solvePose(PoseProblem(book, camera, grip, pixel, shift), book, grip, start);
}

bool shouldCompleteTurn(const Book& book, const BookCamera& camera, const Grip& grip, glm::dvec2 pixel,
                        glm::dvec2 velocity) {
    const BookConfig& c = book.config();
    // The pointer and its velocity in the page space of the turn: x < 0 is past the spine.
    const glm::dmat4 toPage = glm::inverse(placementOf(book, grip).pageToWorld);
    const double dt = 0.05;
    const glm::dvec3 here = pixelToTable(camera, pixel);
    const glm::dvec3 later = pixelToTable(camera, pixel + velocity * dt);
    const double x = (toPage * glm::dvec4(here, 1.0)).x;
    const double speed = ((toPage * glm::dvec4(later, 1.0)).x - x) / dt / c.pageWidth;  // pages per second
    if (speed < -kFlingPagesPerSecond) return true;
    if (speed > kFlingPagesPerSecond) return false;
    // Double display: past the spine. Single display, where the spine is the page's edge and a thumb
    // cannot reach past it: past the middle of the page shown (the turned side is out of view, so a
    // backward turn's page shown lies at x < 0 in its mirrored page space).
    if (c.display == Display::Double) return x < 0.0;
    return grip.backward ? x < -0.5 * c.pageWidth : x < 0.5 * c.pageWidth;
}

CurlParams hoverHintPose(const Book& book, const Grip& grip, double amount) {
    // A cone with its apex close below the page curls the corner at the apex end most; theta is
    // found by bisection so that corner rises amount * kHintLift page heights.
    (void)grip;  // the grip chose the corner already: its curl's page space puts it at (width, 0)
    const double h = book.config().pageHeight;
    const double w = book.config().pageWidth;
    const double lift = kHintLift * h * std::clamp(std::isnan(amount) ? 0.0 : amount, 0.0, 1.0);
    const double apex = -kHintApex * h;
    double flat = kPi / 2.0;
    double curled = 0.3;
    for (int i = 0; i < 48; ++i) {
        const double theta = 0.5 * (flat + curled);
        (curlPoint({w, 0.0}, CurlParams{theta, apex, 0.0}).z < lift ? flat : curled) = theta;
    }
    return sanitize(CurlParams{0.5 * (flat + curled), apex, 0.0});
}

}  // namespace conecurl
