#pragma once

#include <glad/gl.h>

#include <string_view>

namespace rad {

// A linked vertex + fragment program built from two embedded shaders (shaders/NAME).
class ShaderProgram {
  public:
    // Throws std::runtime_error with the driver's log when a shader does not compile or link.
    ShaderProgram(std::string_view vertex_name, std::string_view fragment_name);
    ~ShaderProgram();
    ShaderProgram(const ShaderProgram&) = delete;
    ShaderProgram& operator=(const ShaderProgram&) = delete;

    void use() const { glUseProgram(program_); }
    GLint uniform(const char* name) const { return glGetUniformLocation(program_, name); }

  private:
    GLuint program_ = 0;
};

}  // namespace rad
