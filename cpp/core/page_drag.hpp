// Dragging a page by its corner or edge: which leaf a pointer takes hold of, the cone pose that keeps
// the grabbed point under the pointer (solved on every move), the hover hint, and the release decision.
#pragma once

#include <optional>

#include <glm/vec2.hpp>

#include "book.hpp"
#include "book_camera.hpp"

namespace conecurl {

// A point of a leaf taken hold of, in the page space of the curl that will move it: x from the spine,
// y from the end of the spine where the cone's apex sits (flippedY: the far end, for top corners).
struct Grip {
    bool backward = false;       // the leaf turns back (it lies on the turned side)
    bool flippedY = false;       // taken nearer the far end of the spine
    glm::dvec2 pagePoint{0.0};   // the grabbed point
    bool nearCorner = false;     // close enough to a free corner for the hover hint
};

// The leaf point under a canvas pixel that a press would take hold of, if a leaf there can turn.
// In single display the spine-side quarter of the page takes hold of the previous leaf (which lies
// outside the view) by its free edge at the pointer's height.
std::optional<Grip> gripAt(const Book& book, const BookCamera& camera, glm::dvec2 pixel);

// Canvas pixel where the grabbed point is drawn with the held turn in `pose`.
glm::dvec2 gripPixel(const Book& book, const BookCamera& camera, const Grip& grip, const CurlParams& pose);

// Whether the eye sees the grabbed point with the held turn in `pose`: false where another part of
// the leaf lies in front of it (the point curled inside a roll). Sampled along the point's row.
bool gripVisible(const Book& book, const BookCamera& camera, const Grip& grip, const CurlParams& pose);

struct DragPose {
    CurlParams pose;
    double errorPixels;  // from the grabbed point's projection to the pointer; 0 where reachable
};

// The pose that puts the grabbed point under `pixel`, continued from `start` (the previous pose). Of
// the poses that do, the one nearest the schedule's pose at the same rotation; where none does, the
// nearest reachable one. Poses that hide the grabbed point inside the curl count as out of reach.
// Hard leaves stay flat and only rotate.
DragPose solveDragPose(const Book& book, const BookCamera& camera, const Grip& grip, glm::dvec2 pixel,
                       const CurlParams& start);

// The same on a `width` x `height` canvas through the camera of the pose found: a closed book slides as
// its cover turns (Book::centerShiftHolding), so the camera depends on the pose: the shift whose pose,
// solved through its camera, has that shift, to a hundredth of a pixel (secant steps, a few at most).
DragPose solveSlidingDragPose(const Book& book, int width, int height, const Grip& grip, glm::dvec2 pixel,
                              const CurlParams& start);

// On release at `pixel` moving at `velocity` (pixels per second): complete the turn when the pointer
// is past the line, unless flung back; fall back when short of it, unless flung on. The line is the
// spine in double display, and the middle of the page shown in single display (a thumb holding a phone
// cannot reach past the page's edge). A fling is a speed over 0.8 page widths a
// second towards either side, whatever the display.
bool shouldCompleteTurn(const Book& book, const BookCamera& camera, const Grip& grip, glm::dvec2 pixel,
                        glm::dvec2 velocity);

// The slight lift shown while the pointer hovers near a corner; `amount` in [0, 1] eases it in.
CurlParams hoverHintPose(const Book& book, const Grip& grip, double amount);

}  // namespace conecurl
