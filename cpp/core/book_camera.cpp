// Camera framing and projections; see book_camera.hpp.
#include "book_camera.hpp"

#include <algorithm>
#include <cmath>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include "leaf_placement.hpp"

namespace conecurl {
namespace {
constexpr double kFieldOfViewY = 24.0 * 3.14159265358979323846 / 180.0;  // mild: a lift reads as one
}  // namespace

double frameMargin(Display display) { return display == Display::Single ? kSingleFrameMargin : kFrameMargin; }

BookCamera bookCamera(const Book& book, int width, int height, bool settled) {
    return bookCamera(book.config(), width, height, book.zoom(), settled ? book.settledCenterShift() : book.centerShift());
}

BookCamera bookCamera(const BookConfig& c, int width, int height, const ViewZoom& zoom, double shift) {
    BookCamera camera;
    camera.width = std::max(1, width);
    camera.height = std::max(1, height);
    const ViewFrame frame = viewFrameFor(c.display, c.binding, c.pageWidth, c.pageHeight);
    const double aspect = static_cast<double>(camera.width) / camera.height;
    const double tanHalf = std::tan(kFieldOfViewY * 0.5);
    const double margin = frameMargin(c.display);
    const double halfW = frame.halfExtent.x * margin;
    const double halfH = frame.halfExtent.y * margin;
    const double distance = std::max(halfH / tanHalf, halfW / (tanHalf * aspect));
    const glm::dvec2 moved = frame.center + shift * unturnedSide(c.binding);
    const glm::dvec3 center(moved.x, moved.y, 0.0);
    camera.eye = center + glm::dvec3(0.0, 0.0, distance);
    const double reach = std::max(c.pageWidth, c.pageHeight);
    const glm::dmat4 projection = glm::perspective(kFieldOfViewY, aspect, 0.02 * distance, distance + 2.0 * reach);
    // Zoom acts on the picture (after projection), so the perspective of a lifted leaf stays the same.
    glm::dmat4 magnify(1.0);
    magnify[0][0] = zoom.scale;
    magnify[1][1] = zoom.scale;
    magnify[3][0] = zoom.offsetX;
    magnify[3][1] = zoom.offsetY;
    camera.viewProjection = magnify * projection * glm::lookAt(camera.eye, center, glm::dvec3(0.0, 1.0, 0.0));
    camera.pixelsPerUnit = zoom.scale * camera.height / (2.0 * distance * tanHalf);
    // A leaf standing on its spine comes a page width nearer the eye.
    camera.magnification = distance / std::max(distance - c.pageWidth, 0.25 * distance);
    return camera;
}

ViewZoom zoomAbout(const ViewZoom& zoom, double scale, glm::dvec2 pixel, int width, int height) {
    const double ndcX = 2.0 * pixel.x / std::max(1, width) - 1.0;
    const double ndcY = 1.0 - 2.0 * pixel.y / std::max(1, height);
    const double s = clampZoom(ViewZoom{scale}).scale;
    // The unzoomed picture point under the pixel, then the offset that puts it back there.
    const double px = (ndcX - zoom.offsetX) / zoom.scale;
    const double py = (ndcY - zoom.offsetY) / zoom.scale;
    return clampZoom(ViewZoom{s, ndcX - s * px, ndcY - s * py});
}

ViewZoom panBy(const ViewZoom& zoom, glm::dvec2 pixels, int width, int height) {
    return clampZoom(ViewZoom{zoom.scale, zoom.offsetX + 2.0 * pixels.x / std::max(1, width),
                              zoom.offsetY - 2.0 * pixels.y / std::max(1, height)});
}

PixelRect restingRect(const BookCamera& camera, const BookConfig& config) {
    const ViewFrame frame = viewFrameFor(config.display, config.binding, config.pageWidth, config.pageHeight);
    const glm::dvec2 low = worldToPixel(camera, {frame.center - frame.halfExtent, 0.0});
    const glm::dvec2 high = worldToPixel(camera, {frame.center + frame.halfExtent, 0.0});
    return PixelRect{std::min(low.x, high.x), std::min(low.y, high.y), std::abs(high.x - low.x), std::abs(high.y - low.y)};
}

OpenPages openPagePlaces(const Book& book, const BookCamera& camera) {
    const BookConfig& c = book.config();
    OpenPages open;
    // The flat leaf's page corners, where the renderer puts them: no assumption about which side is which.
    auto place = [&](int leaf, bool turned) {
        const LeafDraw draw = book.restingLeaf(leaf, turned);
        const glm::dvec2 a = worldToPixel(camera, leafPointToWorld(draw, c.binding, c.pageHeight, {0.0, 0.0}));
        const glm::dvec2 b = worldToPixel(camera, leafPointToWorld(draw, c.binding, c.pageHeight, {c.pageWidth, c.pageHeight}));
        const PixelRect rect{std::min(a.x, b.x), std::min(a.y, b.y), std::abs(b.x - a.x), std::abs(b.y - a.y)};
        open.places[open.count++] = PagePlace{turned ? draw.backPage : draw.frontPage, rect, turned};
    };
    const int position = book.position();
    // In single display the turned side lies outside the view, as in Book::frame().
    if (c.display == Display::Double && position > 0) place(position - 1, true);
    if (position < book.leafCount()) place(position, false);
    return open;
}

double leafShareInView(const BookCamera& camera, const BookConfig& config, const LeafDraw& draw, int n) {
    n = std::max(1, n);
    int inside = 0;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            // Cell centres: each stands for an equal area of the flat page.
            const glm::dvec2 q((i + 0.5) / n * config.pageWidth, (j + 0.5) / n * config.pageHeight);
            const glm::dvec2 pixel = worldToPixel(camera, leafPointToWorld(draw, config.binding, config.pageHeight, q));
            if (pixel.x >= 0.0 && pixel.x <= camera.width && pixel.y >= 0.0 && pixel.y <= camera.height) ++inside;
        }
    }
    return static_cast<double>(inside) / (static_cast<double>(n) * n);
}

glm::dvec2 worldToPixel(const BookCamera& camera, glm::dvec3 world) {
    const glm::dvec4 clip = camera.viewProjection * glm::dvec4(world, 1.0);
    const double w = clip.w > 1e-12 ? clip.w : 1e-12;  // behind the eye cannot happen for a book
    return {(clip.x / w + 1.0) * 0.5 * camera.width, (1.0 - clip.y / w) * 0.5 * camera.height};
}

glm::dvec3 pixelToTable(const BookCamera& camera, glm::dvec2 pixel) {
    const glm::dmat4 inverse = glm::inverse(camera.viewProjection);
    const double nx = 2.0 * pixel.x / camera.width - 1.0;
    const double ny = 1.0 - 2.0 * pixel.y / camera.height;
    const glm::dvec4 nearPoint = inverse * glm::dvec4(nx, ny, -1.0, 1.0);
    const glm::dvec4 farPoint = inverse * glm::dvec4(nx, ny, 1.0, 1.0);
    const glm::dvec3 a = glm::dvec3(nearPoint) / nearPoint.w;
    const glm::dvec3 b = glm::dvec3(farPoint) / farPoint.w;
    const double s = a.z / (a.z - b.z);  // the camera looks straight down: a.z > 0 > b.z
    return a + (b - a) * s;
}

}  // namespace conecurl
