// WebGL2 drawing of a book frame. Per frame only uniforms change, and only those whose value did;
// constant uniforms and samplers are set once after linking. The page grid is a static buffer
// rebuilt only when the canvas size calls for a different resolution. What rests while leaves move
// is drawn once into a cached texture (draw(): the resting spread), so a turning frame shades only
// the moving leaves and the shadow they cast; at a movingScale below 1 it does so offscreen on fewer
// pixels, and one scaled blit fills the canvas.
#include "book_renderer.hpp"

#include <emscripten/em_js.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "book_constants.hpp"
#include "cone_deform.hpp"
#include "embedded_shaders.hpp"
#include "gl_program.hpp"
#include "leaf_placement.hpp"
#include "mesh_resolution.hpp"

// WebGL2's getBufferSubData, which Emscripten's GL library implements but GLES3 headers omit (GLES
// has glMapBufferRange instead, which WebGL lacks). Needed to read transform feedback back.
extern "C" void glGetBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size, void* data);

// texImage2D from a browser image into the texture bound to TEXTURE_2D: the browser copies the
// pixels to the GPU without passing them through the wasm heap. 0: done; 1: the page may not read
// the image (SecurityError: cross-origin without CORS); 2: any other refusal.
EM_JS(int, conecurl_tex_image_from_source, (void* source), {
    try {
        GLctx.texImage2D(0x0DE1, 0, 0x8058, 0x1908, 0x1401, Emval.toValue(source));  // TEXTURE_2D, RGBA8, RGBA, UNSIGNED_BYTE
        return 0;
    } catch (error) {
        return error && error.name === 'SecurityError' ? 1 : 2;
    }
});

