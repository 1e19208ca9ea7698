// Whether this GPU's anisotropic filtering keeps a page at rest as sharp as trilinear: found by drawing, since
// renderer strings are masked (WebKitGTK's says "Apple GPU" on Mesa's llvmpipe, which filters wrong). Asked once a page.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>

#include "book_renderer.hpp"

namespace conecurl {
namespace {

// A texture of 1-px black columns every 4 px on white, drawn into a target 2/3 its size: a page at rest, where
// every pixel's footprint is square. Anisotropic filtering there must give what trilinear gives; Mesa's llvmpipe
// filters from too fine a level instead (its pixels differ by up to 35, a stroke of 109 reading 135), a
// conformant GPU within rounding (SwiftShader: 0).
constexpr int kSource = 96;
constexpr int kTarget = 64;
constexpr int kTolerance = 12;  // of 255, on any pixel
// The page-wide verdict: every context of a page draws on the same GPU. -1 not asked yet, 0 wrong, 1 right.
int anisotropyVerdict = -1;

}  // namespace

float BookRenderer::pageAnisotropy(bool probe) {
    if (maxAnisotropy_ <= 1.0f) return 1.0f;
    if (anisotropyVerdict < 0 && probe) anisotropyVerdict = probeAnisotropy() ? 1 : 0;
    return anisotropyVerdict == 1 ? std::min(8.0f, maxAnisotropy_) : 1.0f;
}

bool BookRenderer::anisotropyUnknown() const { return maxAnisotropy_ > 1.0f && anisotropyVerdict < 0; }

void BookRenderer::settleAnisotropy() {
    // The probe draws with the composite program: only once it is linked (prepareTurn links it while the
    // answer is unknown), so it waits on no compile.
    if (anisotropy_ > 1.0f || compositeProgram_.id == 0) return;
    anisotropy_ = pageAnisotropy(true);
    if (anisotropy_ <= 1.0f) return;
    for (const auto& [page, texture] : pageTextures_) {
        bindTexture(0, texture, true);
        setBoundAnisotropy();
    }
}

void BookRenderer::setBoundAnisotropy() {
    if (anisotropy_ > 1.0f) glTexParameterf(GL_TEXTURE_2D, kTextureMaxAnisotropy, anisotropy_);
}

bool BookRenderer::probeAnisotropy() {
    GLuint source = 0;
    GLuint target = 0;
    GLuint framebuffer = 0;
    glGenTextures(1, &source);
    glGenTextures(1, &target);
    glGenFramebuffers(1, &framebuffer);
    // The source's columns are cleared in, not uploaded: no pixels pass through the wasm heap.
    // Its target is bound on a unit the composite program does not sample (its mask's, 2, would be a feedback loop).
    colorTarget(framebuffer, 0, source, kSource, kSource, GL_LINEAR);
    glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    for (int x = 0; x < kSource; x += 4) {
        glScissor(x, 0, 1, kSource);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    glDisable(GL_SCISSOR_TEST);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);  // as createGpuObjects leaves it
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    // Two squares side by side, trilinear then anisotropic, each the composite program's copy of the source.
    colorTarget(framebuffer, 0, target, 2 * kTarget, kTarget, GL_NEAREST);
    const float levels[2] = {1.0f, std::min(2.0f, maxAnisotropy_)};
    for (int i = 0; i < 2; i++) {
        bindTexture(3, source, true);
        glTexParameterf(GL_TEXTURE_2D, kTextureMaxAnisotropy, levels[i]);
        glViewport(i * kTarget, 0, kTarget, kTarget);
        drawComposite(source, kTarget, kTarget, false, {i * kTarget, 0});
    }
    std::array<std::uint8_t, 2 * kTarget * 4> row{};  // one row holds every column of both: the strokes run down
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, kTarget / 2, 2 * kTarget, 1, GL_RGBA, GL_UNSIGNED_BYTE, row.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(1, &source);
    glDeleteTextures(1, &target);
    boundTextures_[0] = 0;  // deleting a bound texture unbinds it
    boundTextures_[3] = 0;
    int worst = 0;
    for (int x = 0; x < kTarget; x++) worst = std::max(worst, std::abs(row[x * 4] - row[(kTarget + x) * 4]));
    return worst <= kTolerance;
}

}  // namespace conecurl
