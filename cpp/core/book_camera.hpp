// The camera that frames a book on a canvas, and the projections between page, world and canvas
// pixels. Pure math: the renderer draws with it, and pointer input is solved against the same one.
#pragma once

#include <array>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "book.hpp"

namespace conecurl {

struct BookCamera {
    glm::dmat4 viewProjection;
    glm::dvec3 eye;
    int width = 1;              // drawing buffer, pixels
    int height = 1;
    double pixelsPerUnit = 1.0;  // at the page plane
    double magnification = 1.0;  // worst case for a leaf lifted towards the eye
};

// How much larger than the view frame the camera's picture is, in the dimension the box limits: a
// spread keeps room for leaves lifting up (kFrameMargin); a single page fills its box (a phone's
// screen is the book), and a lifting leaf may leave the canvas (kSingleFrameMargin).
double frameMargin(Display display);

// A mild perspective looking straight down at the view frame of the book, with room around it for
// leaves lifting up, magnified by `zoom`. Sizes below 1 pixel count as 1.
// `shift` moves the view along the spine's normal, towards the unturned side (Book::centerShift()).
BookCamera bookCamera(const BookConfig& config, int width, int height, const ViewZoom& zoom = {}, double shift = 0.0);
// The camera for `book` as it is now (its config, zoom and centre shift), or with `settled` as it
// will be once turns in flight land.
BookCamera bookCamera(const Book& book, int width, int height, bool settled = false);

// `zoom` changed to `scale` so that the table point under `pixel` stays under it (zooming about the
// pointer), kept inside clampZoom's limits.
ViewZoom zoomAbout(const ViewZoom& zoom, double scale, glm::dvec2 pixel, int width, int height);

// `zoom` moved by (dx, dy) canvas pixels (a pan), kept inside clampZoom's limits: the pages still
// fill the view.
ViewZoom panBy(const ViewZoom& zoom, glm::dvec2 pixels, int width, int height);

// Where the resting pages lie on the canvas (the view frame's corners projected by `camera`), in
// pixels: both page places of a spread in double display, the one page in single.
struct PixelRect {
    double x = 0.0, y = 0.0, width = 0.0, height = 0.0;
};
PixelRect restingRect(const BookCamera& camera, const BookConfig& config);

// A page lying open, where on the canvas, and whether it lies on the turned side (its free edge outward there).
struct PagePlace { int page = kNoPage; PixelRect rect; bool turned = false; };
struct OpenPages { std::array<PagePlace, 2> places{}; int count = 0; };
// The leaves lying open at the settled position (turns in flight ignored: where they will land), each
// with its visible page (kNoPage for a blank back) and its rectangle in canvas pixels under `camera`:
// the turned side first.
OpenPages openPagePlaces(const Book& book, const BookCamera& camera);

// The share of `draw`'s paper, by area, that projects inside the camera's canvas (what hides it
// aside): how much of a turning leaf the reader can see. Sampled on an n x n grid of page points.
double leafShareInView(const BookCamera& camera, const BookConfig& config, const LeafDraw& draw, int n = 64);

// Canvas pixel (x right, y down, origin at the top-left corner) of a world point.
glm::dvec2 worldToPixel(const BookCamera& camera, glm::dvec3 world);

// Where the ray through a canvas pixel meets the table plane (z = 0) of the resting pages.
glm::dvec3 pixelToTable(const BookCamera& camera, glm::dvec2 pixel);

}  // namespace conecurl
