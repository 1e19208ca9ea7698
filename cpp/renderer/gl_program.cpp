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

GLuint compile(GLenum stage, const std::string& text, std::string& error) {
    GLuint shader = glCreateShader(stage);
    const char* src = text.c_str();
    glShaderSource(shader, 1, &src, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        error = std::string(stage == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                " shader failed to compile: " + shaderLog(shader);
        glDeleteShader(shader);
        return 0;
    }
    return shader;
}

}  // namespace

GLuint buildProgram(const ProgramSource& source, std::string& error) {
    GLuint vs = compile(GL_VERTEX_SHADER, source.vertex, error);
    if (!vs) return 0;
    GLuint fs = compile(GL_FRAGMENT_SHADER, source.fragment, error);
    if (!fs) {
        glDeleteShader(vs);
        return 0;
    }
    GLuint program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    if (!source.transformFeedbackVaryings.empty()) {
        glTransformFeedbackVaryings(program, static_cast<GLsizei>(source.transformFeedbackVaryings.size()),
                                    source.transformFeedbackVaryings.data(), GL_INTERLEAVED_ATTRIBS);
    }
    glLinkProgram(program);
    glDeleteShader(vs);  // flagged for deletion; freed with the program
    glDeleteShader(fs);
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        GLint length = 0;
        glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
        std::string log(static_cast<size_t>(length > 0 ? length : 1), '\0');
        glGetProgramInfoLog(program, length, nullptr, log.data());
        error = "shader program failed to link: " + std::string(log.c_str());
        glDeleteProgram(program);
        return 0;
    }
    return program;
}

void vec4PairAttributes(GLuint location, int strideFloats) {
    const auto stride = static_cast<GLsizei>(strideFloats * sizeof(float));
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, 4, GL_FLOAT, GL_FALSE, stride, nullptr);
    glEnableVertexAttribArray(location + 1);
    glVertexAttribPointer(location + 1, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(4 * sizeof(float)));
}

}  // namespace conecurl
