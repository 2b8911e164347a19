#pragma once
// Small buffer helpers shared by the renderers.

#include <cstdint>
#include <span>

#include "render/gl.h"

namespace sculpt::render {

/// Makes `buffer` (a new one when 0) tightly packed float attribute `index` of the bound vertex
/// array, `components` per vertex; returns the buffer.
inline GLuint floatAttribute(GLuint index, GLint components, GLuint buffer = 0) {
  if (buffer == 0) glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glEnableVertexAttribArray(index);
  glVertexAttribPointer(index, components, GL_FLOAT, GL_FALSE, 0, nullptr);
  return buffer;
}

/// Uploads triangle indices into `indexBuffer` as the element array of `vao`; returns the count.
inline GLsizei uploadTriangleIndices(GLuint vao, GLuint indexBuffer,
                                     std::span<const uint32_t> indices) {
  glBindVertexArray(vao);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size_bytes()),
               indices.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
  return static_cast<GLsizei>(indices.size());
}

}  // namespace sculpt::render
