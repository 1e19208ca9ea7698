// Draws a Book's frame with WebGL2 through Emscripten's GL layer: resting pages, leaves in flight,
// light, gutter and shadow. It owns GL objects only; what to draw comes from Book::frame().
#pragma once

#include <GLES3/gl3.h>
#include <emscripten/html5_webgl.h>

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "book.hpp"
#include "book_camera.hpp"
#include "leaf_placement.hpp"
#include "page_grid.hpp"

namespace conecurl {

struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;  // rows top to bottom, as ImageData holds them
};

struct RenderOptions {
    bool lighting = true;
    bool shadows = true;
    bool gutter = true;
};

class BookRenderer {
public:
    // Creates a WebGL2 context on the canvas found by `canvasTarget` (a CSS selector, or a name
    // registered in Emscripten's specialHTMLTargets). On failure ok() is false and error() says why.
    // antialias: multisampled edges (smooth curl silhouettes); a software rasterizer pays ~30% a frame for it.
    explicit BookRenderer(const std::string& canvasTarget, bool antialias = true);
    ~BookRenderer();
    BookRenderer(const BookRenderer&) = delete;
    BookRenderer& operator=(const BookRenderer&) = delete;

    bool ok() const { return error_.empty(); }
    // False when no WebGL2 context could be made at all (as opposed to a shader that failed to build).
    bool hasContext() const { return context_ != 0; }
    const std::string& error() const { return error_; }

    void setOptions(const RenderOptions& options) { options_ = options; }
    const RenderOptions& options() const { return options_; }

    // RGBA8 pixels of page `page`, rows top to bottom, width * height * 4 bytes. Returns an empty
    // string, or why the image was refused; the renderer keeps working either way.
    std::string setPageImage(int page, int width, int height, const std::uint8_t* rgba);
    void releasePageImage(int page);
    bool hasPageImage(int page) const { return pageTextures_.count(page) != 0; }
    int residentPageImages() const { return static_cast<int>(pageTextures_.size()); }

    // Draws one frame of the book into the canvas's drawing buffer.
    void draw(const Book& book);
    int framesDrawn() const { return framesDrawn_; }

    // The pixels of the last drawn frame, rows top to bottom (call in the same task as draw()).
    RgbaImage readPixels();

    // Runs the vertex shader of leaf `drawIndex` of the book's frame over every grid vertex with
    // transform feedback: per vertex the world position and normal, x y z nx ny nz.
    std::vector<float> captureLeaf(const Book& book, int drawIndex);

    // Grid rows for the page mesh; columns follow the page's aspect. 0 chooses from the canvas size.
    void setGridRows(int rows) { requestedRows_ = rows; }
    const PageGrid& grid() const { return grid_; }
    // The chosen grid's verified mesh error in pixels at the current canvas (NaN for fixed rows).
    double gridErrorPixels() const { return gridErrorPixels_; }
    int maxTextureSize() const { return maxTextureSize_; }

    // After a lost context is restored: recreates every GL object from CPU-side state. Page images
    // are GPU-only and must be set again (the JS layer keeps their sources).
    void recreateGpuObjects();

private:
    struct Camera {
        glm::mat4 viewProjection;
        glm::vec3 eye;
        float pixelsPerUnit;  // at the page plane
        float magnification;  // worst case for a leaf lifted towards the eye
    };

    bool makeCurrent();
    void createGpuObjects();
    void destroyGpuObjects();
    void updateGrid(const Book& book, const Camera& camera, int width, int height);
    void uploadGrid();
    Camera cameraFor(const Book& book, int width, int height) const;
    void ensureShadowTarget(int width, int height);
    void drawLeaf(const Book& book, const LeafDraw& leaf, const Camera& camera, bool receiveShadow);
    GLuint textureFor(int page) const;

    std::string error_;
    EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context_ = 0;
    RenderOptions options_;
    int framesDrawn_ = 0;
    int requestedRows_ = 0;
    PageGrid grid_;
    double gridErrorPixels_ = 0.0;
    struct GridKey {  // what the grid choice depends on: it is made again only when this changes
        int width = 0, height = 0, requestedRows = -1;
        double pageWidth = 0.0, pageHeight = 0.0;
        Display display = Display::Double;
        Binding binding = Binding::Left;
        double zoomStep = 1.0;
        bool operator==(const GridKey& o) const {
            return width == o.width && height == o.height && requestedRows == o.requestedRows &&
                   pageWidth == o.pageWidth && pageHeight == o.pageHeight && display == o.display &&
                   binding == o.binding && zoomStep == o.zoomStep;
        }
    } gridKey_;
    int maxTextureSize_ = 0;
    float maxAnisotropy_ = 0.0f;
    int drawingWidth_ = 0;
    int drawingHeight_ = 0;

    // Uniform locations, looked up once per program: the per-frame path makes no string lookups.
    struct Uniforms {
        GLint curl = -1, normalStep = -1, pageToWorld = -1, viewProjection = -1;
        GLint lightDirection = -1, facingTexture = -1, awayTexture = -1, facingUv = -1, awayUv = -1;
        GLint pageSize = -1, eye = -1, lighting = -1, gutter = -1, shadow = -1, shadowMask = -1;
        GLint shadowTexel = -1, viewportInverse = -1, paper = -1, shadowStrength = -1, pageWidth = -1;
    };
    static Uniforms locate(GLuint program);
    // Where the leaf is (both programs); then how its surface looks (the leaf program only).
    LeafPlacement setPlacementUniforms(const Uniforms& u, const Book& book, const LeafDraw& leaf, const Camera& camera);
    void setSurfaceUniforms(const Book& book, const LeafDraw& leaf, const LeafPlacement& placement, const Camera& camera);

    GLuint leafProgram_ = 0;
    GLuint shadowProgram_ = 0;
    Uniforms leafUniforms_;
    Uniforms shadowUniforms_;
    GLuint vertexArray_ = 0;
    GLuint vertexBuffer_ = 0;
    GLuint indexBuffer_ = 0;
    GLuint captureBuffer_ = 0;
    GLuint paperTexture_ = 0;
    GLuint shadowFramebuffer_ = 0;
    GLuint shadowTexture_ = 0;
    int shadowWidth_ = 0;
    int shadowHeight_ = 0;
    std::unordered_map<int, GLuint> pageTextures_;
};

}  // namespace conecurl
