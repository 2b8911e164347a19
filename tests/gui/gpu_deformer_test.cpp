// The GPU Phong deformer (vertex shader, read back by transform feedback) against the CPU
// reference of core/embed, on jittered tet and hex lattices, for linear, vertex, phong and
// attribute.
// Tolerance: 1e-5 of the bounding-box diagonal (single precision on the GPU).

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <random>

#include "embed/cell_coordinates.h"
#include "embed/cell_interpolant.h"
#include "embed/embedded_deformer.h"
#include "mesh/lattice_mesh.h"
#include "render/phong_gpu_deformer.h"
#include "support/cell_points.h"
#include "support/gl_context.h"

namespace sculpt {
namespace {

/// A hidden window with an OpenGL 3.3 core context for the test's lifetime.
class GpuPhongDeformer : public testing::GlContextTest {};

Eigen::Vector3d smoothMap(const Eigen::Vector3d& X) {
  return X + 0.15 * Eigen::Vector3d(std::sin(2 * X.y()) + X.z() * X.z(),
                                    std::cos(1.5 * X.z()) * X.x(),
                                    X.x() * X.y() - X.z() * X.z() * X.z());
}

TEST_F(GpuPhongDeformer, GpuAndCpuDeformersAgreeOnTetsAndHexesWithBothGradientSchemes) {
  LatticeSpec spec;
  spec.cubes = {5, 4, 4};
  spec.spacing = 0.25;
  for (bool hexahedra : {false, true}) {
    VolumeMesh mesh = hexahedra ? hexLattice(spec) : tetLattice(spec);
    jitterLattice(mesh, spec, 0.15, 3);
    // Points inside the cells, with random rest normals.
    std::mt19937 random(5);
    std::normal_distribution<double> gauss;
    const Points points = test::randomPointsInCells(mesh, 6, random);
    Points normals(points.rows(), 3);
    for (Eigen::Index row = 0; row < normals.rows(); ++row)
      normals.row(row) =
          Eigen::RowVector3d(gauss(random), gauss(random), gauss(random)).normalized();
    std::vector<Eigen::Matrix3d> averageGradients;
    for (GradientScheme scheme : {GradientScheme::Average, GradientScheme::Fit}) {
      DeformerSettings settings;
      settings.gradients = scheme;
      EmbeddedDeformer cpu(mesh, points, settings);
      std::vector<float> local, restNormals;
      for (uint32_t p = 0; p < cpu.numPoints(); ++p)
        for (int d = 0; d < 3; ++d) {
          local.push_back(static_cast<float>(cpu.embedding().local(p, d)));
          restNormals.push_back(static_cast<float>(normals(p, d)));
        }
      render::PhongGpuDeformer gpu(mesh, cpu.embedding().cells, local, restNormals);
      gpu.setAttributeNeighbours(
          attributeTransferWeights(mesh.positions, points, cpu.attributeRadius()));
      Points nodes(mesh.positions.rows(), 3);
      for (Eigen::Index i = 0; i < nodes.rows(); ++i)
        nodes.row(i) = smoothMap(mesh.positions.row(i).transpose()).transpose();
      const double diagonal = (nodes.colwise().maxCoeff() - nodes.colwise().minCoeff()).norm();
      cpu.setFrame(nodes, InterpolationMethod::Phong);  // node gradients for every alpha
      const std::vector<Eigen::Matrix3d> gradients = cpu.nodeGradients();
      // The schemes differ (at the boundary nodes): the comparison below is one per scheme.
      if (scheme == GradientScheme::Average)
        averageGradients = gradients;
      else {
        double largest = 0.0;
        for (size_t i = 0; i < gradients.size(); ++i)
          largest = std::max(largest, (gradients[i] - averageGradients[i]).norm());
        EXPECT_GT(largest, 1e-2);
      }
      std::vector<uint32_t> anchors(cpu.numPoints());
      for (uint32_t p = 0; p < cpu.numPoints(); ++p) anchors[p] = p;
      for (InterpolationMethod method :
           {InterpolationMethod::Linear, InterpolationMethod::Vertex, InterpolationMethod::Phong,
            InterpolationMethod::Attribute}) {
        cpu.setFrame(nodes, method);
        const Points expected = cpu.positions();
        const Points expectedNormals = cpu.deformNormals(normals, anchors);
        gpu.setFrame(nodes, gradients, method);
        // O(nodes): 12 floats per node, whatever the number of embedded vertices.
        EXPECT_EQ(gpu.frameUploadBytes(), 12 * sizeof(float) * mesh.numNodes());
        std::vector<float> positions, gpuNormals;
        gpu.capture(positions, gpuNormals);
        double worst = 0.0, worstNormal = 0.0;
        for (uint32_t p = 0; p < cpu.numPoints(); ++p) {
          const Eigen::Vector3d a(positions[3 * p], positions[3 * p + 1], positions[3 * p + 2]);
          const Eigen::Vector3d n(gpuNormals[3 * p], gpuNormals[3 * p + 1], gpuNormals[3 * p + 2]);
          worst = std::max(worst, (a - expected.row(p).transpose()).norm());
          worstNormal = std::max(worstNormal, (n - expectedNormals.row(p).transpose()).norm());
        }
        std::printf(
            "[ measured ] %s %s, %s gradients: position %.2e of the diagonal, normal %.2e\n",
            hexahedra ? "hexes" : "tets", std::string(methodName(method)).c_str(),
            std::string(gradientSchemeName(scheme)).c_str(), worst / diagonal, worstNormal);
        EXPECT_LT(worst / diagonal, 1e-5) << methodName(method);
        EXPECT_LT(worstNormal, 1e-4) << methodName(method);
      }
    }
  }
}

}  // namespace
}  // namespace sculpt
