// WebGL2 drawing of a book frame. Per frame only uniforms change; the page grid is a static buffer
// rebuilt only when the canvas size calls for a different resolution.
#include "book_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "cone_deform.hpp"
#include "embedded_shaders.hpp"
#include "gl_program.hpp"
#include "leaf_placement.hpp"
#include "mesh_resolution.hpp"

// WebGL2's getBufferSubData, which Emscripten's GL library implements but GLES3 headers omit (GLES
// has glMapBufferRange instead, which WebGL lacks). Needed to read transform feedback back.
extern "C" void glGetBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size, void* data);

namespace conecurl {
namespace {

constexpr char kShaderPrelude[] = "#version 300 es\nprecision highp float;\n";
constexpr GLenum kTextureMaxAnisotropy = 0x84FE;     // EXT_texture_filter_anisotropic
constexpr GLenum kMaxTextureMaxAnisotropy = 0x84FF;
constexpr double kNormalStepOfHeight = 1e-3;         // the math doc's finite-difference step
constexpr float kShadowStrength = 0.45f;
constexpr int kShadowDownscale = 2;                  // the mask is blurred anyway
constexpr int kDefaultRows = 48;                     // before the first canvas size is known
const glm::vec3 kLightDirection = glm::normalize(glm::vec3(-0.35f, 0.45f, 1.0f));  // upper left, in front
constexpr std::uint8_t kPaper[4] = {250, 247, 240, 255};

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
    grid_ = makePageGrid(0.8, 1.0, 38, kDefaultRows);
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

BookRenderer::Uniforms BookRenderer::locate(GLuint program) {
    Uniforms u;
    auto at = [program](const char* name) { return glGetUniformLocation(program, name); };
    u.curl = at("uCurl");
    u.normalStep = at("uNormalStep");
    u.pageToWorld = at("uPageToWorld");
    u.viewProjection = at("uViewProjection");
    u.lightDirection = at("uLightDirection");
    u.facingTexture = at("uFacingTexture");
    u.awayTexture = at("uAwayTexture");
    u.facingUv = at("uFacingUv");
    u.awayUv = at("uAwayUv");
    u.pageSize = at("uPageSize");
    u.eye = at("uEye");
    u.lighting = at("uLighting");
    u.gutter = at("uGutter");
    u.shadow = at("uShadow");
    u.shadowMask = at("uShadowMask");
    u.shadowTexel = at("uShadowTexel");
    u.viewportInverse = at("uViewportInverse");
    u.paper = at("uPaper");
    u.shadowStrength = at("uShadowStrength");
    u.pageWidth = at("uPageWidth");
    return u;
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

    const std::string vertex = std::string(shaders::cone_curl_glsl) + shaders::page_vert;
    ProgramSource leaf;
    leaf.vertex = kShaderPrelude + vertex;
    leaf.fragment = std::string(kShaderPrelude) + shaders::page_frag;
    // The drawing program itself is captured, so the readback test checks the very shader that draws.
    leaf.transformFeedbackVaryings = {"vWorldPosition", "vNormal"};
    leafProgram_ = buildProgram(leaf, error_);
    if (!leafProgram_) return;
    ProgramSource shadow;
    shadow.vertex = std::string(kShaderPrelude) + "#define SHADOW_PASS 1\n" + vertex;
    shadow.fragment = std::string(kShaderPrelude) + shaders::shadow_frag;
    shadowProgram_ = buildProgram(shadow, error_);
    if (!shadowProgram_) return;
    leafUniforms_ = locate(leafProgram_);
    shadowUniforms_ = locate(shadowProgram_);

    glGenVertexArrays(1, &vertexArray_);
    glGenBuffers(1, &vertexBuffer_);
    glGenBuffers(1, &indexBuffer_);
    glGenBuffers(1, &captureBuffer_);
    uploadGrid();

    glGenTextures(1, &paperTexture_);
    glBindTexture(GL_TEXTURE_2D, paperTexture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, kPaper);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);

