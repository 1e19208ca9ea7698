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

// A program whose compile and link have been asked for and not yet checked: the driver (or the browser's
// GPU process) works on it while the caller does something else. Checking it is what waits.
struct PendingProgram {
    GLuint program = 0;
    GLuint vertex = 0;
    GLuint fragment = 0;
};

// Asks for both stages' compiles and the link; queries nothing, so it does not wait.
PendingProgram startProgram(const ProgramSource& source);
// Whether the driver has finished `pending` (KHR_parallel_shader_compile's COMPLETION_STATUS_KHR; ask only
// where that extension is enabled, else the answer is always false).
bool programCompleted(const PendingProgram& pending);
// Checks `pending` (waiting for it if need be): the linked program, or 0 with `error` set to a readable
// message naming the stage that failed. Either way `pending` is spent (its shaders deleted).
GLuint finishProgram(PendingProgram& pending, std::string& error);
// Frees a started program that will never be finished.
void abandonProgram(PendingProgram& pending);

// startProgram then finishProgram: the linked program, or 0 with `error` set.
GLuint buildProgram(const ProgramSource& source, std::string& error);

// The buffer bound to GL_ARRAY_BUFFER read as two vec4 attributes a vertex, at `location` and
// `location + 1`, from vertices of `strideFloats` floats (the stacks' faces and the edge marks).
void vec4PairAttributes(GLuint location, int strideFloats);

}  // namespace conecurl
