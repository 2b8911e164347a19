#include "render/surface_renderer.h"

#include <glm/gtc/type_ptr.hpp>

#include "render/gl_buffers.h"
#include "shader_sources.h"

namespace sculpt::render {

SurfaceRenderer::SurfaceRenderer()
    : program_("surface", shaders::kSurfaceVert, litFragmentSource(shaders::kSurfaceFrag).c_str()) {
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &indexBuffer_);
  glBindVertexArray(vao_);
  positionBuffer_ = floatAttribute(0, 3);
  normalBuffer_ = floatAttribute(1, 3);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);
  glBindVertexArray(0);
}

SurfaceRenderer::~SurfaceRenderer() {
  glDeleteBuffers(1, &indexBuffer_);
  glDeleteBuffers(1, &normalBuffer_);
  glDeleteBuffers(1, &positionBuffer_);
  glDeleteVertexArrays(1, &vao_);
}

void SurfaceRenderer::setTriangles(std::span<const uint32_t> indices) {
  indexCount_ = uploadTriangleIndices(vao_, indexBuffer_, indices);
}

void SurfaceRenderer::setVertices(std::span<const float> positions,
                                  std::span<const float> normals) {
  glBindBuffer(GL_ARRAY_BUFFER, positionBuffer_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(positions.size_bytes()), positions.data(),
               GL_DYNAMIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, normalBuffer_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(normals.size_bytes()), normals.data(),
               GL_DYNAMIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void SurfaceRenderer::draw(const glm::mat4& modelView, const glm::mat4& projection,
                           const glm::vec3& colour) const {
  program_.use();
  glUniformMatrix4fv(program_.uniform("modelView"), 1, GL_FALSE, glm::value_ptr(modelView));
  glUniformMatrix4fv(program_.uniform("projection"), 1, GL_FALSE, glm::value_ptr(projection));
  glUniform3fv(program_.uniform("baseColour"), 1, glm::value_ptr(colour));
  glBindVertexArray(vao_);
  glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
}

}  // namespace sculpt::render