namespace conecurl {
namespace {

constexpr char kShaderPrelude[] = "#version 300 es\nprecision highp float;\n";
constexpr double kNormalStepOfHeight = 1e-3;         // the math doc's finite-difference step
constexpr float kShadowStrength = 0.45f;
constexpr float kShadowPenumbra = 0.015f;            // half the shadow's soft edge, a fraction of the page width
constexpr int kShadowDownscale = 2;                  // the mask's edge is soft as drawn
constexpr int kDefaultRows = 48;                     // before the first canvas size is known
const glm::vec3 kLightDirection = glm::normalize(glm::vec3(-0.35f, 0.45f, 1.0f));  // upper left, in front
constexpr std::uint8_t kPaper[4] = {kPaperRed, kPaperGreen, kPaperBlue, 255};

// The whole pixels of a `width` x `height` target that points of the page plane move by from camera
// `from` to camera `to`: the same for all of them when the camera only slid along the plane.
std::array<int, 2> pixelOffset(const glm::mat4& from, const glm::mat4& to, int width, int height) {
    const glm::vec4 a = from * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    const glm::vec4 b = to * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    return {static_cast<int>(std::lround((b.x / b.w - a.x / a.w) * 0.5f * static_cast<float>(width))),
            static_cast<int>(std::lround((b.y / b.w - a.y / a.w) * 0.5f * static_cast<float>(height)))};
}

// Digits of a whole number; std::to_string's snprintf would bring printf's float formatting into the wasm.
std::string decimal(int n) {
    if (n < 0) return "-" + decimal(-n);
    std::string out(1, static_cast<char>('0' + n % 10));
    return n >= 10 ? decimal(n / 10) + out : out;
}

}  // namespace

BookRenderer::BookRenderer(const std::string& canvasTarget, bool antialias) {
    EmscriptenWebGLContextAttributes attributes;
    emscripten_webgl_init_context_attributes(&attributes);
    attributes.majorVersion = 2;
    attributes.minorVersion = 0;
    attributes.alpha = true;
    attributes.premultipliedAlpha = true;
    attributes.antialias = antialias;
    attributes.depth = true;
    context_ = emscripten_webgl_create_context(canvasTarget.c_str(), &attributes);
    if (context_ <= 0) {
        error_ = "WebGL2 is not available on canvas '" + canvasTarget + "'";
        context_ = 0;
        return;
    }
    grid_ = makePageGrid(kDefaultPageWidth, kDefaultPageHeight, 38, kDefaultRows);
    createGpuObjects();
}

BookRenderer::~BookRenderer() {
    if (!context_) return;
    if (makeCurrent()) destroyGpuObjects();
    emscripten_webgl_destroy_context(context_);
}

bool BookRenderer::makeCurrent() {
    return context_ && emscripten_webgl_make_context_current(context_) == EMSCRIPTEN_RESULT_SUCCESS;
}

void BookRenderer::locate(Program& program) {
    static constexpr const char* kNames[kUniformCount] = {
        "uCurl", "uCurlTrig", "uNormalStep", "uPageToWorld", "uViewProjection", "uLightDirection",
        "uFacingTexture", "uAwayTexture", "uFacingUv", "uAwayUv", "uPageSize", "uEye", "uLighting", "uGutter",
        "uLeaf", "uShadowMask", "uViewportInverse", "uPaper", "uShadowStrength", "uPenumbra",
        "uFlatLight", "uCache", "uCacheOffset", "uShowThrough", "uMirrorLight", "uMirroredLight"};
    for (int u = 0; u < kUniformCount; ++u) program.location[u] = glGetUniformLocation(program.id, kNames[u]);
    program.known.fill(false);
}

BookRenderer::Kind BookRenderer::kindOf(const Program& program) const {
    if (&program == &leafProgram_) return Kind::leaf;
    if (&program == &shadowProgram_) return Kind::shadow;
    if (&program == &stackProgram_) return Kind::stack;
    if (&program == &flatProgram_) return Kind::flat;
    return Kind::composite;
}

ProgramSource BookRenderer::sourceOf(Kind kind) const {
    const std::string prelude = kShaderPrelude;
    const std::string leafVertex = std::string(shaders::cone_curl_glsl) + shaders::page_vert;
    const std::string flatVertex = prelude + shaders::cone_curl_glsl + shaders::flat_page_vert;
    ProgramSource source;
    switch (kind) {
        case Kind::leaf:
            source.vertex = prelude + leafVertex;
            source.fragment = prelude + shaders::paper_light_glsl + shaders::page_frag;
            // The drawing program itself is captured, so the readback test checks the very shader that draws.
            source.transformFeedbackVaryings = {"vWorldPosition", "vNormal"};
            break;
        case Kind::shadow:
            source.vertex = prelude + "#define SHADOW_PASS 1\n" + leafVertex;
            source.fragment = prelude + shaders::shadow_frag;
            break;
        case Kind::stack:
            source.vertex = prelude + shaders::stack_vert;
            source.fragment = prelude + shaders::stack_frag;
            break;
        case Kind::flat:
            source.vertex = flatVertex;
            source.fragment = prelude + shaders::paper_light_glsl + shaders::flat_page_frag;
            break;
        case Kind::composite:
            source.vertex = prelude + shaders::composite_vert;
            source.fragment = prelude + shaders::composite_frag;
            break;
    }
    return source;
}

void BookRenderer::start(Program& program) {
    if (program.id || program.pending.program || !error_.empty()) return;
    program.pending = startProgram(sourceOf(kindOf(program)));
}

bool BookRenderer::build(Program& program) {
    if (program.id) return true;
    if (!error_.empty()) return false;
    const Kind kind = kindOf(program);
    start(program);  // unless prepareTurn() or createGpuObjects() asked for it already
    PendingProgram pending = program.pending;
    program = Program{};
    program.id = finishProgram(pending, error_);
    if (!program.id) return false;
    locate(program);
    // What never changes is set once, here: samplers, the light, the paper colour, the shadow's strength.
    const float light[3] = {kLightDirection.x, kLightDirection.y, kLightDirection.z};
    const float paper[3] = {kPaper[0] / 255.0f, kPaper[1] / 255.0f, kPaper[2] / 255.0f};
    glUseProgram(program.id);
    programInUse_ = program.id;
    switch (kind) {
        case Kind::leaf:
            glUniform1i(program.location[uFacingTexture], 0);
            glUniform1i(program.location[uAwayTexture], 1);
            setUniform(program, uLightDirection, light, 3);
            setUniform(program, uPaper, paper, 3);
            break;
        case Kind::flat:
            glUniform1i(program.location[uFacingTexture], 0);
            setUniform(program, uPaper, paper, 3);
            break;
        case Kind::composite:
            glUniform1i(program.location[uCache], 3);
            glUniform1i(program.location[uShadowMask], 2);
            break;
        case Kind::stack:
            setUniform(program, uLightDirection, light, 3);
            setUniform(program, uPaper, paper, 3);
            break;
        case Kind::shadow:
            setUniform(program, uLightDirection, light, 3);
            setUniform(program, uShadowStrength, kShadowStrength);
            setUniform(program, uPenumbra, kShadowPenumbra);
            break;
    }
    return true;
}

bool BookRenderer::prepareTurn() {
    if (!ok() || !makeCurrent()) return true;
    // The composite program also draws the probe of anisotropic filtering, while the page has not asked it.
    Program* const turn[] = {&leafProgram_, options_.shadows ? &shadowProgram_ : nullptr,
                             options_.shadows || canvasSamples_ > 0 || anisotropyUnknown() ? &compositeProgram_ : nullptr};
    // Where the driver compiles beside the page (KHR_parallel_shader_compile), this call asks and a later
    // one checks, once the driver says it is done (a bounded number of asks: a driver that never says so
    // is waited for). Without it the compile happens when its status is first asked (Chromium on
    // SwiftShader: a check one idle task later waited 106-456 ms, against 72-245 ms asked and checked
    // at once), so it is done in this call.
    if (parallelCompile_) {
        bool asked = false;
        for (Program* program : turn) {
            if (!program || program->id || program->pending.program) continue;
            start(*program);
            asked = true;
        }
        if (asked) {
            glFlush();  // on their way to the driver now, not at the end of the task
            turnPolls_ = 0;
            return false;
        }
        if (++turnPolls_ < kMaxTurnPolls) {
            for (Program* program : turn) {
                if (program && program->pending.program && !programCompleted(program->pending)) return false;
            }
        }
    }
    for (Program* program : turn) {
        if (program) build(*program);  // each leaves its program in use (programInUse_ follows), as useProgram would
    }
    settleAnisotropy();
    return true;
}

void BookRenderer::useProgram(Program& program) {
    if (!program.id && !build(program)) return;  // first use: linked now (error_ says why not)
    if (programInUse_ == program.id) return;
    glUseProgram(program.id);
    programInUse_ = program.id;
}

void BookRenderer::setUniform(Program& program, Uniform u, const float* values, int count) {
    const GLint at = program.location[u];
    if (at < 0) return;
    std::array<float, 16>& last = program.value[u];
    const size_t bytes = static_cast<size_t>(count) * sizeof(float);
    if (program.known[u] && std::memcmp(last.data(), values, bytes) == 0) return;
    std::memcpy(last.data(), values, bytes);
    program.known[u] = true;
    switch (count) {
        case 1: glUniform1f(at, values[0]); break;
        case 2: glUniform2fv(at, 1, values); break;
        case 3: glUniform3fv(at, 1, values); break;
        case 4: glUniform4fv(at, 1, values); break;
        case 9: glUniformMatrix3fv(at, 1, GL_FALSE, values); break;
        default: glUniformMatrix4fv(at, 1, GL_FALSE, values); break;
    }
}

void BookRenderer::setBlendEquation(GLenum equation) {
    if (blendEquation_ == equation) return;
    glBlendEquation(equation);
    blendEquation_ = equation;
}

void BookRenderer::bindTexture(int unit, GLuint texture, bool toEdit) {
    // For drawing, a texture already bound to its unit costs no call. To edit (`toEdit`), `unit` is
    // left active, so texture calls that follow (uploads, parameters) act on `texture`.
    if (!toEdit && boundTextures_[unit] == texture) return;
    if (activeUnit_ != unit) {
        glActiveTexture(GL_TEXTURE0 + unit);
        activeUnit_ = unit;
    }
    if (boundTextures_[unit] == texture) return;
    glBindTexture(GL_TEXTURE_2D, texture);
    boundTextures_[unit] = texture;
}

void BookRenderer::createGpuObjects() {
    if (!makeCurrent()) {
        error_ = "could not make the WebGL2 context current";
        return;
    }
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTextureSize_);
    if (emscripten_webgl_enable_extension(context_, "EXT_texture_filter_anisotropic")) {
        glGetFloatv(kMaxTextureMaxAnisotropy, &maxAnisotropy_);
    }
    // Whether it keeps 1-px strokes of a page at rest is found in idle time (prepareTurn), once a page.
    anisotropy_ = pageAnisotropy(false);

