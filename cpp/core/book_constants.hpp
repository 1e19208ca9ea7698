// The numbers the JS layer shares with the engine, in one place: CMakeLists.txt turns each line
// below into dist/engine-constants.js, so keep them one `inline constexpr <type> kName = value;` a line.
#pragma once

#include <string_view>

namespace conecurl {

inline constexpr int kMaxPages = 1000000;  // the most pages a Book, and the renderer's page numbers, take
// FrameLoop.requestTurn's answers (TurnRequest in book_clock.hpp).
inline constexpr int kTurnStarted = 0;
inline constexpr int kTurnQueued = 1;  // waits behind a leaf in flight
inline constexpr int kTurnRefused = 2;  // at the end of the book, or too many queued
// The side a book's spine binds on, as the engine's Book takes it (BookConfig.binding).
inline constexpr std::string_view kBindingLeft = "left";
inline constexpr std::string_view kBindingRight = "right";
inline constexpr std::string_view kBindingTop = "top";

inline constexpr int kMaxTurnsInFlight = 6;
inline constexpr double kRiffleSpan = 1.75;  // a riffle to a far page lands within this many turn durations
inline constexpr double kMaxZoom = 4.0;
inline constexpr double kFrameMargin = 1.3;  // double display: room around the spread for leaves lifting up
inline constexpr double kSingleFrameMargin = 1.06;  // single display: the page fills 94% of its box
inline constexpr double kDefaultPageWidth = 0.8;  // world units from the spine to the free edge
inline constexpr double kDefaultPageHeight = 1.0;  // world units along the spine
inline constexpr double kDefaultLeafThickness = 0.004;  // a leaf, of the page width: stacks' depth (thickness: true)
inline constexpr double kMaxLeafThickness = 0.02;  // the largest the thickness option takes
inline constexpr double kBoardThicknessOfWidth = 0.012;  // a board (a hard cover), of the page width, whatever the paper
// The paper of a stack never gets deeper than this fraction of the page width: it approaches it
// smoothly (raw / sqrt(1 + (raw / cap)^2): about raw for a thin stack), so a 1000-page book stays a
// book, not a brick, and every added leaf still adds depth (book_stacks.hpp).
inline constexpr double kMaxPaperDepthOfWidth = 0.1;
inline constexpr int kPaperRed = 250;  // placeholder paper, shown before a page's image arrives
inline constexpr int kPaperGreen = 247;
inline constexpr int kPaperBlue = 240;
// How much of a leaf's print shows through its blank back (single display) by default: thin paper.
inline constexpr double kDefaultShowThrough = 0.1;

}  // namespace conecurl
