// Shader compile/link helpers; kept apart so the renderer reads as drawing, not boilerplate.
#include "gl_program.hpp"

namespace conecurl {
namespace {

std::string shaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(length > 0 ? length : 1), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    return log.c_str();
}

GLuint startStage(GLenum stage, const std::string& text) {
    GLuint shader = glCreateShader(stage);
    const char* src = text.c_str();
    glShaderSource(shader, 1, &src, nullptr);
    glCompileShader(shader);
    return shader;
}

bool compiled(GLuint shader) {
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    return ok == GL_TRUE;
}

constexpr GLenum kCompletionStatus = 0x91B1;  // GL_COMPLETION_STATUS_KHR (KHR_parallel_shader_compile)

}  // namespace

PendingProgram startProgram(const ProgramSource& source) {
    PendingProgram pending;
    pending.vertex = startStage(GL_VERTEX_SHADER, source.vertex);
    pending.fragment = startStage(GL_FRAGMENT_SHADER, source.fragment);
    pending.program = glCreateProgram();
    glAttachShader(pending.program, pending.vertex);
    glAttachShader(pending.program, pending.fragment);
    if (!source.transformFeedbackVaryings.empty()) {
        glTransformFeedbackVaryings(pending.program, static_cast<GLsizei>(source.transformFeedbackVaryings.size()),
                                    source.transformFeedbackVaryings.data(), GL_INTERLEAVED_ATTRIBS);
    }
    glLinkProgram(pending.program);  // a link of stages that failed fails too; finishProgram says which stage
    return pending;
}

bool programCompleted(const PendingProgram& pending) {
    GLint done = GL_FALSE;
    glGetProgramiv(pending.program, kCompletionStatus, &done);
    return done == GL_TRUE;
}

GLuint finishProgram(PendingProgram& pending, std::string& error) {
    GLuint program = pending.program;
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        // The first stage that failed to compile is the error, as it would be compiled and checked alone.
        if (!compiled(pending.vertex)) {
            error = "vertex shader failed to compile: " + shaderLog(pending.vertex);
        } else if (!compiled(pending.fragment)) {
            error = "fragment shader failed to compile: " + shaderLog(pending.fragment);
        } else {
            GLint length = 0;
            glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
            std::string log(static_cast<size_t>(length > 0 ? length : 1), '\0');
            glGetProgramInfoLog(program, length, nullptr, log.data());
            error = "shader program failed to link: " + std::string(log.c_str());
        }
        glDeleteProgram(program);
        program = 0;
    }
    glDeleteShader(pending.vertex);  // attached ones are only flagged, and freed with their program
    glDeleteShader(pending.fragment);
    pending = PendingProgram{};
    return program;
}

void abandonProgram(PendingProgram& pending) {
    if (!pending.program) return;
    glDeleteProgram(pending.program);
    glDeleteShader(pending.vertex);
    glDeleteShader(pending.fragment);
    pending = PendingProgram{};
}

GLuint buildProgram(const ProgramSource& source, std::string& error) {
    PendingProgram pending = startProgram(source);
    return finishProgram(pending, error);
}

void vec4PairAttributes(GLuint location, int strideFloats) {
    const auto stride = static_cast<GLsizei>(strideFloats * sizeof(float));
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, 4, GL_FLOAT, GL_FALSE, stride, nullptr);
    glEnableVertexAttribArray(location + 1);
    glVertexAttribPointer(location + 1, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(4 * sizeof(float)));
}

}  // namespace conecurl