    // KHR_parallel_shader_compile: compiles run beside the page, and prepareTurn() can ask whether they are done.
    parallelCompile_ = emscripten_webgl_enable_extension(context_, "KHR_parallel_shader_compile");
    // The resting frame's programs now, so a missing feature fails create(); the turn's on first use. Both
    // are asked for before either is checked, so the driver works on them together.
    start(stackProgram_);
    start(flatProgram_);
    if (!build(stackProgram_) || !build(flatProgram_)) return;
    // Every pass clears to transparent. Blending: the shadow mask's darkest-wins (GL_MAX, which ignores
    // the factors) and the shadow received on the resting pages, which multiplies their colour by the
    // output and keeps their alpha (GL_FUNC_ADD with these factors).
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glBlendFuncSeparate(GL_ZERO, GL_SRC_COLOR, GL_ZERO, GL_ONE);
    blendEquation_ = 0;
    setBlendEquation(GL_MAX);
    glDisable(GL_CULL_FACE);  // one mesh, two sides
    // The canvas's samples: a multisampled drawing buffer cannot be blitted into, so the cache is drawn.
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glGetIntegerv(GL_SAMPLES, &canvasSamples_);

    glGenVertexArrays(1, &vertexArray_);
    glGenBuffers(1, &vertexBuffer_);
    glGenBuffers(1, &indexBuffer_);
    glGenBuffers(1, &captureBuffer_);
    uploadGrid();
    // The stacks' faces share the one vertex array, at locations 1 and 2 (stack.vert), from their own
    // buffer: the leaf program reads only location 0, the stack program only 1 and 2, so drawing the
    // stacks binds no other vertex array. The buffer is filled by updateStacks().
    glGenBuffers(1, &stackBuffer_);
    glBindBuffer(GL_ARRAY_BUFFER, stackBuffer_);
    vec4PairAttributes(1, kStackVertexFloats);
    stackKey_ = StackKey{};
    stackVertexCount_ = 0;

    glGenTextures(1, &paperTexture_);
    boundTextures_.fill(0);
    activeUnit_ = -1;
    bindTexture(0, paperTexture_, true);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, kPaper);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);

    glGenFramebuffers(1, &shadowFramebuffer_);
    glGenTextures(1, &shadowTexture_);
    shadowWidth_ = shadowHeight_ = 0;
    glGenFramebuffers(1, &cacheFramebuffer_);
    glGenTextures(1, &cacheTexture_);
    cacheWidth_ = cacheHeight_ = 0;
    glGenFramebuffers(1, &scaledFramebuffer_);
    glGenTextures(1, &scaledTexture_);
    glGenRenderbuffers(1, &scaledDepth_);
    scaledWidth_ = scaledHeight_ = 0;
    invalidateRestingSpread();
}

void BookRenderer::destroyGpuObjects() {
    for (Program* program : {&leafProgram_, &shadowProgram_, &stackProgram_, &flatProgram_, &compositeProgram_}) {
        abandonProgram(program->pending);  // asked for and never checked
    }
    glDeleteProgram(leafProgram_.id);
    glDeleteProgram(shadowProgram_.id);
    glDeleteProgram(stackProgram_.id);
    glDeleteProgram(flatProgram_.id);
    glDeleteProgram(compositeProgram_.id);
    glDeleteFramebuffers(1, &cacheFramebuffer_);
    glDeleteTextures(1, &cacheTexture_);
    glDeleteFramebuffers(1, &scaledFramebuffer_);
    glDeleteTextures(1, &scaledTexture_);
    glDeleteRenderbuffers(1, &scaledDepth_);
    glDeleteBuffers(1, &stackBuffer_);
    glDeleteVertexArrays(1, &vertexArray_);
    glDeleteBuffers(1, &vertexBuffer_);
    glDeleteBuffers(1, &indexBuffer_);
    glDeleteBuffers(1, &captureBuffer_);
    glDeleteTextures(1, &paperTexture_);
    glDeleteFramebuffers(1, &shadowFramebuffer_);
    glDeleteTextures(1, &shadowTexture_);
    for (const auto& [page, texture] : pageTextures_) glDeleteTextures(1, &texture);
    withoutMipmaps_.clear();
    edgeMarks_.release();
    dropBand();
    forgetGpuObjects();
}

void BookRenderer::forgetGpuObjects() {
    edgeMarks_.forget();
    pageTextures_.clear();
    withoutMipmaps_.clear();
    bufferSize_ = BufferSize{};  // a restored context's buffer is asked for again
    dropBand(false);
    gridKey_ = GridKey{};  // the grid buffer is gone too
    leafProgram_ = Program{};
    shadowProgram_ = Program{};
    stackProgram_ = Program{};
    flatProgram_ = Program{};
    compositeProgram_ = Program{};
    cacheFramebuffer_ = cacheTexture_ = 0;
    cacheWidth_ = cacheHeight_ = 0;
    scaledFramebuffer_ = scaledTexture_ = scaledDepth_ = 0;
    scaledWidth_ = scaledHeight_ = 0;
    invalidateRestingSpread();
    cachedTextures_.fill(0);
    blendEquation_ = 0;
    stackBuffer_ = 0;
    stackVertexCount_ = 0;
    stackBox_ = WorldBox{};
    stackKey_ = StackKey{};
    programInUse_ = 0;
    boundTextures_.fill(0);
    activeUnit_ = -1;
    vertexArray_ = vertexBuffer_ = indexBuffer_ = captureBuffer_ = 0;
    paperTexture_ = shadowFramebuffer_ = shadowTexture_ = 0;
}

