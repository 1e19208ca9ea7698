// Draws a Book's frame with WebGL2 through Emscripten's GL layer: resting pages, leaves in flight,
// light, gutter and shadow. It owns GL objects only; what to draw comes from Book::frame(). While
// leaves move, what rests (stacks, resting pages, their light) is drawn once into a cached texture and
// each frame lays it down with one blit or draw; only the moving leaves and their shadow are shaded.
// Moving frames may be drawn at a fraction of the canvas's pixels offscreen and scaled up (movingScale).
#pragma once

#include <GLES3/gl3.h>
#include <emscripten/html5_webgl.h>
#include <emscripten/val.h>

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "book.hpp"
#include "book_camera.hpp"
#include "book_stacks.hpp"
#include "gl_program.hpp"
#include "edge_marks_renderer.hpp"
#include "leaf_placement.hpp"
#include "page_grid.hpp"
#include "world_box.hpp"

namespace conecurl {

struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;  // rows top to bottom, as ImageData holds them
};

// A JS value held by Embind (emscripten::val::as_handle()), e.g. the image a page is uploaded from.
using JsHandle = decltype(std::declval<emscripten::val>().as_handle());

struct RenderOptions {
    bool lighting = true;
    bool shadows = true;
    bool gutter = true;
    // The share of the drawing buffer's width and height a frame with moving leaves is drawn at, in
    // (0, 1]: below 1 it is drawn offscreen and scaled up to the canvas. Resting frames are always whole.
    double movingScale = 1.0;
    // How much of the other side's print shows through a blank side of a soft leaf (single display's
    // back), in [0, 1]: thin paper held to the light. 0: none.
    double showThrough = kDefaultShowThrough;
};

class BookRenderer {
public:
    // Creates a WebGL2 context on the canvas found by `canvasTarget` (a CSS selector, or a name
    // registered in Emscripten's specialHTMLTargets). On failure ok() is false and error() says why.
    // Only the resting frame's programs are linked here; a turn's are linked at their first draw (a
    // program that fails then makes ok() false from that frame on).
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

    // Uploads page `page` straight from a browser image (an ImageBitmap, canvas, <img>, ImageData,
    // video frame: anything WebGL's texImage2D takes) of `width` x `height` pixels, with no copy
    // through the wasm heap. Returns an empty string, or why the image was refused; a source whose
    // pixels the page may not read (cross-origin without CORS) is refused with kTaintedSource. The
    // renderer keeps working either way.
    static constexpr const char* kTaintedSource = "tainted";
    std::string setPageImage(int page, int width, int height, JsHandle source);
    // The same upload in horizontal bands, one call a band (page_bands.cpp), so that no frame of a turn
    // carries a whole page: rows [y, y + rows) of the `width` x `height` source go into a texture of
    // their own, which takes the page's place once its last row is in (until then the page shows what
    // it showed). Bands come in order from y = 0; y = 0 starts over. Returns as setPageImage does, or
    // why the band was refused.
    std::string setPageImageRows(int page, int width, int height, int y, int rows, JsHandle source);
    // The page whose upload in bands is under way, or -1.
    int pageInBands() const { return band_.page; }
    void releasePageImage(int page);
    // The book's pages were spliced: `removed` pages at `at` went (their textures are released) and
    // `inserted` pages came in their place, so textures of later pages move to their new indices (no
    // upload: the same texture objects, renumbered).
    void splicePageImages(int at, int removed, int inserted);
    bool hasPageImage(int page) const { return findTexture(page) != pageTextures_.end(); }
    int residentPageImages() const { return static_cast<int>(pageTextures_.size()); }

    // Draws one frame of the book into the canvas's drawing buffer.
    void draw(const Book& book) { draw(book, book.frame()); }
    // The same, with the frame the caller composed already (the frame loop composes it once).
    void draw(const Book& book, const BookFrame& frame);
    int framesDrawn() const { return framesDrawn_; }
    // The scale the last frame was drawn at: movingScale's (rounded to whole pixels) while leaves
    // moved, 1 for a resting frame.
    double lastFrameScale() const { return lastFrameScale_; }
    // How many times the resting spread was drawn into its cache: once when a turn starts, then again
    // only when what rests changes (a page image, a leaf that lands or lifts, size, camera, options).
    int restingSpreadDraws() const { return restingSpreadDraws_; }
    // Something drawn in the resting spread changed outside what the renderer tracks (e.g. marks on
    // the page block): the next turning frame draws the spread again.
    void invalidateRestingSpread() { restingKey_.fill(kNoKey); }

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
    // The anisotropy page textures are filtered with: 1 until prepareTurn() found this GPU's filtering right.
    float anisotropy() const { return anisotropy_; }
    // Tabs and ticks on the page blocks' fore-edge (edge_marks_renderer.hpp), drawn over the stacks.
    EdgeMarksRenderer& edgeMarks() { return edgeMarks_; }

