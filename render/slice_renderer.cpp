#include "render/slice_renderer.h"

#include <stdexcept>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "render/gl_buffers.h"
#include "shader_sources.h"

namespace sculpt::render {
namespace {

/// Replaces a buffer's contents, reallocating only when the size changes.
template <typename T>
void fill(GLenum target, GLuint buffer, const std::vector<T>& data, size_t& allocatedBytes) {
  glBindBuffer(target, buffer);
  const size_t bytes = data.size() * sizeof(T);
  if (bytes == allocatedBytes)
    glBufferSubData(target, 0, static_cast<GLsizeiptr>(bytes), data.data());
  else
    glBufferData(target, static_cast<GLsizeiptr>(bytes), data.data(), GL_DYNAMIC_DRAW);
  allocatedBytes = bytes;
}

void checkSlice(const PlaneSlice& slice) {
  const size_t numVertices = slice.values.size();
  if (slice.positions.size() != 3 * numVertices || slice.triangles.size() % 3 != 0)
    throw std::invalid_argument(
        "SliceRenderer::setSlice: " + std::to_string(slice.positions.size()) + " coordinates, " +
        std::to_string(numVertices) + " values and " + std::to_string(slice.triangles.size()) +
        " indices do not make a triangle mesh");
  for (uint32_t index : slice.triangles)
    if (index >= numVertices)
      throw std::invalid_argument("SliceRenderer::setSlice: vertex index " + std::to_string(index) +
                                  " beyond the " + std::to_string(numVertices) + " vertices");
}

}  // namespace

SliceRenderer::SliceRenderer()
    : program_("slice", shaders::kSliceVert,
               shaderSource({shaders::kColourMapGlsl}, shaders::kSliceFrag).c_str()) {
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &indexBuffer_);
  glBindVertexArray(vao_);
  positionBuffer_ = floatAttribute(0, 3);
  valueBuffer_ = floatAttribute(1, 1);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

SliceRenderer::~SliceRenderer() {
  glDeleteBuffers(1, &indexBuffer_);
  glDeleteBuffers(1, &valueBuffer_);
  glDeleteBuffers(1, &positionBuffer_);
  glDeleteVertexArrays(1, &vao_);
}

void SliceRenderer::setSlice(const PlaneSlice& slice) {
  checkSlice(slice);
  fill(GL_ARRAY_BUFFER, positionBuffer_, slice.positions, positionBytes_);
  fill(GL_ARRAY_BUFFER, valueBuffer_, slice.values, valueBytes_);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindVertexArray(vao_);  // the element array binding is part of the vertex array
  fill(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_, slice.triangles, indexBytes_);
  glBindVertexArray(0);
  indexCount_ = static_cast<GLsizei>(slice.triangles.size());
}

void SliceRenderer::draw(const glm::mat4& view, const glm::mat4& projection, float low,
                         float high) const {
  if (indexCount_ == 0) return;
  program_.use();
  glUniformMatrix4fv(program_.uniform("view"), 1, GL_FALSE, glm::value_ptr(view));
  glUniformMatrix4fv(program_.uniform("projection"), 1, GL_FALSE, glm::value_ptr(projection));
  glUniform1f(program_.uniform("low"), low);
  glUniform1f(program_.uniform("high"), high);
  const GLboolean culling = glIsEnabled(GL_CULL_FACE);
  glDisable(GL_CULL_FACE);
  glBindVertexArray(vao_);
  glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
  if (culling) glEnable(GL_CULL_FACE);
}

}  // namespace sculpt::render
