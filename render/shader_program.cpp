#include "render/shader_program.h"

#include "shader_sources.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace sculpt::render {
namespace {

/// The info log of a shader or program (glGetShaderiv/glGetShaderInfoLog or the program pair).
template <typename GetIv, typename GetLog>
std::string infoLog(GLuint object, GetIv getIv, GetLog getLog) {
  GLint length = 0;
  getIv(object, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(static_cast<size_t>(std::max(length, 1)), '\0');
  getLog(object, length, nullptr, log.data());
  return log.data();
}

GLuint compile(std::string_view name, GLenum kind, const char* source) {
  const GLuint shader = glCreateShader(kind);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = infoLog(shader, glGetShaderiv, glGetShaderInfoLog);
    glDeleteShader(shader);
    throw std::runtime_error(std::string(name) +
                             (kind == GL_VERTEX_SHADER ? " vertex" : " fragment") +
                             " shader: " + log);
  }
  return shader;
}

}  // namespace

std::string shaderSource(std::initializer_list<const char*> libraries, const char* body) {
  std::string source = "#version 330 core\n";
  for (const char* library : libraries) source += library;
  return source + body;
}

std::string litFragmentSource(const char* body) {
  return shaderSource({shaders::kLightingGlsl}, body);
}

ShaderProgram::ShaderProgram(std::string_view name, const char* vertexSource,
                             const char* fragmentSource,
                             std::span<const char* const> feedbackVaryings) {
  const GLuint vertex = compile(name, GL_VERTEX_SHADER, vertexSource);
  const GLuint fragment = fragmentSource ? compile(name, GL_FRAGMENT_SHADER, fragmentSource) : 0;
  program_ = glCreateProgram();
  glAttachShader(program_, vertex);
  if (fragment) glAttachShader(program_, fragment);
  if (!feedbackVaryings.empty())
    glTransformFeedbackVaryings(program_, static_cast<GLsizei>(feedbackVaryings.size()),
                                feedbackVaryings.data(), GL_INTERLEAVED_ATTRIBS);
  glLinkProgram(program_);
  glDeleteShader(vertex);
  if (fragment) glDeleteShader(fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = infoLog(program_, glGetProgramiv, glGetProgramInfoLog);
    glDeleteProgram(program_);
    throw std::runtime_error(std::string(name) + " link: " + log);
  }
}

ShaderProgram::~ShaderProgram() { glDeleteProgram(program_); }

}  // namespace sculpt::render
