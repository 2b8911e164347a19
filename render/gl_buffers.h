#pragma once
// Small buffer helpers shared by the renderers.

#include <cstdint>
#include <span>

#include "render/gl.h"

namespace sculpt::render {

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
