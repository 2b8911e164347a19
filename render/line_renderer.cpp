#include "render/line_renderer.h"

#include <stdexcept>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "render/gl_buffers.h"
#include "shader_sources.h"

namespace sculpt::render {
namespace {

void checkSizes(const char* what, std::span<const float> xyz, std::span<const float> rgb,
                size_t verticesPerPrimitive) {
  if (xyz.size() % (3 * verticesPerPrimitive) != 0 || rgb.size() != xyz.size())
    throw std::invalid_argument(std::string("LineRenderer::") + what + ": " +
                                std::to_string(xyz.size()) + " coordinates and " +
                                std::to_string(rgb.size()) + " colour components; expected 3 per " +
                                "vertex, the same count of each" +
                                (verticesPerPrimitive == 2 ? ", two vertices per segment" : ""));
}

/// Replaces a buffer's contents, reallocating only when the size changes.
void fill(GLuint buffer, std::span<const float> data, bool sameSize) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  const auto bytes = static_cast<GLsizeiptr>(data.size_bytes());
  if (sameSize)
    glBufferSubData(GL_ARRAY_BUFFER, 0, bytes, data.data());
  else
    glBufferData(GL_ARRAY_BUFFER, bytes, data.data(), GL_DYNAMIC_DRAW);
}

}  // namespace

LineRenderer::LineRenderer() : program_("lines", shaders::kLinesVert, shaders::kLinesFrag) {
  create(lines_);
  create(points_);
}

LineRenderer::~LineRenderer() {
  destroy(points_);
  destroy(lines_);
}

void LineRenderer::create(Batch& batch) {
  glGenVertexArrays(1, &batch.vao);
  glBindVertexArray(batch.vao);
  batch.positions = floatAttribute(0, 3);
  batch.colours = floatAttribute(1, 3);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void LineRenderer::destroy(Batch& batch) {
  glDeleteBuffers(1, &batch.colours);
  glDeleteBuffers(1, &batch.positions);
  glDeleteVertexArrays(1, &batch.vao);
}

void LineRenderer::upload(Batch& batch, std::span<const float> xyz, std::span<const float> rgb) {
  const bool sameSize = xyz.size_bytes() == batch.bytes;
  fill(batch.positions, xyz, sameSize);
  fill(batch.colours, rgb, sameSize);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  batch.bytes = xyz.size_bytes();
  batch.count = static_cast<GLsizei>(xyz.size() / 3);
}

void LineRenderer::setLines(std::span<const float> xyz, std::span<const float> rgb) {
  checkSizes("setLines", xyz, rgb, 2);
  upload(lines_, xyz, rgb);
}

void LineRenderer::setPoints(std::span<const float> xyz, std::span<const float> rgb) {
  checkSizes("setPoints", xyz, rgb, 1);
  upload(points_, xyz, rgb);
}

void LineRenderer::clear() {
  lines_.count = 0;
  points_.count = 0;
}

void LineRenderer::draw(const glm::mat4& view, const glm::mat4& projection,
                        float pointSizePixels) const {
  if (lines_.count == 0 && points_.count == 0) return;
  program_.use();
  glUniformMatrix4fv(program_.uniform("view"), 1, GL_FALSE, glm::value_ptr(view));
  glUniformMatrix4fv(program_.uniform("projection"), 1, GL_FALSE, glm::value_ptr(projection));
  glUniform1f(program_.uniform("pointSize"), pointSizePixels);
  if (lines_.count > 0) {
    glUniform1i(program_.uniform("roundPoints"), 0);
    glBindVertexArray(lines_.vao);
    glDrawArrays(GL_LINES, 0, lines_.count);
  }
  if (points_.count > 0) {
    glEnable(GL_PROGRAM_POINT_SIZE);
    glUniform1i(program_.uniform("roundPoints"), 1);
    glBindVertexArray(points_.vao);
    glDrawArrays(GL_POINTS, 0, points_.count);
  }
  glBindVertexArray(0);
}

}  // namespace sculpt::render