void BookRenderer::recreateGpuObjects() {
    error_.clear();
    forgetGpuObjects();  // the old names died with the lost context: forget them without deleting
    createGpuObjects();
}

void BookRenderer::uploadGrid() {
    // The renderer's one vertex array stays bound from here on: draws and captures need no bind.
    glBindVertexArray(vertexArray_);
    glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
    glBufferData(GL_ARRAY_BUFFER, grid_.points.size() * sizeof(float), grid_.points.data(), GL_STATIC_DRAW);
    // aPagePoint is at location 0 in both programs (layout qualifier in page.vert).
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, grid_.indices.size() * sizeof(std::uint32_t), grid_.indices.data(),
                 GL_STATIC_DRAW);
}

void BookRenderer::updateGrid(const Book& book, const Camera& camera, int width, int height) {
    const BookConfig& c = book.config();
    // Zoom in steps of a half: the grid is chosen again on each step, not on every pinch movement.
    const double zoomStep = std::ceil(book.zoom().scale * 2.0) / 2.0;
    const GridKey key{width, height, requestedRows_, c.pageWidth, c.pageHeight, c.display, c.binding, zoomStep};
    if (key == gridKey_) return;  // the choice costs milliseconds: never per frame
    const bool samePage = key.pageWidth == gridKey_.pageWidth && key.pageHeight == gridKey_.pageHeight;
    gridKey_ = key;
    int rows = requestedRows_;
    int columns = 0;
    if (rows <= 0) {
        const float pixelsPerUnit = camera.pixelsPerUnit * static_cast<float>(zoomStep / book.zoom().scale);
        const GridResolution chosen = closedFormGridResolution(c.pageWidth, c.pageHeight, c.schedule,
                                                           pixelsPerUnit, camera.magnification);
        rows = chosen.rows;
        columns = chosen.columns;
        gridErrorPixels_ = chosen.predictedErrorPixels;
    } else {
        gridErrorPixels_ = std::nan("");
        columns = std::max(4, static_cast<int>(std::lround(rows * c.pageWidth / c.pageHeight)));
    }
    // A resize that lands on the same grid for the same page keeps the buffer as it is.
    if (rows == grid_.rows && columns == grid_.columns && samePage) return;
    grid_ = makePageGrid(c.pageWidth, c.pageHeight, columns, rows);
    uploadGrid();
}

std::string BookRenderer::setPageImage(int page, int width, int height, JsHandle source) {
    if (page < 0) return "page index must not be negative";
    if (width <= 0 || height <= 0 || !source) return "page image must have a positive size";
    if (width > maxTextureSize_ || height > maxTextureSize_) {
        return "page image " + decimal(width) + "x" + decimal(height) + " exceeds MAX_TEXTURE_SIZE " +
               decimal(maxTextureSize_);
    }
    if (!makeCurrent()) return "the WebGL2 context is not available";
    if (band_.page == page) dropBand();  // the whole image now: the bands under way are moot
    auto found = findTexture(page);
    GLuint texture = found == pageTextures_.end() ? 0 : found->second;
    if (!texture) glGenTextures(1, &texture);
    bindTexture(0, texture, true);
    const int uploaded = conecurl_tex_image_from_source(static_cast<void*>(source));
    if (uploaded != 0) {
        if (found == pageTextures_.end()) {
            bindTexture(0, paperTexture_);
            glDeleteTextures(1, &texture);
        }
        return uploaded == 1 ? kTaintedSource : "the browser refused to upload the page image";
    }
    if (found == pageTextures_.end()) pageTextures_.emplace_back(page, texture);
    // New pixels in a texture the cached resting spread shows: draw the spread again.
    if (std::find(cachedTextures_.begin(), cachedTextures_.end(), texture) != cachedTextures_.end()) invalidateRestingSpread();
    finishPageTexture(texture);
    return {};
}

void BookRenderer::releasePageImage(int page) {
    if (band_.page == page && makeCurrent()) dropBand();
    auto found = findTexture(page);
    if (found == pageTextures_.end()) return;
    withoutMipmaps_.erase(std::remove(withoutMipmaps_.begin(), withoutMipmaps_.end(), found->second), withoutMipmaps_.end());
    if (makeCurrent()) {
        for (GLuint& bound : boundTextures_) {
            if (bound == found->second) bound = 0;  // a deleted name may come back for another texture
        }
        glDeleteTextures(1, &found->second);
    }
    pageTextures_.erase(found);
}

void BookRenderer::splicePageImages(int at, int removed, int inserted) {
    if (band_.page >= 0 && makeCurrent()) dropBand();  // the JS layer starts that upload over
    std::vector<int> gone;  // the pages held, not every index removed: a million removed costs no more
    for (const auto& entry : pageTextures_) {
        if (entry.first >= at && entry.first < at + removed) gone.push_back(entry.first);
    }
    for (int page : gone) releasePageImage(page);
    for (auto& entry : pageTextures_) {
        if (entry.first >= at + removed) entry.first += inserted - removed;
    }
}

BookRenderer::PageTextures::const_iterator BookRenderer::findTexture(int page) const {
    return std::find_if(pageTextures_.begin(), pageTextures_.end(), [page](const auto& entry) { return entry.first == page; });
}

GLuint BookRenderer::textureFor(int page) const {
    auto found = findTexture(page);
    return found == pageTextures_.end() ? paperTexture_ : found->second;
}

