#pragma once
// Measures what drawing the Phong-deformed surface costs against drawing the same triangles from
// a static vertex buffer (positions and normals captured from the deformer once), interleaved in
// one run so that machine noise affects both alike. Used by `sculpt --bench N`.

#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include <glm/glm.hpp>

#include "render/phong_gpu_deformer.h"

namespace sculpt::app {

struct DrawMeasurement {
  double deformedMs = 0;  ///< median of setFrame (upload) + deformation pass + draw + glFinish
  double staticMs = 0;    ///< median of draw + glFinish from a static buffer
  double ratio() const { return staticMs > 0 ? deformedMs / staticMs : 0; }
};

/// Draws `repetitions` times each way into the bound framebuffer (cleared each time). Every
/// deformed draw starts from a new frame (setFrame with these nodes and gradients), so that the
/// deformation pass runs each time as it does when the simulation publishes a state per frame.
DrawMeasurement measureDrawing(
    render::PhongGpuDeformer& deformer,
    const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& nodes,
    const std::vector<Eigen::Matrix3d>& gradients, InterpolationMethod method,
    std::span<const uint32_t> triangles, const glm::mat4& view, const glm::mat4& projection,
    int repetitions);

}  // namespace sculpt::app
