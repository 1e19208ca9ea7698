// What the renderer leaves out of the first view and does once it is on screen (BookRenderer::finishFirstView):
// each is a wait on the browser's GL that the first frame does not need. Kept apart from the drawing.
#include <emscripten/em_js.h>

#include <algorithm>

#include "book_renderer.hpp"

// The current context's canvas size, read from the element: no call on the GL, so nothing waits on it.
EM_JS(void, conecurl_canvas_size, (int* width, int* height), {
    HEAP32[width >> 2] = GLctx.canvas.width;
    HEAP32[height >> 2] = GLctx.canvas.height;
});

namespace conecurl {

bool BookRenderer::finishFirstView() {
    if (!firstView_) return false;
    firstView_ = false;
    if (!ok() || !makeCurrent()) return false;
    makeMipmaps();
    int width = 0;
    int height = 0;
    drawingBufferSize(width, height);
    return drawingWidth_ > 0 && (width != drawingWidth_ || height != drawingHeight_);
}

void BookRenderer::drawingBufferSize(int& width, int& height) {
    int canvasWidth = 0;
    int canvasHeight = 0;
    conecurl_canvas_size(&canvasWidth, &canvasHeight);
    if (firstView_) {
        // The buffer has the canvas's size unless the browser clamped it, as Chromium does to the largest texture.
        width = std::min(canvasWidth, maxTextureSize_);
        height = std::min(canvasHeight, maxTextureSize_);
        return;
    }
    if (canvasWidth != bufferSize_.canvasWidth || canvasHeight != bufferSize_.canvasHeight) {
        emscripten_webgl_get_drawing_buffer_size(context_, &bufferSize_.width, &bufferSize_.height);
        bufferSize_.canvasWidth = canvasWidth;
        bufferSize_.canvasHeight = canvasHeight;
    }
    width = bufferSize_.width;
    height = bufferSize_.height;
}

void BookRenderer::finishPageTexture(GLuint texture) {
    bindTexture(0, texture, true);
    if (!firstView_) {
        glGenerateMipmap(GL_TEXTURE_2D);
    } else if (std::find(withoutMipmaps_.begin(), withoutMipmaps_.end(), texture) == withoutMipmaps_.end()) {
        withoutMipmaps_.push_back(texture);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, firstView_ ? GL_LINEAR : GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    // Small text on a tilted page stays legible with anisotropic filtering, where the GPU does it right.
    setBoundAnisotropy();
}

void BookRenderer::makeMipmaps() {
    for (GLuint texture : withoutMipmaps_) {
        bindTexture(0, texture, true);
        glGenerateMipmap(GL_TEXTURE_2D);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        setBoundAnisotropy();
    }
    withoutMipmaps_.clear();
}

}  // namespace conecurl