    // Readies the programs a turning frame draws that resting frames do not (the leaf; with shadows the
    // shadow and the shadow received; on a multisampled canvas the composite), so the first turn does
    // not pay for them: the JS layer calls it in idle time once the first view is shown, and again in a
    // later idle task while it returns false. Where the browser has KHR_parallel_shader_compile, the
    // first call asks for their compiles and links and returns false, and a later one, once the driver
    // says they are done, checks them and returns true: no call waits on a compile. Without it, one call
    // compiles, links and checks them. A turn before then links its own at its first frame, as it waits.
    // The call that finds them linked also asks, once a page, whether anisotropic filtering draws a page at
    // rest as trilinear does (a draw read back, anisotropy_probe.cpp); until then pages go without it.
    bool prepareTurn();

    // The first view leaves out what its frame does not need, each a wait on the browser's GL (first_view.cpp):
    // the page textures' mipmaps (a page at rest is drawn at about its image's size; WebKit on llvmpipe spent
    // 76-134 ms making the first ones), asking the drawing buffer's size (in Firefox a round trip to its
    // GPU process, which waited 230 ms on all the first view had queued), taken from the canvas meanwhile.
    // The JS layer calls this once the first view is on screen, in idle time; the first frame with a moving
    // leaf does it first if that comes sooner. Returns true if the drawing buffer is not the canvas's size
    // (the browser clamped it): the frame drawn at that size must be drawn again. Later calls do nothing.
    bool finishFirstView();

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

    // Uniforms by name, in both programs; a program lacks some (location -1).
    enum Uniform : int {
        uCurl, uCurlTrig, uNormalStep, uPageToWorld, uViewProjection, uLightDirection, uFacingTexture,
        uAwayTexture, uFacingUv, uAwayUv, uPageSize, uEye, uLighting, uGutter, uLeaf, uShadowMask,
        uViewportInverse, uPaper, uShadowStrength, uPenumbra, uFlatLight, uCache, uCacheOffset, uShowThrough,
        uMirrorLight, uMirroredLight, kUniformCount
    };
    // A linked program, its uniform locations (looked up once: the per-frame path makes no string
    // lookups) and the value each uniform was last given, so an unchanged value costs no GL call.
    struct Program {
        GLuint id = 0;
        PendingProgram pending;  // asked for (start) and not yet checked
        std::array<GLint, kUniformCount> location{};
        std::array<std::array<float, 16>, kUniformCount> value{};
        std::array<bool, kUniformCount> known{};
    };
    // Which program a Program member is: each is compiled and linked on first use (useProgram), so a
    // resting book links only the two its frame draws (stacks, flat pages) and a turn the others.
    enum class Kind { leaf, shadow, stack, flat, composite };
    Kind kindOf(const Program& program) const;
    ProgramSource sourceOf(Kind kind) const;
    void start(Program& program);  // asks for its compile and link, checking nothing (gl_program.hpp)
    bool build(Program& program);  // compiles (unless started), links and sets the constant uniforms; false (error_) on failure
    void locate(Program& program);
    // Sets `count` floats of uniform `u` of the program in use (1-4: a vector, 9 or 16: a matrix).
    void setUniform(Program& program, Uniform u, const float* values, int count);
    void setUniform(Program& program, Uniform u, float x) { setUniform(program, u, &x, 1); }
    void useProgram(Program& program);
    void bindTexture(int unit, GLuint texture, bool toEdit = false);

