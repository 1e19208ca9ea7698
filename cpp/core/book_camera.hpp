// The camera that frames a book on a canvas, and the projections between page, world and canvas
// pixels. Pure math: the renderer draws with it, and pointer input is solved against the same one.
#pragma once

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

// A mild perspective looking straight down at the view frame of the book, with room around it for
// leaves lifting up, magnified by `zoom`. Sizes below 1 pixel count as 1.
BookCamera bookCamera(const BookConfig& config, int width, int height, const ViewZoom& zoom = {});

// `zoom` changed to `scale` so that the table point under `pixel` stays under it (zooming about the
// pointer), kept inside the limits of Book::setZoom.
ViewZoom zoomAbout(const ViewZoom& zoom, double scale, glm::dvec2 pixel, int width, int height);

// Canvas pixel (x right, y down, origin at the top-left corner) of a world point.
glm::dvec2 worldToPixel(const BookCamera& camera, glm::dvec3 world);

// Where the ray through a canvas pixel meets the table plane (z = 0) of the resting pages.
glm::dvec3 pixelToTable(const BookCamera& camera, glm::dvec2 pixel);

}  // namespace conecurl
