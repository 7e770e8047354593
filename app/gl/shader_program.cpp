#include "gl/shader_program.hpp"

#include <stdexcept>
#include <string>
#include <vector>

#include "gl/embedded_shaders.hpp"

namespace rad {

namespace {

GLuint compile(GLenum stage, std::string_view name) {
    const std::string_view source = embedded_shader(name);
    if (source.empty()) throw std::runtime_error("no embedded shader named " + std::string(name));
    const GLuint shader = glCreateShader(stage);
    const char* text = source.data();
    const auto length = static_cast<GLint>(source.size());
    glShaderSource(shader, 1, &text, &length);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        GLint log_length = 0;
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &log_length);
        std::vector<char> log(static_cast<std::size_t>(std::max(log_length, 1)));
        glGetShaderInfoLog(shader, log_length, nullptr, log.data());
        glDeleteShader(shader);
        throw std::runtime_error("shader " + std::string(name) + " does not compile: " + log.data());
    }
    return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(std::string_view vertex_name, std::string_view fragment_name) {
    const GLuint vertex = compile(GL_VERTEX_SHADER, vertex_name);
    const GLuint fragment = compile(GL_FRAGMENT_SHADER, fragment_name);
    program_ = glCreateProgram();
    glAttachShader(program_, vertex);
    glAttachShader(program_, fragment);
    glLinkProgram(program_);
    glDeleteShader(vertex);
    glDeleteShader(fragment);
    GLint ok = GL_FALSE;
    glGetProgramiv(program_, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        char log[1024] = {};
        glGetProgramInfoLog(program_, sizeof log, nullptr, log);
        glDeleteProgram(program_);
        throw std::runtime_error("shaders " + std::string(vertex_name) + " + " + std::string(fragment_name) +
                                 " do not link: " + log);
    }
}

ShaderProgram::~ShaderProgram() {
    glDeleteProgram(program_);
}

}  // namespace rad
