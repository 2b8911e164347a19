#pragma once
// Draws a PlaneSlice (the section of the solid by the clipping plane) coloured by its field
// through the colour map (shaders/colour_map.glsl), unlit and two-sided. Needs a current GL 3.3
// context from construction to destruction.

#include <glm/glm.hpp>

#include "mesh/plane_slice.h"
#include "render/gl.h"
#include "render/shader_program.h"

namespace sculpt::render {

class SliceRenderer {
 public:
  SliceRenderer();
  ~SliceRenderer();
  SliceRenderer(const SliceRenderer&) = delete;
  SliceRenderer& operator=(const SliceRenderer&) = delete;

  /// Uploads positions, values and triangles (buffers reused while sizes stay the same).
  /// Throws std::invalid_argument when the arrays disagree (3 floats per position, one value
  /// per vertex, 3 indices per triangle, each below the vertex count).
  void setSlice(const PlaneSlice& slice);
  /// Draws with colour colourMap((value - low) / (high - low)); values outside [low, high] take
  /// the end colours, and low >= high gives the middle colour. Culling is switched off while
  /// drawing (the section is seen from both sides) and restored afterwards.
  void draw(const glm::mat4& view, const glm::mat4& projection, float low, float high) const;

  GLsizei numTriangles() const { return indexCount_ / 3; }

 private:
  ShaderProgram program_;
  GLuint vao_ = 0, positionBuffer_ = 0, valueBuffer_ = 0, indexBuffer_ = 0;
  GLsizei indexCount_ = 0;
  size_t positionBytes_ = 0, valueBytes_ = 0, indexBytes_ = 0;  ///< allocated sizes
};

}  // namespace sculpt::render
