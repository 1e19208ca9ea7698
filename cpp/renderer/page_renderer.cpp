// WebGL2 drawing of a curled page: static grid in a VBO, cone parameters as uniforms, two textures.
#include "page_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "embedded_shaders.hpp"
#include "gl_program.hpp"

// WebGL2's getBufferSubData, which Emscripten's GL library implements but GLES3 headers omit (GLES
// has glMapBufferRange instead, which WebGL lacks). Needed to read transform feedback back.
extern "C" void glGetBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size, void* data);

namespace conecurl {
namespace {

constexpr char kShaderPrelude[] = "#version 300 es\nprecision highp float;\n";
constexpr int kGridRows = 60;            // first slice: fixed; the renderer issue sizes it by error
constexpr double kNormalStepOfHeight = 1e-3;  // the math doc's finite-difference step
constexpr float kFieldOfViewY = 24.0f;   // degrees; mild perspective so a lifted page reads as lifted
constexpr float kFrameMargin = 1.3f;     // room around the spread for the page lifting towards the eye

// Placeholder texels until the user's image arrives: warm paper, a little darker on the back.
constexpr std::uint8_t kPaperFront[4] = {246, 242, 232, 255};
constexpr std::uint8_t kPaperBack[4] = {232, 226, 214, 255};

}  // namespace

PageRenderer::PageRenderer(const std::string& canvasTarget) {
    EmscriptenWebGLContextAttributes attributes;
    emscripten_webgl_init_context_attributes(&attributes);
    attributes.majorVersion = 2;
    attributes.minorVersion = 0;
    attributes.alpha = true;
    attributes.premultipliedAlpha = true;
    attributes.antialias = true;
    attributes.depth = true;
    context_ = emscripten_webgl_create_context(canvasTarget.c_str(), &attributes);
    if (context_ <= 0) {
        error_ = "WebGL2 is not available on canvas '" + canvasTarget + "'";
        context_ = 0;
        return;
    }
    setPageSize(pageWidth_, pageHeight_);
    createGpuObjects();
}

PageRenderer::~PageRenderer() {
    if (!context_) return;
    if (makeCurrent()) {
        glDeleteProgram(program_);
        glDeleteVertexArrays(1, &vertexArray_);
        glDeleteBuffers(1, &vertexBuffer_);
        glDeleteBuffers(1, &indexBuffer_);
        glDeleteBuffers(1, &captureBuffer_);
        glDeleteTextures(2, textures_);
    }
    emscripten_webgl_destroy_context(context_);
}

bool PageRenderer::makeCurrent() {
    return context_ && emscripten_webgl_make_context_current(context_) == EMSCRIPTEN_RESULT_SUCCESS;
}

void PageRenderer::setPageSize(double width, double height) {
    pageWidth_ = width;
    pageHeight_ = height;
    const int columns = std::max(8, static_cast<int>(std::lround(kGridRows * width / height)));
    grid_ = makePageGrid(width, height, columns, kGridRows);
    if (vertexBuffer_) uploadGrid();
}

void PageRenderer::createGpuObjects() {
    if (!makeCurrent()) {
        error_ = "could not make the WebGL2 context current";
        return;
    }
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTextureSize_);

    ProgramSource source;
    source.vertex = std::string(kShaderPrelude) + shaders::cone_curl_glsl + shaders::page_vert;
    source.fragment = std::string(kShaderPrelude) + shaders::page_frag;
    // The drawing program itself is captured, so the readback test checks the very shader that draws.
    source.transformFeedbackVaryings = {"vWorldPosition", "vNormal"};
    program_ = buildProgram(source, error_);
    if (!program_) return;

    uniforms_.curl = glGetUniformLocation(program_, "uCurl");
    uniforms_.pageSize = glGetUniformLocation(program_, "uPageSize");
    uniforms_.normalStep = glGetUniformLocation(program_, "uNormalStep");
    uniforms_.viewProjection = glGetUniformLocation(program_, "uViewProjection");
    uniforms_.frontTexture = glGetUniformLocation(program_, "uFrontTexture");
    uniforms_.backTexture = glGetUniformLocation(program_, "uBackTexture");
    uniforms_.eye = glGetUniformLocation(program_, "uEye");
    uniforms_.shading = glGetUniformLocation(program_, "uShading");

    glGenVertexArrays(1, &vertexArray_);
    glGenBuffers(1, &vertexBuffer_);
    glGenBuffers(1, &indexBuffer_);
    glGenBuffers(1, &captureBuffer_);
    uploadGrid();

