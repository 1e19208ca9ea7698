// Book state and animation: which leaves rest on which side, which are turning and how far. Each
// frame is composed as a short fixed-size list of leaf draws; the renderer only draws what it says.
#pragma once

#include <array>
#include <vector>

#include "book_constants.hpp"
#include "curl_schedule.hpp"

namespace conecurl {

enum class Display { Single = 0, Double = 1 };
enum class Binding { Left = 0, Right = 1, Top = 2 };  // where the spine is: LTR, RTL (manga), calendar
enum class TurnDirection { Forward = 0, Backward = 1 };

inline constexpr int kNoPage = -1;            // blank paper: an empty back, or no page at all
inline constexpr int kMaxLeafDraws = kMaxTurnsInFlight + 2;  // + the two resting pages

// Magnification of the view: the camera's picture scaled by `scale` about the canvas centre, then
// moved by `offset` (normalised device coordinates, -1..1 across the canvas). 1 and (0, 0): all of it.
struct ViewZoom {
    double scale = 1.0;
    double offsetX = 0.0;
    double offsetY = 0.0;
};

// `zoom` kept so the pages still fill the view: scale in [1, kMaxZoom], offset no more than
// scale - 1 either way; NaN scale counts as 1, NaN offset as 0.
ViewZoom clampZoom(const ViewZoom& zoom);

struct Stacks;  // book_stacks.hpp: the depth of the stacks of leaves on each side

struct BookConfig {
    int pageCount = 0;
    Display display = Display::Double;
    Binding binding = Binding::Left;
    double pageWidth = kDefaultPageWidth;    // world units from the spine to the free edge
    double pageHeight = kDefaultPageHeight;  // world units along the spine
    double turnSeconds = 1.0;
    CurlSchedule schedule;
    std::vector<bool> hardPages;  // by page index; pages past its end are soft
    bool center = true;  // a closed book (one cover alone) sits in the middle of the view: see centerShift()
    // A leaf's thickness as a fraction of the page width, for the stacks' depth (book_stacks.hpp); 0: none.
    double leafThickness = kDefaultLeafThickness;
};

// One leaf as it is to be drawn. Pages are the leaf's physical sides.
struct LeafDraw {
    int leaf = 0;
    int frontPage = kNoPage;  // the side facing up while the leaf rests unturned
    int backPage = kNoPage;
    CurlParams curl{};        // rho 0: resting unturned; pi: resting turned
    bool mirrored = false;    // a backward turn, posed as the mirror image of a forward one
    bool flippedY = false;    // curled from the far end of the spine (a drag from the top corner)
    bool hard = false;
    bool resting = false;     // flat in a stack: drawn first, receives shadows
};

struct BookFrame {
    std::array<LeafDraw, kMaxLeafDraws> leaves{};
    int count = 0;
};

class Book {
public:
    explicit Book(BookConfig config = {});

    const BookConfig& config() const { return config_; }
    int leafCount() const;
    // Positions are spreads in double display (0: the first page alone on the unturned side) and
    // pages in single display. The position is where the book settles once turns in flight land.
    int position() const { return position_; }
    int lastPosition() const;
    int positionOfPage(int page) const;
    // First visible page at the settled position; at a last spread that shows only a blank back,
    // the last page (lying face down under it). kNoPage for a book without pages.
    int firstVisiblePage() const;

    // Starts a turn; false (nothing changes) at the end of the book, if the leaf is already turning
    // or kMaxTurnsInFlight turns are in flight.
    bool startTurn(TurnDirection direction);
    // Sets the progress in [0, 1] of the most recently started turn (exact frames for tests, scrubbing).
    void setLatestTurnProgress(double progress);
    // Advances every turn in flight; turns that reach 1 land. Returns whether any is still in flight.
    bool advance(double seconds);
    bool animating() const { return turnCount_ > 0; }
    // Whether time changes the frame: a turn in flight that is not held, or a held one still
    // catching up with its target pose. A resting book or a still held leaf needs no new frames.
    bool moving() const;
    // Turns towards a far `position` by a riffle: up to kMaxTurnsInFlight leaves, spread evenly over
    // the way there (the first leaf from the top of the stack, the last landing at `position`), start
    // one after another and turn a little faster than a single turn; the leaves between them travel
    // with the one ahead (they are not drawn, and land with it). All of it lands within
    // kRiffleSpan turn durations. False (nothing changes) while a leaf is in flight or held, or for a
    // position one leaf away or less (a plain turn).
    bool riffleTo(int position);
    // The paper's thickness from now on (config.leafThickness), kept in [0, kMaxLeafThickness]; NaN: 0.
    void setLeafThickness(double leafThickness);
    // Jumps to a position at once, dropping turns in flight.
    void jumpTo(int position);
    // Shows one page or two from now on, keeping the first visible page in view; turns in flight land
    // at once. Pages keep their indices, so whatever the renderer holds for them stays valid.
    void setDisplay(Display display);
    // The pages changed on a live book (pages inserted, removed or replaced): `pageCount` pages, hard as
    // `hardPages` says (by index; pages past its end are soft). Turns in flight land at once and the
    // first visible page's index stays in view, clamped to the book, as setDisplay keeps it; the caller
    // jumps on to where the page it follows went.
    void setPages(int pageCount, std::vector<bool> hardPages);