    bool makeCurrent();
    void createGpuObjects();
    void destroyGpuObjects();
    void updateGrid(const Book& book, const Camera& camera, int width, int height);
    void uploadGrid();
    static Camera toGpu(const BookCamera& camera);  // the core's camera in float
    Camera cameraFor(const Book& book, int width, int height) const;
    // The camera what rests is cached through while leaves move: the book's with no centre shift. The
    // shift slides the camera along the page plane, which moves everything on it by the same pixels, so
    // one cache serves every frame of a turn, laid down that many pixels away (cacheOffset). Zoomed in,
    // what would slide into view lies outside the cache: then it is the book's camera itself.
    Camera restingCameraFor(const Book& book, int width, int height) const;
    void ensureShadowTarget(int width, int height);
    void drawLeaf(const Book& book, const LeafDraw& leaf, const Camera& camera);
    // A resting leaf with the flat program (the side seen and its light decided here, once).
    void drawFlatPage(const Book& book, const LeafDraw& leaf, const Camera& camera);
    // What rests: the stacks' edges, then the resting pages over them; nothing depth-tested.
    void drawRestingSpread(const Book& book, const BookFrame& frame, const Camera& camera);
    void setBlendEquation(GLenum equation);
    // The key of what the resting spread shows; equal keys draw equal pictures.
    using RestingKey = std::array<double, 16 + 8 + 10 * kMaxLeafDraws>;
    static constexpr double kNoKey = -1.0e300;
    RestingKey restingKey(const Book& book, const BookFrame& frame, const Camera& camera, int width, int height) const;
    void ensureCacheTarget(int width, int height);
    // Gives `texture` (bound at `unit`) width x height of RGBA8, `filter`ed and clamped, and attaches it
    // as the colour of `framebuffer`, which is left bound.
    void colorTarget(GLuint framebuffer, int unit, GLuint texture, int width, int height, GLint filter);
    // Lays the cached resting spread over the target (`target`: 0 for the canvas, else the scaled
    // frame's framebuffer), over its rectangle: with the shadow, a draw that darkens it by the mask;
    // without, a blit (a draw on a multisampled canvas, which takes no blit).
    void composeRestingSpread(GLuint target, bool shadows, int width, int height, std::array<int, 2> offset);
    // Where what rests lies in the world: the resting pages, the stacks' faces and the marks on them.
    WorldBox restingBox(const Book& book, const BookFrame& frame) const;
    // The offscreen target of a scaled moving frame (colour texture and depth), then its scaling up
    // into the canvas: a linear blit, or a draw on a multisampled canvas.
    void ensureScaledTarget(int width, int height);
    void presentScaledFrame(int width, int height);
    // Lays `texture` over the bound target's `width` x `height` pixels with the composite program
    // (unit 3), darkened by the shadow mask (unit 2) when `shadowed`.
    void drawComposite(GLuint texture, int width, int height, bool shadowed, std::array<int, 2> offset = {0, 0});
    // The stacks' edge faces: their buffer is rebuilt only when what they depend on changes.
    void updateStacks(const Book& book);
    void drawStacks(const Camera& camera);
    using PageTextures = std::vector<std::pair<int, GLuint>>;  // a few dozen at most: a list beats a hash map
    PageTextures::const_iterator findTexture(int page) const;
    GLuint textureFor(int page) const;
    void forgetGpuObjects();

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
    // EXT_texture_filter_anisotropic's enums: a texture's level, and the GPU's most.
    static constexpr GLenum kTextureMaxAnisotropy = 0x84FE;
    static constexpr GLenum kMaxTextureMaxAnisotropy = 0x84FF;
    float maxAnisotropy_ = 0.0f;  // the GPU's most, 0 without the extension
    float anisotropy_ = 1.0f;     // what page textures get: 1 until this GPU is known to filter right (pageAnisotropy)
    // The anisotropy page textures get: 1 without the extension, or where it filters a page at rest otherwise
    // than trilinear (Mesa's llvmpipe), else up to 8. Found once a page by drawing (anisotropy_probe.cpp):
    // with `probe` false an unknown answer is 1 and nothing is drawn.
    float pageAnisotropy(bool probe);
    // Once the composite program is linked (prepareTurn): the probe's answer, given to every page texture.
    void settleAnisotropy();
    bool anisotropyUnknown() const;  // the GPU has it and the page has not probed it yet
    bool probeAnisotropy();  // draws, reads back and compares: a wait on the GL, for idle time
    void setBoundAnisotropy();  // the page texture bound for editing gets anisotropy_ (no call where it is 1)
    int drawingWidth_ = 0;
    int drawingHeight_ = 0;
    bool firstView_ = true;  // see finishFirstView()
    std::vector<GLuint> withoutMipmaps_;  // page textures uploaded in the first view, filtered without mipmaps
    struct BufferSize { int canvasWidth = -1, canvasHeight = -1, width = 0, height = 0; } bufferSize_;  // as last asked
    // The drawing buffer's size for a frame: the canvas's in the first view, else the browser's (asked again
    // only when the canvas's size changed).
    void drawingBufferSize(int& width, int& height);
    // The page texture bound to unit 0 for editing: its mipmaps and filtering, or (first view) filtering without.
    void finishPageTexture(GLuint texture);
    void makeMipmaps();