    glGenTextures(2, textures_);
    setPageImage(PageSide::Front, 1, 1, kPaperFront);
    setPageImage(PageSide::Back, 1, 1, kPaperBack);
}

void PageRenderer::uploadGrid() {
    if (!makeCurrent()) return;
    glBindVertexArray(vertexArray_);
    glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
    glBufferData(GL_ARRAY_BUFFER, grid_.points.size() * sizeof(float), grid_.points.data(), GL_STATIC_DRAW);
    const GLint location = glGetAttribLocation(program_, "aPagePoint");
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, grid_.indices.size() * sizeof(std::uint32_t), grid_.indices.data(),
                 GL_STATIC_DRAW);
    glBindVertexArray(0);
}

std::string PageRenderer::setPageImage(PageSide side, int width, int height, const std::uint8_t* rgba) {
    if (width <= 0 || height <= 0 || !rgba) return "page image must have a positive size";
    if (width > maxTextureSize_ || height > maxTextureSize_) {
        return "page image " + std::to_string(width) + "x" + std::to_string(height) +
               " exceeds MAX_TEXTURE_SIZE " + std::to_string(maxTextureSize_);
    }
    if (!makeCurrent()) return "the WebGL2 context is not available";
    glBindTexture(GL_TEXTURE_2D, textures_[static_cast<int>(side)]);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return {};
}

glm::mat4 PageRenderer::viewProjection(float aspect, glm::vec3& eye) const {
    // Frame the open spread: the page on the right of the spine and where it lands on the left.
    const float tanHalf = std::tan(glm::radians(kFieldOfViewY) * 0.5f);
    const float halfHeight = 0.5f * static_cast<float>(pageHeight_) * kFrameMargin;
    const float halfWidth = static_cast<float>(pageWidth_) * kFrameMargin;
    const float distance = std::max(halfHeight / tanHalf, halfWidth / (tanHalf * aspect));
    const glm::vec3 center(0.0f, 0.5f * static_cast<float>(pageHeight_), 0.0f);
    eye = center + glm::vec3(0.0f, 0.0f, distance);
    const float reach = static_cast<float>(std::max(pageWidth_, pageHeight_));
    const glm::mat4 projection =
        glm::perspective(glm::radians(kFieldOfViewY), aspect, 0.02f * distance, distance + 2.0f * reach);
    return projection * glm::lookAt(eye, center, glm::vec3(0.0f, 1.0f, 0.0f));
}

void PageRenderer::useProgramWith(const CurlParams& raw, float aspect) {
    const CurlParams params = sanitize(raw);
    glm::vec3 eye;
    const glm::mat4 vp = viewProjection(aspect, eye);
    glUseProgram(program_);
    glUniform3f(uniforms_.curl, static_cast<float>(params.theta), static_cast<float>(params.apexY),
                static_cast<float>(params.rho));
    glUniform2f(uniforms_.pageSize, static_cast<float>(pageWidth_), static_cast<float>(pageHeight_));
    glUniform1f(uniforms_.normalStep, static_cast<float>(kNormalStepOfHeight * pageHeight_));
    glUniformMatrix4fv(uniforms_.viewProjection, 1, GL_FALSE, glm::value_ptr(vp));
    glUniform3f(uniforms_.eye, eye.x, eye.y, eye.z);
    glUniform1f(uniforms_.shading, shading_ ? 1.0f : 0.0f);
    glUniform1i(uniforms_.frontTexture, 0);
    glUniform1i(uniforms_.backTexture, 1);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, textures_[0]);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, textures_[1]);
}

void PageRenderer::draw(const CurlParams& params) {
    if (!ok() || !makeCurrent()) return;
    int width = 0;
    int height = 0;
    emscripten_webgl_get_drawing_buffer_size(context_, &width, &height);
    if (width <= 0 || height <= 0) return;
    glViewport(0, 0, width, height);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);  // one mesh, two sides
    useProgramWith(params, static_cast<float>(width) / static_cast<float>(height));
    glBindVertexArray(vertexArray_);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(grid_.indices.size()), GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
}

RgbaImage PageRenderer::readPixels() {
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

std::vector<float> PageRenderer::captureCurledVertices(const CurlParams& params) {
    std::vector<float> out;
    if (!ok() || !makeCurrent()) return out;
    const int count = grid_.vertexCount();
    out.resize(static_cast<size_t>(count) * 6);
    const GLsizeiptr bytes = static_cast<GLsizeiptr>(out.size() * sizeof(float));

    glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, captureBuffer_);
    glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, bytes, nullptr, GL_STREAM_READ);
    glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, 0);

    useProgramWith(params, 1.0f);
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
