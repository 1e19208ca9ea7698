// Compiling and linking GLSL programs with errors that name the stage and carry the driver's log.
#pragma once

#include <GLES3/gl3.h>

#include <string>
#include <vector>

namespace conecurl {

struct ProgramSource {
    std::string vertex;
    std::string fragment;
    std::vector<const char*> transformFeedbackVaryings;  // captured interleaved, if any
};

// Returns the linked program, or 0 with `error` set to a readable message.
GLuint buildProgram(const ProgramSource& source, std::string& error);

// The buffer bound to GL_ARRAY_BUFFER read as two vec4 attributes a vertex, at `location` and
// `location + 1`, from vertices of `strideFloats` floats (the stacks' faces and the edge marks).
void vec4PairAttributes(GLuint location, int strideFloats);

}  // namespace conecurl
