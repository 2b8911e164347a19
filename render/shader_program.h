#pragma once
// A linked GLSL program from vertex and fragment source, with the compiler's log in the error.

#include <initializer_list>
#include <span>
#include <string>
#include <string_view>

#include "render/gl.h"

namespace sculpt::render {

/// A shader body with the version line and shared GLSL function files (e.g.
/// shaders::kColourMapGlsl) in front, in order: GLSL 3.30 has no #include.
std::string shaderSource(std::initializer_list<const char*> libraries, const char* body);
/// shaderSource with the shared lighting functions (lighting.glsl).
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
