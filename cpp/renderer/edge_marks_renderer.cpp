// The edge marks' GL side: their quads coloured like a real book's index tabs, uploaded when the
// leaves on a side or the marks change, drawn in one call; see edge_marks_renderer.hpp.
#include "edge_marks_renderer.hpp"

#include <iterator>
#include <string>
#include <utility>

#include <glm/gtc/type_ptr.hpp>

#include "embedded_shaders.hpp"
#include "gl_program.hpp"

namespace conecurl {

namespace {

constexpr char kPrelude[] = "#version 300 es\nprecision highp float;\n";
constexpr int kFloats = 8;  // x y z u, v r g b
// Index-tab colours, one per slot in turn: saturated enough to tell apart at a glance on white paper.
constexpr float kTabColors[][3] = {
    {0.85f, 0.27f, 0.27f}, {0.93f, 0.58f, 0.20f}, {0.91f, 0.77f, 0.22f}, {0.33f, 0.64f, 0.36f},
    {0.20f, 0.62f, 0.64f}, {0.27f, 0.47f, 0.80f}, {0.55f, 0.37f, 0.76f}, {0.84f, 0.38f, 0.60f},
};
constexpr float kTickColor[3] = {0.90f, 0.33f, 0.05f};

std::vector<float> markMesh(const Book& book, const std::vector<EdgeMark>& marks) {
    std::vector<float> out;
    for (const EdgeMarkShape& shape : edgeMarkShapes(book, marks)) {
        const float* color = shape.kind == EdgeMarkKind::Tick
                                 ? kTickColor
                                 : kTabColors[shape.slot % static_cast<int>(std::size(kTabColors))];
        // Corners 0-1 run across the mark (u: 0 at its inner end), 1-2 along it (v).
        const float uv[4][2] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
        for (const int i : {0, 1, 2, 0, 2, 3}) {
            const glm::dvec3& p = shape.corners[i];
            const float v[kFloats] = {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z), uv[i][0],
                                      uv[i][1], color[0], color[1], color[2]};
            out.insert(out.end(), v, v + kFloats);
        }
    }
    return out;
}

}  // namespace

void EdgeMarksRenderer::setMarks(std::vector<EdgeMark> marks) {
    marks_ = std::move(marks);
    marksChanged_ = true;
}

void EdgeMarksRenderer::draw(const Book& book, const glm::mat4& viewProjection, GLuint restoreProgram) {
    if (marks_.empty() || !error_.empty()) return;
    if (!program_) {
        ProgramSource source;
        source.vertex = std::string(kPrelude) + shaders::edge_marks_vert;
        source.fragment = std::string(kPrelude) + shaders::edge_marks_frag;
        program_ = buildProgram(source, error_);
        if (!program_) return;
        viewProjection_ = glGetUniformLocation(program_, "uViewProjection");
        glGenBuffers(1, &buffer_);
        glBindBuffer(GL_ARRAY_BUFFER, buffer_);
        vec4PairAttributes(3, kFloats);
        marksChanged_ = true;
    }
    const BookConfig& c = book.config();
    const Key key{stackLeaves(book), c.pageCount, c.leafThickness, c.pageWidth, c.pageHeight, c.display, c.binding};
    if (marksChanged_ || !(key == key_)) {
        key_ = key;
        marksChanged_ = false;
        const std::vector<float> mesh = markMesh(book, marks_);
        vertexCount_ = static_cast<int>(mesh.size()) / kFloats;
        box_ = WorldBox::of(mesh, kFloats);
        if (vertexCount_ > 0) {
            glBindBuffer(GL_ARRAY_BUFFER, buffer_);
            glBufferData(GL_ARRAY_BUFFER, mesh.size() * sizeof(float), mesh.data(), GL_DYNAMIC_DRAW);
        }
    }
    if (vertexCount_ == 0) return;
    // Below the pages and every leaf that moves: drawn over the stacks, under all that follows.
    const bool depthTest = glIsEnabled(GL_DEPTH_TEST);
    if (depthTest) glDisable(GL_DEPTH_TEST);
    glUseProgram(program_);
    glUniformMatrix4fv(viewProjection_, 1, GL_FALSE, glm::value_ptr(viewProjection));
    glDrawArrays(GL_TRIANGLES, 0, vertexCount_);
    glUseProgram(restoreProgram);
    if (depthTest) glEnable(GL_DEPTH_TEST);
}

void EdgeMarksRenderer::release() {
    glDeleteProgram(program_);
    glDeleteBuffers(1, &buffer_);
    forget();
}

void EdgeMarksRenderer::forget() {
    error_.clear();
    program_ = 0;
    buffer_ = 0;
    viewProjection_ = -1;
    vertexCount_ = 0;
    key_ = Key{};
    marksChanged_ = true;
}

}  // namespace conecurl
