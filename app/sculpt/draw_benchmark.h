#pragma once
// Measures what drawing the Phong-deformed surface costs against drawing the same triangles from
// a static vertex buffer (positions and normals captured from the deformer once), interleaved in
// one run so that machine noise affects both alike. Used by `sculpt --bench N`.

#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include "render/phong_gpu_deformer.h"

namespace sculpt::app {

struct DrawMeasurement {
  double deformedMs = 0;  ///< median of draw + glFinish with deformation in the vertex shader
  double staticMs = 0;    ///< median of draw + glFinish from a static buffer
  double ratio() const { return staticMs > 0 ? deformedMs / staticMs : 0; }
};

/// Draws `repetitions` times each way into the bound framebuffer (cleared each time).
DrawMeasurement measureDrawing(const render::PhongGpuDeformer& deformer,
                               std::span<const uint32_t> triangles, const glm::mat4& view,
                               const glm::mat4& projection, int repetitions);

}  // namespace sculpt::app
