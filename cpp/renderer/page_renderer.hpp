// Draws one page curled on the cone with WebGL2 through Emscripten's GL layer. The core decides the
// cone parameters; this class only owns GL objects and turns parameters into uniforms and draws.
#pragma once

#include <GLES3/gl3.h>
#include <emscripten/html5_webgl.h>

#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "cone_deform.hpp"
#include "curl_schedule.hpp"
#include "page_grid.hpp"

namespace conecurl {

enum class PageSide { Front = 0, Back = 1 };

struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;  // rows top to bottom, as ImageData holds them
};

class PageRenderer {
public:
    // Creates a WebGL2 context on the canvas found by `canvasTarget` (a CSS selector, or a name
    // registered in Emscripten's specialHTMLTargets). On failure ok() is false and error() says why.
    explicit PageRenderer(const std::string& canvasTarget);
    ~PageRenderer();
    PageRenderer(const PageRenderer&) = delete;
    PageRenderer& operator=(const PageRenderer&) = delete;

    bool ok() const { return error_.empty(); }
    const std::string& error() const { return error_; }

    // Page size in world units (height 1 is Nuon's page); rebuilds the grid.
    void setPageSize(double width, double height);
    double pageWidth() const { return pageWidth_; }
    double pageHeight() const { return pageHeight_; }
    void setSchedule(const CurlSchedule& schedule) { schedule_ = schedule; }
    const CurlSchedule& schedule() const { return schedule_; }
    void setShading(bool on) { shading_ = on; }

    // RGBA8 pixels, rows top to bottom, width * height * 4 bytes. Returns an empty string, or why the
    // image was refused (size not positive, over the GPU's texture limit); the renderer keeps working.
    std::string setPageImage(PageSide side, int width, int height, const std::uint8_t* rgba);

    CurlParams paramsAt(double t) const { return curlAt(t, schedule_, pageHeight_); }
    void drawAt(double t) { draw(paramsAt(t)); }
    void draw(const CurlParams& params);

    // The pixels of the last drawn frame, rows top to bottom (call in the same task as draw()).
    RgbaImage readPixels();

    // Runs the vertex shader over every grid vertex with transform feedback and returns, per vertex,
    // the curled position and the shader's finite-difference normal: x y z nx ny nz.
    std::vector<float> captureCurledVertices(const CurlParams& params);

    const PageGrid& grid() const { return grid_; }
    int maxTextureSize() const { return maxTextureSize_; }

private:
    bool makeCurrent();
    void createGpuObjects();
    void uploadGrid();
    void useProgramWith(const CurlParams& params, float aspect);
    glm::mat4 viewProjection(float aspect, glm::vec3& eyeOut) const;

    std::string error_;
    EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context_ = 0;

    double pageWidth_ = 0.8;
    double pageHeight_ = 1.0;
    CurlSchedule schedule_;
    bool shading_ = true;
    PageGrid grid_;
    int maxTextureSize_ = 0;

    GLuint program_ = 0;
    GLuint vertexArray_ = 0;
    GLuint vertexBuffer_ = 0;
    GLuint indexBuffer_ = 0;
    GLuint captureBuffer_ = 0;
    GLuint textures_[2] = {0, 0};

    struct Uniforms {
        GLint curl = -1, pageSize = -1, normalStep = -1, viewProjection = -1;
        GLint frontTexture = -1, backTexture = -1, eye = -1, shading = -1;
    } uniforms_;
};

}  // namespace conecurl
