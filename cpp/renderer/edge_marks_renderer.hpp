// Draws the marks on the page blocks' fore-edge (index tabs, search ticks) that cpp/core/edge_marks
// places: its own program and buffer, drawn from one hook where the renderer draws the stacks.
#pragma once

#include <GLES3/gl3.h>

#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "book.hpp"
#include "book_stacks.hpp"
#include "edge_marks.hpp"
#include "world_box.hpp"

namespace conecurl {

class EdgeMarksRenderer {
public:
    void setMarks(std::vector<EdgeMark> marks);
    const std::vector<EdgeMark>& marks() const { return marks_; }
    // Draws the marks that show on `book` now, below everything else (no depth test, no depth
    // written), with the vertex array in place bound (it adds its attributes there, at locations 3
    // and 4, once). The program `restoreProgram` and the depth test are as they were afterwards.
    // Without marks it makes no GL call. A program that fails to build leaves the marks out (error()
    // says why) and the book drawn as ever.
    void draw(const Book& book, const glm::mat4& viewProjection, GLuint restoreProgram);
    const std::string& error() const { return error_; }
    int verticesDrawn() const { return vertexCount_; }
    // Where the marks drawn last lie in the world (empty without marks).
    WorldBox worldBox() const { return marks_.empty() || vertexCount_ == 0 ? WorldBox{} : box_; }
    void release();  // deletes its GL objects (the context is current)
    void forget();   // they died with a lost context

private:
    struct Key {  // what the marks' quads depend on besides the marks themselves
        StackLeaves leaves;
        int pageCount = -1;
        double thickness = -1.0, pageWidth = 0.0, pageHeight = 0.0;
        Display display = Display::Double;
        Binding binding = Binding::Left;
        bool operator==(const Key& o) const {
            return leaves == o.leaves && pageCount == o.pageCount && thickness == o.thickness &&
                   pageWidth == o.pageWidth && pageHeight == o.pageHeight && display == o.display && binding == o.binding;
        }
    };
    std::vector<EdgeMark> marks_;
    bool marksChanged_ = true;
    Key key_;
    std::string error_;
    GLuint program_ = 0;
    GLint viewProjection_ = -1;
    GLuint buffer_ = 0;
    int vertexCount_ = 0;
    WorldBox box_;
};

}  // namespace conecurl
