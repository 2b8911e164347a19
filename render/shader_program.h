#pragma once
// A linked GLSL program from vertex and fragment source, with the compiler's log in the error.

#include <span>
#include <string>
#include <string_view>

#include "render/gl.h"

namespace sculpt::render {

/// A fragment shader body with the version line and the shared lighting functions in front
/// (GLSL 3.30 has no #include).
std::string litFragmentSource(const char* body);

class ShaderProgram {
 public:
  /// Compiles and links; throws std::runtime_error with the GLSL log ("<name>: ...").
  /// `fragmentSource` may be null for a transform-feedback-only program; `feedbackVaryings` are
  /// the vertex outputs captured (interleaved) by transform feedback.
  ShaderProgram(std::string_view name, const char* vertexSource, const char* fragmentSource,
                std::span<const char* const> feedbackVaryings = {});
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  void use() const { glUseProgram(program_); }
  GLint uniform(const char* name) const { return glGetUniformLocation(program_, name); }

 private:
  GLuint program_ = 0;
};

}  // namespace sculpt::render