    // Where the leaf is and whether it lies flat (every program that draws a leaf's grid); then how its
    // surface looks (the leaf program only).
    LeafPlacement setPlacementUniforms(Program& program, const Book& book, const LeafDraw& leaf, const Camera& camera);
    void setSurfaceUniforms(const Book& book, const LeafDraw& leaf, const LeafPlacement& placement, const Camera& camera);

    Program leafProgram_;
    Program shadowProgram_;
    Program stackProgram_;
    Program flatProgram_;       // resting pages (flat_page.*)
    Program compositeProgram_;  // the cache laid down with the shadow on it; a scaled frame onto a multisampled canvas
    int stackGeneration_ = 0;   // counts rebuilds of the stacks' buffer, for the resting key
    int restingSpreadDraws_ = 0;
    RestingKey restingKey_{};
    glm::mat4 lastViewProjection_{0.0f};  // the last frame's camera: a moving one is not cached
    std::array<GLuint, 2 * kMaxLeafDraws> cachedTextures_{};  // the page textures the cache shows
    GLuint cacheFramebuffer_ = 0;
    GLuint cacheTexture_ = 0;
    int cacheWidth_ = 0;
    int cacheHeight_ = 0;
    GLuint scaledFramebuffer_ = 0;  // a moving frame drawn at movingScale, before it is scaled up
    GLuint scaledTexture_ = 0;
    GLuint scaledDepth_ = 0;
    int scaledWidth_ = 0;
    int scaledHeight_ = 0;
    double lastFrameScale_ = 1.0;
    GLint canvasSamples_ = 0;   // the drawing buffer's samples (0: not multisampled, a blit composes)
    GLuint stackBuffer_ = 0;
    int stackVertexCount_ = 0;
    WorldBox stackBox_;                      // where the stacks' faces lie
    std::array<int, 4> restingRect_{};       // the cache's pixels that hold what rests: x, y, width, height
    struct StackKey {  // what the stacks' faces depend on
        StackLeaves leaves;
        double thickness = -1.0, pageWidth = 0.0, pageHeight = 0.0;
        Display display = Display::Double;
        Binding binding = Binding::Left;
        bool operator==(const StackKey& o) const {
            return leaves == o.leaves && thickness == o.thickness && pageWidth == o.pageWidth &&
                   pageHeight == o.pageHeight && display == o.display && binding == o.binding;
        }
    } stackKey_;
    GLuint programInUse_ = 0;
    bool parallelCompile_ = false;  // KHR_parallel_shader_compile enabled
    static constexpr int kMaxTurnPolls = 30;
    int turnPolls_ = 0;  // prepareTurn()'s asks of the driver since it started the turn's programs
    std::array<GLuint, 4> boundTextures_{};  // per texture unit, as last bound here (3: the cache)
    GLenum blendEquation_ = 0;
    int activeUnit_ = -1;
    GLuint vertexArray_ = 0;
    GLuint vertexBuffer_ = 0;
    GLuint indexBuffer_ = 0;
    GLuint captureBuffer_ = 0;
    GLuint paperTexture_ = 0;
    GLuint shadowFramebuffer_ = 0;
    GLuint shadowTexture_ = 0;
    int shadowWidth_ = 0;
    int shadowHeight_ = 0;
    PageTextures pageTextures_;
    EdgeMarksRenderer edgeMarks_;
    // The upload in bands under way (page_bands.cpp): its texture, filled down to `rows`.
    struct Band {
        int page = -1;
        GLuint texture = 0;
        int width = 0;
        int height = 0;
        int rows = 0;
    } band_;
    void dropBand(bool deleteTexture = true);
};

}  // namespace conecurl
