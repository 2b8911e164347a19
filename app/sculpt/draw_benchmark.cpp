#include "sculpt/draw_benchmark.h"

#include <algorithm>
#include <chrono>
#include <vector>

#include "render/surface_renderer.h"

namespace sculpt::app {
namespace {

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values.empty() ? 0.0 : values[values.size() / 2];
}

template <typename Draw>
double timed(Draw draw) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glFinish();
  const auto start = std::chrono::steady_clock::now();
  draw();
  glFinish();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

DrawMeasurement measureDrawing(
    render::PhongGpuDeformer& deformer,
    const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& nodes,
    const std::vector<Eigen::Matrix3d>& gradients, InterpolationMethod method,
    std::span<const uint32_t> triangles, const glm::mat4& view, const glm::mat4& projection,
    int repetitions) {
  deformer.setFrame(nodes, gradients, method);
  std::vector<float> positions, normals;
  deformer.capture(positions, normals);
  render::SurfaceRenderer staticSurface;
  staticSurface.setTriangles(triangles);
  staticSurface.setVertices(positions, normals);
  const render::SurfaceStyle style;
  std::vector<double> deformed, still;
  glEnable(GL_DEPTH_TEST);
  const auto deformAndDraw = [&] {
    deformer.setFrame(nodes, gradients, method);
    deformer.draw(view, projection, style);
  };
  timed(deformAndDraw);  // warm up both paths
  timed([&] { staticSurface.draw(view, projection, style.colour); });
  for (int k = 0; k < repetitions; ++k) {
    deformed.push_back(timed(deformAndDraw));
    still.push_back(timed([&] { staticSurface.draw(view, projection, style.colour); }));
  }
  return {median(deformed), median(still)};
}

}  // namespace sculpt::app
