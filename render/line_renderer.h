#pragma once
// Draws coloured line segments (GL_LINES) and points (GL_POINTS, round, a size in pixels): the
// overlays of the sculpt window. Vertex data can be replaced every frame; buffers are reused
// (glBufferSubData) while their size stays the same. Needs a current GL 3.3 context from
// construction to destruction.

#include <span>

#include <glm/glm.hpp>

#include "render/gl.h"
#include "render/shader_program.h"

namespace sculpt::render {

class LineRenderer {
 public:
  LineRenderer();
  ~LineRenderer();
  LineRenderer(const LineRenderer&) = delete;
  LineRenderer& operator=(const LineRenderer&) = delete;

  /// Segments: xyz per vertex, two vertices per segment; rgb per vertex (linear [0,1]).
  /// Throws std::invalid_argument when the sizes are not 3 floats per vertex, an even vertex
  /// count, and one colour per position.
  void setLines(std::span<const float> xyz, std::span<const float> rgb);
  /// Points: xyz and rgb per vertex (same checks, any vertex count).
  void setPoints(std::span<const float> xyz, std::span<const float> rgb);
  /// Empties both lists.
  void clear();

  /// Lines first, then points `pointSizePixels` across (with GL_PROGRAM_POINT_SIZE enabled).
  /// Depth test and blending are left as the caller set them.
  void draw(const glm::mat4& view, const glm::mat4& projection, float pointSizePixels) const;

  GLsizei numLineVertices() const { return lines_.count; }
  GLsizei numPoints() const { return points_.count; }

 private:
  /// A vertex array with a position and a colour buffer.
  struct Batch {
    GLuint vao = 0, positions = 0, colours = 0;
    GLsizei count = 0;
    size_t bytes = 0;  ///< allocated size of each buffer
  };
  static void create(Batch& batch);
  static void destroy(Batch& batch);
  static void upload(Batch& batch, std::span<const float> xyz, std::span<const float> rgb);

  ShaderProgram program_;
  Batch lines_, points_;
};

}  // namespace sculpt::render