BookRenderer::Camera BookRenderer::toGpu(const BookCamera& c) {
    return Camera{glm::mat4(c.viewProjection), glm::vec3(c.eye), static_cast<float>(c.pixelsPerUnit),
                  static_cast<float>(c.magnification)};
}

BookRenderer::Camera BookRenderer::cameraFor(const Book& book, int width, int height) const {
    // The core's camera, in float for the GPU: pointer input is solved against the same one.
    return toGpu(bookCamera(book, width, height));
}

BookRenderer::Camera BookRenderer::restingCameraFor(const Book& book, int width, int height) const {
    if (book.zoom().scale > 1.0) return cameraFor(book, width, height);
    return toGpu(bookCamera(book.config(), width, height, book.zoom(), 0.0));
}

void BookRenderer::ensureShadowTarget(int width, int height) {
    const int w = std::max(1, width / kShadowDownscale);
    const int h = std::max(1, height / kShadowDownscale);
    if (w == shadowWidth_ && h == shadowHeight_) return;
    shadowWidth_ = w;
    shadowHeight_ = h;
    colorTarget(shadowFramebuffer_, 2, shadowTexture_, w, h, GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

LeafPlacement BookRenderer::setPlacementUniforms(Program& program, const Book& book, const LeafDraw& leaf,
                                                 const Camera& camera) {
    const BookConfig& c = book.config();
    const LeafPlacement placement = placeLeaf(c.binding, leaf.mirrored, c.pageHeight, leaf.flippedY);
    const glm::mat4 pageToWorld(placement.pageToWorld);
    const CurlParams& curl = leaf.curl;
    // The trigonometry of theta and rho is the same for every vertex: once per leaf, here, in double.
    const float curlValues[3] = {static_cast<float>(curl.theta), static_cast<float>(curl.apexY), static_cast<float>(curl.rho)};
    const float trig[4] = {static_cast<float>(std::sin(curl.theta)), static_cast<float>(std::cos(curl.theta)),
                           static_cast<float>(std::sin(curl.rho)), static_cast<float>(std::cos(curl.rho))};
    // A resting leaf lies flat: the shader skips the cone (the same points: theta is 90 degrees there).
    const float flags[2] = {leaf.resting ? 1.0f : 0.0f, 0.0f};
    setUniform(program, uLeaf, flags, 2);
    setUniform(program, uCurl, curlValues, 3);
    setUniform(program, uCurlTrig, trig, 4);
    setUniform(program, uNormalStep, static_cast<float>(kNormalStepOfHeight * c.pageHeight));
    setUniform(program, uPageToWorld, glm::value_ptr(pageToWorld), 16);
    setUniform(program, uViewProjection, glm::value_ptr(camera.viewProjection), 16);
    return placement;
}

void BookRenderer::setSurfaceUniforms(const Book& book, const LeafDraw& leaf, const LeafPlacement& placement,
                                      const Camera& camera) {
    Program& p = leafProgram_;
    const BookConfig& c = book.config();
    const glm::mat3 facingUv(placement.facingUv);
    const glm::mat3 awayUv(placement.awayUv);
    const float pageSize[2] = {static_cast<float>(c.pageWidth), static_cast<float>(c.pageHeight)};
    setUniform(p, uFacingUv, glm::value_ptr(facingUv), 9);
    setUniform(p, uAwayUv, glm::value_ptr(awayUv), 9);
    setUniform(p, uPageSize, pageSize, 2);
    setUniform(p, uEye, glm::value_ptr(camera.eye), 3);
    setUniform(p, uLighting, options_.lighting ? 1.0f : 0.0f);
    // The gutter shading of paper, or the hinge groove of a hard board (page.frag).
    setUniform(p, uGutter, options_.gutter ? (leaf.hard ? 2.0f : 1.0f) : 0.0f);
    const int facingPage = placement.facingIsBackPage ? leaf.backPage : leaf.frontPage;
    const int awayPage = placement.facingIsBackPage ? leaf.frontPage : leaf.backPage;
    // A blank side of soft paper (single display's back) shows the other side's print through it and,
    // in single display, takes the light mirrored across the spine (page.frag says why). A board's
    // blank side stays board.
    const bool paper = !leaf.hard;
    const bool single = c.display == Display::Single;
    const float amount = paper ? static_cast<float>(options_.showThrough) : 0.0f;
    const float showThrough[2] = {facingPage == kNoPage ? amount : 0.0f, awayPage == kNoPage ? amount : 0.0f};
    const float mirror[2] = {paper && single && facingPage == kNoPage ? 1.0f : 0.0f,
                             paper && single && awayPage == kNoPage ? 1.0f : 0.0f};
    glm::vec3 mirrored = kLightDirection;
    if (c.binding == Binding::Top) mirrored.y = -mirrored.y; else mirrored.x = -mirrored.x;
    setUniform(p, uShowThrough, showThrough, 2);
    setUniform(p, uMirrorLight, mirror, 2);
    setUniform(p, uMirroredLight, glm::value_ptr(mirrored), 3);
    bindTexture(0, textureFor(facingPage));
    bindTexture(1, textureFor(awayPage));
}

void BookRenderer::drawLeaf(const Book& book, const LeafDraw& leaf, const Camera& camera) {
    setSurfaceUniforms(book, leaf, setPlacementUniforms(leafProgram_, book, leaf, camera), camera);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(grid_.indices.size()), GL_UNSIGNED_INT, nullptr);
}

void BookRenderer::drawFlatPage(const Book& book, const LeafDraw& leaf, const Camera& camera) {
    Program& p = flatProgram_;
    const BookConfig& c = book.config();
    const LeafPlacement placement = setPlacementUniforms(p, book, leaf, camera);
    // page.frag's choice of side and its light, made once: a flat leaf's normal is the same at every
    // point, and the eye is above the page plane, so one point (the page's middle) decides.
    const glm::mat4 pageToWorld(placement.pageToWorld);
    const float sinRho = static_cast<float>(std::sin(leaf.curl.rho));
    const float cosRho = static_cast<float>(std::cos(leaf.curl.rho));
    const glm::vec3 normal = glm::normalize(glm::mat3(pageToWorld) * glm::vec3(-sinRho, 0.0f, cosRho));
    const float midX = static_cast<float>(c.pageWidth / 2.0);
    const glm::vec4 middle = pageToWorld * glm::vec4(midX * cosRho, static_cast<float>(c.pageHeight / 2.0), midX * sinRho, 1.0f);
    const bool facing = glm::dot(normal, camera.eye - glm::vec3(middle)) >= 0.0f;
    auto diffuse = [](const glm::vec3& n) { return 0.35f + 0.65f * std::max(glm::dot(n, kLightDirection), 0.0f); };
    const float light = options_.lighting ? diffuse(facing ? normal : -normal) / diffuse(glm::vec3(0.0f, 0.0f, 1.0f)) : 1.0f;
    const glm::mat3 uv(facing ? placement.facingUv : placement.awayUv);
    const bool backSeen = facing == placement.facingIsBackPage;
    const float pageSize[2] = {static_cast<float>(c.pageWidth), static_cast<float>(c.pageHeight)};
    setUniform(p, uFlatLight, light);
    setUniform(p, uFacingUv, glm::value_ptr(uv), 9);
    setUniform(p, uPageSize, pageSize, 2);
    setUniform(p, uGutter, options_.gutter ? (leaf.hard ? 2.0f : 1.0f) : 0.0f);
    bindTexture(0, textureFor(backSeen ? leaf.backPage : leaf.frontPage));
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(grid_.indices.size()), GL_UNSIGNED_INT, nullptr);
}

