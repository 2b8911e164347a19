#include "render/shader_program.h"

#include <stdexcept>
#include <vector>

namespace sculpt::render {
namespace {

GLuint compile(std::string_view name, GLenum kind, const char* source) {
  const GLuint shader = glCreateShader(kind);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<size_t>(std::max(length, 1)));
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    glDeleteShader(shader);
    throw std::runtime_error(std::string(name) +
                             (kind == GL_VERTEX_SHADER ? " vertex" : " fragment") +
                             " shader: " + log.data());
  }
  return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(std::string_view name, const char* vertexSource,
                             const char* fragmentSource) {
  const GLuint vertex = compile(name, GL_VERTEX_SHADER, vertexSource);
  const GLuint fragment = compile(name, GL_FRAGMENT_SHADER, fragmentSource);
  program_ = glCreateProgram();
  glAttachShader(program_, vertex);
  glAttachShader(program_, fragment);
  glLinkProgram(program_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    glGetProgramiv(program_, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<size_t>(std::max(length, 1)));
    glGetProgramInfoLog(program_, length, nullptr, log.data());
    glDeleteProgram(program_);
    throw std::runtime_error(std::string(name) + " link: " + log.data());
  }
}

ShaderProgram::~ShaderProgram() { glDeleteProgram(program_); }

}  // namespace sculpt::render