    // Held turns follow a pointer: the pose is set from outside (see page_drag.hpp) until the turn
    // is let go. At most one is held; starting one fails where startTurn would, or while one is held.
    bool startHeldTurn(TurnDirection direction, bool flippedY);
    bool holding() const;
    TurnDirection heldDirection() const;
    bool heldFlippedY() const;
    int heldLeaf() const;
    // Shows `pose` at once.
    void setHeldPose(const CurlParams& pose);
    // Moves towards `pose`: at once for a small step, else catching up over a few frames of advance()
    // (a pointer that the pose in hand could not follow without a jump).
    void setHeldTarget(const CurlParams& pose);
    CurlParams heldPose() const;    // as shown
    CurlParams heldTarget() const;  // where it is heading
    // Lets the held turn go from its pose: it completes, or falls back to where it started (the
    // position steps back at once). Either way it blends into the schedule with no jump: rho carries
    // on along the schedule from where it is, theta and apex offsets fade out by the turn's end.
    void releaseHeldTurn(bool complete);

    // View magnification, kept so the pages still fill the view: scale in [1, kMaxZoom], offset no more
    // than scale - 1 either way. Not book state as such, but the camera reads it from here.
    void setZoom(const ViewZoom& zoom);
    const ViewZoom& zoom() const { return zoom_; }

    // How far the camera moves along the spine's normal, towards the unturned side, so what is in
    // view sits in the middle: half a page width (plus half the edge band of the stack under it, see
    // book_stacks.hpp) towards a front cover alone on the unturned side, back again as it turns open;
    // the same the other way for a back cover alone. 0 for an open book or with config.center off. In
    // single display, where the page fills the view, it moves towards the turned side while a leaf
    // turns, up to half a page width as a leaf stands on its spine, so the curl stays in view; 0 at
    // rest. It follows the leaves' rotation, so the book slides as part of the turn (and of a drag)
    // with no jump.
    double centerShift() const;
    // The same once turns in flight have landed (where the open pages will lie).
    double settledCenterShift() const;
    // centerShift() with the held leaf shown at `pose` (the camera a drag's pose would be seen through).
    double centerShiftHolding(const CurlParams& pose) const;

    // The top leaf of the turned (or unturned) stack: the nearest to the position that is not in flight
    // (nor carried by a riffling leaf); -1 (or leafCount()) for an empty stack. The leaves below it
    // down to 0 (up to leafCount() - 1) all rest in that stack.
    int stackTop(bool turned) const;

    bool isHardLeaf(int leaf) const;
    // The pose of a leaf turning at progress p (soft: the schedule; hard: rigid).
    CurlParams scheduledPose(int leaf, double progress) const;
    BookFrame frame() const;
    // `leaf` lying flat in its stack, turned (rho pi, its back page up) or not (rho 0): as frame() draws it.
    LeafDraw restingLeaf(int leaf, bool turned) const;

private:
    struct Turn {
        int leaf;
        TurnDirection direction;
        double progress;
        bool flippedY = false;
        bool held = false;          // pose comes from heldPose
        bool fallingBack = false;   // runs from progress down to 0, then lands where it started
        CurlParams heldPose{};
        CurlParams heldTarget{};
        double blendFrom = 0.0;     // progress at release; the released pose fades from there to the end
        bool released = false;      // let go by the pointer: its pose is eased into the schedule's
        CurlParams releasedPose{};  // the pose when let go
        int carriedTo = -1;         // riffle: the far end of the leaves carried with this one (-1: none)
        double speed = 1.0;         // progress per turn duration
    };
    CurlParams poseOf(const Turn& turn) const;
    double shiftFor(double unturnedSide, double turnedSide, const Stacks& stacks) const;
    double shiftOf(const BookFrame& frame) const;
    int heldIndex() const;
    int frontPageOf(int leaf) const;
    int backPageOf(int leaf) const;
    bool inFlight(int leaf) const;

    BookConfig config_;
    int position_ = 0;
    ViewZoom zoom_;
    std::array<Turn, kMaxTurnsInFlight> turns_{};
    int turnCount_ = 0;
};

// Pose of a hard leaf (a cover) at progress p: flat, turned rigidly about the spine with easing.
CurlParams rigidTurnAt(double progress, double pageHeight);

}  // namespace conecurl