void BookRenderer::updateStacks(const Book& book) {
    const BookConfig& c = book.config();
    const StackKey key{stackLeaves(book), c.leafThickness, c.pageWidth, c.pageHeight, c.display, c.binding};
    if (key == stackKey_) return;  // a turn changes the leaves on a side twice: as it lifts and as it lands
    stackKey_ = key;
    ++stackGeneration_;
    const std::vector<float> mesh = stackMesh(c, bookStacks(c, key.leaves, key.thickness));
    stackVertexCount_ = static_cast<int>(mesh.size()) / kStackVertexFloats;
    stackBox_ = WorldBox::of(mesh, kStackVertexFloats);
    if (stackVertexCount_ == 0) return;
    glBindBuffer(GL_ARRAY_BUFFER, stackBuffer_);
    glBufferData(GL_ARRAY_BUFFER, mesh.size() * sizeof(float), mesh.data(), GL_STATIC_DRAW);
}

void BookRenderer::drawStacks(const Camera& camera) {
    if (stackVertexCount_ == 0) return;
    // Below the table plane and outside the pages: drawn first, everything else lies over them.
    useProgram(stackProgram_);
    setUniform(stackProgram_, uViewProjection, glm::value_ptr(camera.viewProjection), 16);
    setUniform(stackProgram_, uLighting, options_.lighting ? 1.0f : 0.0f);
    glDrawArrays(GL_TRIANGLES, 0, stackVertexCount_);
}

void BookRenderer::drawRestingSpread(const Book& book, const BookFrame& frame, const Camera& camera) {
    drawStacks(camera);
    // Marks on the page block (tabs, ticks) are drawn here, with the stacks: they rest with them.
    edgeMarks_.draw(book, camera.viewProjection, programInUse_);
    useProgram(flatProgram_);
    for (int i = 0; i < frame.count; ++i) {
        if (frame.leaves[i].resting) drawFlatPage(book, frame.leaves[i], camera);
    }
}

BookRenderer::RestingKey BookRenderer::restingKey(const Book& book, const BookFrame& frame, const Camera& camera,
                                                  int width, int height) const {
    RestingKey key{};
    size_t at = 0;
    auto put = [&key, &at](double value) { key[at++] = value; };
    const float* viewProjection = glm::value_ptr(camera.viewProjection);
    for (int i = 0; i < 16; ++i) put(viewProjection[i]);  // zoom, pan, layout, size: all move the camera
    put(width);
    put(height);
    put(options_.lighting);
    put(options_.gutter);
    put(stackGeneration_);
    put(grid_.rows * 4096.0 + grid_.columns);
    put(book.config().pageWidth);
    put(book.config().pageHeight);
    for (int i = 0; i < frame.count; ++i) {
        const LeafDraw& leaf = frame.leaves[i];
        if (!leaf.resting) continue;
        put(leaf.leaf);
        put(leaf.frontPage);
        put(leaf.backPage);
        put(textureFor(leaf.frontPage));  // a page that arrives or goes changes the texture drawn
        put(textureFor(leaf.backPage));
        put(leaf.curl.rho);
        put(leaf.mirrored);
        put(leaf.flippedY);
        put(leaf.hard);
        put(1.0);  // this slot is a leaf
    }
    return key;
}

void BookRenderer::colorTarget(GLuint framebuffer, int unit, GLuint texture, int width, int height, GLint filter) {
    bindTexture(unit, texture, true);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
}

