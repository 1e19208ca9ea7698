// A page image uploaded in horizontal bands, one band a frame while leaves move (page-textures.js asks),
// so that a page arriving mid-turn never puts a whole texImage2D into one frame of the turn. The bands
// fill a texture of their own; it replaces the page's texture once its last row is in.
#include <emscripten/em_js.h>

#include <algorithm>

#include "book_renderer.hpp"

// Rows [y, y + rows) of a browser image into the same rows of the texture bound to TEXTURE_2D: WebGL2
// reads a sub-rectangle of the source through UNPACK_SKIP_ROWS. 0: done; 1: the page may not read the
// image (SecurityError); 2: any other refusal.
EM_JS(int, conecurl_tex_rows_from_source, (void* source, int y, int width, int rows), {
    const UNPACK_SKIP_ROWS = 0x0CF3;
    try {
        GLctx.pixelStorei(UNPACK_SKIP_ROWS, y);
        GLctx.texSubImage2D(0x0DE1, 0, 0, y, width, rows, 0x1908, 0x1401, Emval.toValue(source));  // TEXTURE_2D, RGBA, UNSIGNED_BYTE
        return 0;
    } catch (error) {
        return error && error.name === 'SecurityError' ? 1 : 2;
    } finally {
        GLctx.pixelStorei(UNPACK_SKIP_ROWS, 0);
    }
});

namespace conecurl {

std::string BookRenderer::setPageImageRows(int page, int width, int height, int y, int rows, JsHandle source) {
    if (page < 0) return "page index must not be negative";
    if (width <= 0 || height <= 0 || !source) return "page image must have a positive size";
    if (width > maxTextureSize_ || height > maxTextureSize_) return "page image exceeds MAX_TEXTURE_SIZE";
    if (y < 0 || rows <= 0 || y + rows > height) return "page image band out of the image";
    if (!makeCurrent()) return "the WebGL2 context is not available";
    if (y == 0) {
        dropBand();
        band_ = Band{page, 0, width, height, 0};
        glGenTextures(1, &band_.texture);
        bindTexture(0, band_.texture, true);
        // Storage only: no pixels pass here (the bands bring them).
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    } else if (band_.page != page || band_.width != width || band_.height != height || band_.rows != y) {
        return "page image band out of order (bands go from row 0 down, one page at a time)";
    }
    bindTexture(0, band_.texture, true);  // to edit: unit 0 active whatever was bound
    const int uploaded = conecurl_tex_rows_from_source(static_cast<void*>(source), y, width, rows);
    if (uploaded != 0) {
        dropBand();
        return uploaded == 1 ? kTaintedSource : "the browser refused to upload the page image";
    }
    band_.rows = y + rows;
    if (band_.rows < height) return {};
    // The last band: the texture is the page's now, with its mipmaps and filtering as setPageImage's.
    const GLuint texture = band_.texture;
    band_ = Band{};
    releasePageImage(page);
    finishPageTexture(texture);
    pageTextures_.emplace_back(page, texture);
    return {};
}

// The bands under way are given up; their texture is deleted unless its context is gone with it.
void BookRenderer::dropBand(bool deleteTexture) {
    if (band_.texture && deleteTexture) {
        for (GLuint& bound : boundTextures_) {
            if (bound == band_.texture) bound = 0;
        }
        glDeleteTextures(1, &band_.texture);
    }
    band_ = Band{};
}

}  // namespace conecurl
