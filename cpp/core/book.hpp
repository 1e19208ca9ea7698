// Book state and animation: which leaves rest on which side, which are turning and how far. Each
// frame is composed as a short fixed-size list of leaf draws; the renderer only draws what it says.
#pragma once

#include <array>
#include <vector>

#include "curl_schedule.hpp"

namespace conecurl {

enum class Display { Single = 0, Double = 1 };
enum class Binding { Left = 0, Right = 1, Top = 2 };  // where the spine is: LTR, RTL (manga), calendar
enum class TurnDirection { Forward = 0, Backward = 1 };

inline constexpr int kNoPage = -1;            // blank paper: an empty back, or no page at all
inline constexpr int kMaxTurnsInFlight = 6;
inline constexpr int kMaxLeafDraws = kMaxTurnsInFlight + 2;  // + the two resting pages

struct BookConfig {
    int pageCount = 0;
    Display display = Display::Double;
    Binding binding = Binding::Left;
    double pageWidth = 0.8;   // world units from the spine to the free edge
    double pageHeight = 1.0;  // world units along the spine
    double turnSeconds = 1.0;
    CurlSchedule schedule;
    std::vector<bool> hardPages;  // by page index; pages past its end are soft
};

// One leaf as it is to be drawn. Pages are the leaf's physical sides.
struct LeafDraw {
    int leaf = 0;
    int frontPage = kNoPage;  // the side facing up while the leaf rests unturned
    int backPage = kNoPage;
    CurlParams curl{};        // rho 0: resting unturned; pi: resting turned
    bool mirrored = false;    // a backward turn, posed as the mirror image of a forward one
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
    // Jumps to a position at once, dropping turns in flight.
    void jumpTo(int position);

    bool isHardLeaf(int leaf) const;
    BookFrame frame() const;

private:
    struct Turn {
        int leaf;
        TurnDirection direction;
        double progress;
    };
    int frontPageOf(int leaf) const;
    int backPageOf(int leaf) const;
    bool inFlight(int leaf) const;
    LeafDraw restingLeaf(int leaf, bool turned) const;

    BookConfig config_;
    int position_ = 0;
    std::array<Turn, kMaxTurnsInFlight> turns_{};
    int turnCount_ = 0;
};

// Pose of a hard leaf (a cover) at progress p: flat, turned rigidly about the spine with easing.
CurlParams rigidTurnAt(double progress, double pageHeight);

}  // namespace conecurl