void BookRenderer::ensureCacheTarget(int width, int height) {
    if (width == cacheWidth_ && height == cacheHeight_) return;
    cacheWidth_ = width;
    cacheHeight_ = height;
    colorTarget(cacheFramebuffer_, 3, cacheTexture_, width, height, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

WorldBox BookRenderer::restingBox(const Book& book, const BookFrame& frame) const {
    const BookConfig& c = book.config();
    WorldBox box = stackBox_;
    box.add(edgeMarks_.worldBox());
    for (int i = 0; i < frame.count; ++i) {
        const LeafDraw& leaf = frame.leaves[i];
        if (!leaf.resting) continue;
        const glm::mat4 pageToWorld(placeLeaf(c.binding, leaf.mirrored, c.pageHeight, leaf.flippedY).pageToWorld);
        const float x = static_cast<float>(c.pageWidth * std::cos(leaf.curl.rho));  // rho is 0 or pi at rest
        const float z = static_cast<float>(c.pageWidth * std::sin(leaf.curl.rho));
        for (const float y : {0.0f, static_cast<float>(c.pageHeight)}) {
            box.add(glm::vec3(pageToWorld * glm::vec4(0.0f, y, 0.0f, 1.0f)));
            box.add(glm::vec3(pageToWorld * glm::vec4(x, y, z, 1.0f)));
        }
    }
    return box;
}

void BookRenderer::composeRestingSpread(GLuint target, bool shadows, int width, int height, std::array<int, 2> offset) {
    // On a multisampled canvas one triangle covers it all (the cache is clear outside what rests),
    // over the depth cleared alone: SwiftShader left such a canvas blank where a colour clear came
    // before the triangle. Elsewhere only the pixels that hold what rests, the rest cleared.
    const bool multisampled = target == 0 && canvasSamples_ > 0;
    glClear((multisampled ? 0 : GL_COLOR_BUFFER_BIT) | GL_DEPTH_BUFFER_BIT);
    const auto [x, y, w, h] = restingRect_;
    if (!multisampled && (w == 0 || h == 0)) return;
    const auto [dx, dy] = offset;
    if (!shadows && !multisampled) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, cacheFramebuffer_);
        glBlitFramebuffer(x, y, x + w, y + h, x + dx, y + dy, x + w + dx, y + h + dy, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, target);  // readPixels reads the canvas
        return;
    }
    // The shadow darkens what rests as it is laid down: one triangle, one pass, no blending. (A
    // multisampled drawing buffer takes no blit either: the triangle copies each pixel's texel.)
    if (!multisampled) {
        glEnable(GL_SCISSOR_TEST);
        glScissor(x + dx, y + dy, w, h);
    }
    if (shadows) bindTexture(2, shadowTexture_);
    drawComposite(cacheTexture_, width, height, shadows, offset);
    glDisable(GL_SCISSOR_TEST);
}

void BookRenderer::drawComposite(GLuint texture, int width, int height, bool shadowed, std::array<int, 2> offset) {
    useProgram(compositeProgram_);
    bindTexture(3, texture);
    const float viewportInverse[2] = {1.0f / static_cast<float>(width), 1.0f / static_cast<float>(height)};
    const float cacheOffset[2] = {static_cast<float>(offset[0]), static_cast<float>(offset[1])};
    setUniform(compositeProgram_, uViewportInverse, viewportInverse, 2);
    setUniform(compositeProgram_, uCacheOffset, cacheOffset, 2);
    setUniform(compositeProgram_, uShadowStrength, shadowed ? 1.0f : 0.0f);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void BookRenderer::ensureScaledTarget(int width, int height) {
    if (width == scaledWidth_ && height == scaledHeight_) return;
    scaledWidth_ = width;
    scaledHeight_ = height;
    // Linear: scaled up, each canvas pixel blends the four texels about it.
    colorTarget(scaledFramebuffer_, 3, scaledTexture_, width, height, GL_LINEAR);
    glBindRenderbuffer(GL_RENDERBUFFER, scaledDepth_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, scaledDepth_);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void BookRenderer::presentScaledFrame(int width, int height) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    if (canvasSamples_ > 0) {
        glDisable(GL_DEPTH_TEST);
        drawComposite(scaledTexture_, width, height, false);
        return;
    }
    // Cleared first, as in draw(): the browser's lazy clear of the canvas would wipe a blit made before.
    glClear(GL_COLOR_BUFFER_BIT);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, scaledFramebuffer_);
    glBlitFramebuffer(0, 0, scaledWidth_, scaledHeight_, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

void BookRenderer::draw(const Book& book, const BookFrame& frame) {
    if (!ok() || !makeCurrent()) return;
    int moving = 0;
    bool curled = false;  // a curled leaf may hide part of itself; a hard leaf turns flat
    for (int i = 0; i < frame.count; ++i) {
        if (frame.leaves[i].resting) continue;
        ++moving;
        curled |= !frame.leaves[i].hard;
    }
    if (moving > 0) finishFirstView();  // a moving leaf shows its pages at a slant: their mipmaps first
    int width = 0;
    int height = 0;
    drawingBufferSize(width, height);
    if (width <= 0 || height <= 0) return;
    drawingWidth_ = width;
    drawingHeight_ = height;
    const Camera camera = cameraFor(book, width, height);
    updateGrid(book, camera, width, height);
    updateStacks(book);
    ++framesDrawn_;

    glDisable(GL_DEPTH_TEST);
    if (moving == 0) {
        // A resting book: the stacks, the flat pages over them. Nothing is depth-tested.
        glViewport(0, 0, width, height);
        glClear(GL_COLOR_BUFFER_BIT);
        drawRestingSpread(book, frame, camera);
        lastViewProjection_ = restingCameraFor(book, width, height).viewProjection;
        lastFrameScale_ = 1.0;
        return;
    }
    // Where the moving frame is drawn: the canvas, or at movingScale offscreen, scaled up at the end.
    // The camera is the canvas's: the offscreen target is the canvas, stretched.
    const int targetWidth = std::max(1, static_cast<int>(std::lround(width * options_.movingScale)));
    const int targetHeight = std::max(1, static_cast<int>(std::lround(height * options_.movingScale)));
    const bool scaled = targetWidth < width || targetHeight < height;
    if (scaled) ensureScaledTarget(targetWidth, targetHeight);
    const GLuint target = scaled ? scaledFramebuffer_ : 0;
    lastFrameScale_ = static_cast<double>(targetWidth) / width;
    const bool shadows = options_.shadows;
    const GLsizei indexCount = static_cast<GLsizei>(grid_.indices.size());
    if (shadows) {
        // Shadow mask: every lifted leaf flattened along the light, the darkest wins where they overlap.
        ensureShadowTarget(targetWidth, targetHeight);
        glBindFramebuffer(GL_FRAMEBUFFER, shadowFramebuffer_);
        glViewport(0, 0, shadowWidth_, shadowHeight_);
        glClear(GL_COLOR_BUFFER_BIT);
        glEnable(GL_BLEND);
        setBlendEquation(GL_MAX);
        useProgram(shadowProgram_);
        const float pageSize[2] = {static_cast<float>(book.config().pageWidth), static_cast<float>(book.config().pageHeight)};
        setUniform(shadowProgram_, uPageSize, pageSize, 2);
        for (int i = 0; i < frame.count; ++i) {
            if (frame.leaves[i].resting) continue;
            setPlacementUniforms(shadowProgram_, book, frame.leaves[i], camera);
            glDrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, nullptr);
        }
        glDisable(GL_BLEND);
    }
    ensureCacheTarget(targetWidth, targetHeight);  // before the target is bound: it binds and unbinds the cache's
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, targetWidth, targetHeight);

    // What rests: drawn into the target once, as a resting book draws it, and copied into the cache;
    // every frame lays the cache down (the shadow on it), until what rests changes (restingKey). It is
    // cached through the unshifted camera, and laid down where this frame's shift puts it.
    const Camera still = restingCameraFor(book, width, height);
    const std::array<int, 2> offset = pixelOffset(still.viewProjection, camera.viewProjection, targetWidth, targetHeight);
    const RestingKey key = restingKey(book, frame, still, targetWidth, targetHeight);
    // The depth, for the moving leaves below. Cleared first: a browser clears a composited canvas
    // lazily at the frame's first clear or draw, which would wipe a blit made before it.
    glDepthMask(GL_TRUE);
    bool laid = false;  // what rests is on the target already, as it is to be shown
    if (key != restingKey_) {
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        drawRestingSpread(book, frame, still);
        ++restingSpreadDraws_;
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, cacheFramebuffer_);
        glBlitFramebuffer(0, 0, targetWidth, targetHeight, 0, 0, targetWidth, targetHeight, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_FRAMEBUFFER, target);
        // Two pixels about it: the edges' antialiasing and rounding.
        restingRect_ = pixelRect(restingBox(book, frame), still.viewProjection, targetWidth, targetHeight, 2);
        // While the unshifted camera moves (a change of size) every frame draws the spread anew: it is
        // kept only once the camera holds still for a frame.
        if (still.viewProjection != lastViewProjection_) {
            invalidateRestingSpread();
        } else {
            restingKey_ = key;
        }
        cachedTextures_.fill(0);
        for (int i = 0, n = 0; i < frame.count; ++i) {
            if (!frame.leaves[i].resting) continue;
            cachedTextures_[n++] = textureFor(frame.leaves[i].frontPage);
            cachedTextures_[n++] = textureFor(frame.leaves[i].backPage);
        }
        laid = !shadows && offset == std::array<int, 2>{0, 0};  // else laid down again below: darkened, or moved
    }
    if (!laid) composeRestingSpread(target, shadows, targetWidth, targetHeight, offset);
    lastViewProjection_ = still.viewProjection;

    // The moving leaves, over everything that rests (they lie above the page plane, nearer the eye).
    // Depth is tested only among them: where leaves overlap each other, or a curl over its own leaf.
    if (moving > 1 || curled) glEnable(GL_DEPTH_TEST);
    useProgram(leafProgram_);
    for (int i = 0; i < frame.count; ++i) {
        if (!frame.leaves[i].resting) drawLeaf(book, frame.leaves[i], camera);
    }
    if (scaled) presentScaledFrame(width, height);
}

