#pragma once
// Draws a triangle surface with per-vertex normals (Blinn-Phong, two lights). Positions and
// normals can be replaced every frame (the CPU deformation path); topology is uploaded once.

#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include "render/gl.h"
#include "render/shader_program.h"

namespace sculpt::render {

class SurfaceRenderer {
 public:
  SurfaceRenderer();
  ~SurfaceRenderer();
  SurfaceRenderer(const SurfaceRenderer&) = delete;
  SurfaceRenderer& operator=(const SurfaceRenderer&) = delete;

  /// Triangle indices (3 per triangle) into the vertex arrays.
  void setTriangles(std::span<const uint32_t> indices);
  /// xyz per vertex, positions and normals of the same count.
  void setVertices(std::span<const float> positions, std::span<const float> normals);
  void draw(const glm::mat4& modelView, const glm::mat4& projection, const glm::vec3& colour) const;

 private:
  ShaderProgram program_;
  GLuint vao_ = 0, positionBuffer_ = 0, normalBuffer_ = 0, indexBuffer_ = 0;
  GLsizei indexCount_ = 0;
};

}  // namespace sculpt::render