    glGenFramebuffers(1, &shadowFramebuffer_);
    glGenTextures(1, &shadowTexture_);
    shadowWidth_ = shadowHeight_ = 0;
}

void BookRenderer::destroyGpuObjects() {
    glDeleteProgram(leafProgram_);
    glDeleteProgram(shadowProgram_);
    glDeleteVertexArrays(1, &vertexArray_);
    glDeleteBuffers(1, &vertexBuffer_);
    glDeleteBuffers(1, &indexBuffer_);
    glDeleteBuffers(1, &captureBuffer_);
    glDeleteTextures(1, &paperTexture_);
    glDeleteFramebuffers(1, &shadowFramebuffer_);
    glDeleteTextures(1, &shadowTexture_);
    for (const auto& [page, texture] : pageTextures_) glDeleteTextures(1, &texture);
    pageTextures_.clear();
    gridKey_ = GridKey{};  // the grid buffer is gone too
    leafProgram_ = shadowProgram_ = vertexArray_ = vertexBuffer_ = indexBuffer_ = captureBuffer_ = 0;
    paperTexture_ = shadowFramebuffer_ = shadowTexture_ = 0;
}

void BookRenderer::recreateGpuObjects() {
    error_.clear();
    // The old names died with the lost context; forget them without deleting.
    pageTextures_.clear();
    gridKey_ = GridKey{};  // the grid buffer is gone too
    leafProgram_ = shadowProgram_ = vertexArray_ = vertexBuffer_ = indexBuffer_ = captureBuffer_ = 0;
    paperTexture_ = shadowFramebuffer_ = shadowTexture_ = 0;
    createGpuObjects();
}

void BookRenderer::uploadGrid() {
    glBindVertexArray(vertexArray_);
    glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
    glBufferData(GL_ARRAY_BUFFER, grid_.points.size() * sizeof(float), grid_.points.data(), GL_STATIC_DRAW);
    // aPagePoint is at location 0 in both programs (layout qualifier in page.vert).
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, grid_.indices.size() * sizeof(std::uint32_t), grid_.indices.data(),
                 GL_STATIC_DRAW);
    glBindVertexArray(0);
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
        const GridResolution chosen = chooseGridResolution(c.pageWidth, c.pageHeight, c.schedule,
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

std::string BookRenderer::setPageImage(int page, int width, int height, const std::uint8_t* rgba) {
    if (page < 0) return "page index must not be negative";
    if (width <= 0 || height <= 0 || !rgba) return "page image must have a positive size";
    if (width > maxTextureSize_ || height > maxTextureSize_) {
        return "page image " + decimal(width) + "x" + decimal(height) + " exceeds MAX_TEXTURE_SIZE " +
               decimal(maxTextureSize_);
    }
    if (!makeCurrent()) return "the WebGL2 context is not available";
    GLuint& texture = pageTextures_[page];
    if (!texture) glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    // Small text on a tilted page stays legible with anisotropic filtering, where the GPU has it.
    if (maxAnisotropy_ > 1.0f) glTexParameterf(GL_TEXTURE_2D, kTextureMaxAnisotropy, std::min(8.0f, maxAnisotropy_));
    return {};
}

void BookRenderer::releasePageImage(int page) {
    auto found = pageTextures_.find(page);
    if (found == pageTextures_.end()) return;
    if (makeCurrent()) glDeleteTextures(1, &found->second);
    pageTextures_.erase(found);
}

GLuint BookRenderer::textureFor(int page) const {
    auto found = pageTextures_.find(page);
    return found == pageTextures_.end() ? paperTexture_ : found->second;
}

BookRenderer::Camera BookRenderer::cameraFor(const Book& book, int width, int height) const {
    // The core's camera, in float for the GPU: pointer input is solved against the same one.
    const BookCamera c = bookCamera(book.config(), width, height, book.zoom());
    return Camera{glm::mat4(c.viewProjection), glm::vec3(c.eye), static_cast<float>(c.pixelsPerUnit),
                  static_cast<float>(c.magnification)};
}

void BookRenderer::ensureShadowTarget(int width, int height) {
    const int w = std::max(1, width / kShadowDownscale);
    const int h = std::max(1, height / kShadowDownscale);
    if (w == shadowWidth_ && h == shadowHeight_) return;
    shadowWidth_ = w;
    shadowHeight_ = h;
    glBindTexture(GL_TEXTURE_2D, shadowTexture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindFramebuffer(GL_FRAMEBUFFER, shadowFramebuffer_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, shadowTexture_, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

LeafPlacement BookRenderer::setPlacementUniforms(const Uniforms& u, const Book& book, const LeafDraw& leaf,
                                                 const Camera& camera) {
    const BookConfig& c = book.config();
    const LeafPlacement placement = placeLeaf(c.binding, leaf.mirrored, c.pageHeight, leaf.flippedY);
    const glm::mat4 pageToWorld(placement.pageToWorld);
    glUniform3f(u.curl, static_cast<float>(leaf.curl.theta), static_cast<float>(leaf.curl.apexY),
                static_cast<float>(leaf.curl.rho));
    glUniform1f(u.normalStep, static_cast<float>(kNormalStepOfHeight * c.pageHeight));
    glUniformMatrix4fv(u.pageToWorld, 1, GL_FALSE, glm::value_ptr(pageToWorld));
    glUniformMatrix4fv(u.viewProjection, 1, GL_FALSE, glm::value_ptr(camera.viewProjection));
    glUniform3f(u.lightDirection, kLightDirection.x, kLightDirection.y, kLightDirection.z);
    return placement;
}

void BookRenderer::setSurfaceUniforms(const Book& book, const LeafDraw& leaf, const LeafPlacement& placement,
                                      const Camera& camera) {
    const Uniforms& u = leafUniforms_;
    const BookConfig& c = book.config();
    const glm::mat3 facingUv(placement.facingUv);
    const glm::mat3 awayUv(placement.awayUv);
    glUniformMatrix3fv(u.facingUv, 1, GL_FALSE, glm::value_ptr(facingUv));
    glUniformMatrix3fv(u.awayUv, 1, GL_FALSE, glm::value_ptr(awayUv));
    glUniform2f(u.pageSize, static_cast<float>(c.pageWidth), static_cast<float>(c.pageHeight));
    glUniform3f(u.eye, camera.eye.x, camera.eye.y, camera.eye.z);
    glUniform1f(u.lighting, options_.lighting ? 1.0f : 0.0f);
    glUniform1f(u.gutter, options_.gutter ? 1.0f : 0.0f);
    glUniform3f(u.paper, kPaper[0] / 255.0f, kPaper[1] / 255.0f, kPaper[2] / 255.0f);
    const int facingPage = placement.facingIsBackPage ? leaf.backPage : leaf.frontPage;
    const int awayPage = placement.facingIsBackPage ? leaf.frontPage : leaf.backPage;
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, textureFor(facingPage));
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, textureFor(awayPage));
    glUniform1i(u.facingTexture, 0);
    glUniform1i(u.awayTexture, 1);
    glUniform1i(u.shadowMask, 2);
}

void BookRenderer::drawLeaf(const Book& book, const LeafDraw& leaf, const Camera& camera, bool receiveShadow) {
    setSurfaceUniforms(book, leaf, setPlacementUniforms(leafUniforms_, book, leaf, camera), camera);
    glUniform1f(leafUniforms_.shadow, receiveShadow ? 1.0f : 0.0f);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(grid_.indices.size()), GL_UNSIGNED_INT, nullptr);
}

void BookRenderer::draw(const Book& book) {
    if (!ok() || !makeCurrent()) return;
    int width = 0;
    int height = 0;
    emscripten_webgl_get_drawing_buffer_size(context_, &width, &height);
    if (width <= 0 || height <= 0) return;
    drawingWidth_ = width;
    drawingHeight_ = height;
    const Camera camera = cameraFor(book, width, height);
    updateGrid(book, camera, width, height);
    const BookFrame frame = book.frame();
    ++framesDrawn_;

    bool anyLifted = false;
    for (int i = 0; i < frame.count; ++i) anyLifted |= !frame.leaves[i].resting;
    const bool shadows = options_.shadows && anyLifted;

    glBindVertexArray(vertexArray_);
    glDisable(GL_CULL_FACE);  // one mesh, two sides
    if (shadows) {
        // Shadow mask: every lifted leaf flattened along the light, the darkest wins where they overlap.
        ensureShadowTarget(width, height);
        glBindFramebuffer(GL_FRAMEBUFFER, shadowFramebuffer_);
        glViewport(0, 0, shadowWidth_, shadowHeight_);
        glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        glDisable(GL_DEPTH_TEST);
        glEnable(GL_BLEND);
        glBlendEquation(GL_MAX);
        glUseProgram(shadowProgram_);
        glUniform1f(shadowUniforms_.shadowStrength, kShadowStrength);
        glUniform1f(shadowUniforms_.pageWidth, static_cast<float>(book.config().pageWidth));
        for (int i = 0; i < frame.count; ++i) {
            if (frame.leaves[i].resting) continue;
            setPlacementUniforms(shadowUniforms_, book, frame.leaves[i], camera);
            glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(grid_.indices.size()), GL_UNSIGNED_INT, nullptr);
        }
        glDisable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }

    glViewport(0, 0, width, height);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(leafProgram_);
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_2D, shadows ? shadowTexture_ : paperTexture_);
    glUniform2f(leafUniforms_.shadowTexel, 1.0f / std::max(1, shadowWidth_), 1.0f / std::max(1, shadowHeight_));
    glUniform2f(leafUniforms_.viewportInverse, 1.0f / width, 1.0f / height);
    // Resting pages lie flat under everything that moves: drawn first, writing no depth, so a leaf
    // settling onto them never fights them for the same depth.
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    for (int i = 0; i < frame.count; ++i) {
        if (frame.leaves[i].resting) drawLeaf(book, frame.leaves[i], camera, shadows);
    }
    // Leaves in flight: the depth buffer sorts them against each other and against their own curl.
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    for (int i = 0; i < frame.count; ++i) {
        if (!frame.leaves[i].resting) drawLeaf(book, frame.leaves[i], camera, false);
    }
    glBindVertexArray(0);
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

    glUseProgram(leafProgram_);
    Camera camera = cameraFor(book, std::max(1, drawingWidth_), std::max(1, drawingHeight_));
    setPlacementUniforms(leafUniforms_, book, frame.leaves[drawIndex], camera);  // positions and normals only
    glBindVertexArray(vertexArray_);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, captureBuffer_);
    glEnable(GL_RASTERIZER_DISCARD);
    glBeginTransformFeedback(GL_POINTS);
    glDrawArrays(GL_POINTS, 0, count);
    glEndTransformFeedback();
    glDisable(GL_RASTERIZER_DISCARD);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
    glBindVertexArray(0);
    glBindBuffer(GL_COPY_READ_BUFFER, captureBuffer_);
    glGetBufferSubData(GL_COPY_READ_BUFFER, 0, bytes, out.data());
    glBindBuffer(GL_COPY_READ_BUFFER, 0);
    return out;
}

}  // namespace conecurl