RgbaImage BookRenderer::readPixels() {
    RgbaImage image;
    if (!ok() || !makeCurrent()) return image;
    emscripten_webgl_get_drawing_buffer_size(context_, &image.width, &image.height);
    const size_t rowBytes = static_cast<size_t>(image.width) * 4;
    image.pixels.resize(rowBytes * image.height);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
    // GL's rows run bottom to top; flip to the top-down order of ImageData and PNG.
    std::vector<std::uint8_t> row(rowBytes);
    for (int y = 0; y < image.height / 2; ++y) {
        std::uint8_t* a = image.pixels.data() + y * rowBytes;
        std::uint8_t* b = image.pixels.data() + (image.height - 1 - y) * rowBytes;
        std::memcpy(row.data(), a, rowBytes);
        std::memcpy(a, b, rowBytes);
        std::memcpy(b, row.data(), rowBytes);
    }
    return image;
}

std::vector<float> BookRenderer::captureLeaf(const Book& book, int drawIndex) {
    std::vector<float> out;
    const BookFrame frame = book.frame();
    if (!ok() || !makeCurrent() || drawIndex < 0 || drawIndex >= frame.count) return out;
    const int count = grid_.vertexCount();
    out.resize(static_cast<size_t>(count) * 6);
    const GLsizeiptr bytes = static_cast<GLsizeiptr>(out.size() * sizeof(float));
    glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, captureBuffer_);
    glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, bytes, nullptr, GL_STREAM_READ);
    glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, 0);

    useProgram(leafProgram_);
    Camera camera = cameraFor(book, std::max(1, drawingWidth_), std::max(1, drawingHeight_));
    setPlacementUniforms(leafProgram_, book, frame.leaves[drawIndex], camera);  // positions and normals only
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, captureBuffer_);
    glEnable(GL_RASTERIZER_DISCARD);
    glBeginTransformFeedback(GL_POINTS);
    glDrawArrays(GL_POINTS, 0, count);
    glEndTransformFeedback();
    glDisable(GL_RASTERIZER_DISCARD);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
    glBindBuffer(GL_COPY_READ_BUFFER, captureBuffer_);
    glGetBufferSubData(GL_COPY_READ_BUFFER, 0, bytes, out.data());
    glBindBuffer(GL_COPY_READ_BUFFER, 0);
    return out;
}

}  // namespace conecurl
