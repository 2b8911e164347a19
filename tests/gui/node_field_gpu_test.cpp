// The smooth field on the GPU (phong_deform.vert, fieldMode 3: sum_a beta_a v_a over the cell's
// nodes) against the same sum on the CPU from the embedding's cell and local coordinates, on
// jittered tet and hex lattices; and the flat per-cell field, which is the cell's value exactly.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "embed/cell_coordinates.h"
#include "embed/embedded_deformer.h"
#include "embed/node_field.h"
#include "mesh/lattice_mesh.h"
#include "render/phong_gpu_deformer.h"
#include "support/cell_points.h"
#include "support/gl_context.h"

namespace sculpt {
namespace {

class GpuNodeField : public testing::GlContextTest {};

TEST_F(GpuNodeField, SmoothValuesAreTheCellInterpolantOfTheNodeValuesAndPerCellTheCellsOwn) {
  LatticeSpec spec;
  spec.cubes = {5, 4, 3};
  spec.spacing = 0.25;
  for (bool hexahedra : {false, true}) {
    VolumeMesh mesh = hexahedra ? hexLattice(spec) : tetLattice(spec);
    jitterLattice(mesh, spec, 0.15, 11);
    std::mt19937 random(3);
    const Points points = test::randomPointsInCells(mesh, 4, random);
    const EmbeddedDeformer cpu(mesh, points, DeformerSettings{});
    const Embedding& embedding = cpu.embedding();
    std::vector<float> local;
    for (uint32_t p = 0; p < embedding.numPoints(); ++p)
      for (int d = 0; d < 3; ++d) local.push_back(static_cast<float>(embedding.local(p, d)));
    const std::vector<float> restNormals(local.size(), 0.0f);
    render::PhongGpuDeformer gpu(mesh, embedding.cells, local, restNormals);
    gpu.setFrame(mesh.positions, {}, InterpolationMethod::Linear);

    // A stripe of stiff cells (3e8 Pa) across a soft block (3e6 Pa), as a painted modulus.
    std::vector<float> cellValues(mesh.numCells());
    for (uint32_t c = 0; c < mesh.numCells(); ++c)
      cellValues[c] = std::abs(cellCentroid(mesh, c).x() - 0.6) < 0.2 ? 3e8f : 3e6f;
    std::vector<float> nodeValues;
    nodeFieldFromCells(nodeFieldWeights(mesh), cellValues, nodeValues);
    gpu.setNodeField(nodeValues);
    gpu.setCellField(cellValues);

    std::vector<float> smooth, perCellValues;
    gpu.captureField(render::SurfaceField::PerNode, smooth);
    gpu.captureField(render::SurfaceField::PerCell, perCellValues);
    ASSERT_EQ(smooth.size(), embedding.numPoints());
    double worst = 0.0;
    int between = 0;  // vertices whose value lies strictly between the two moduli
    for (uint32_t p = 0; p < embedding.numPoints(); ++p) {
      const uint32_t cell = embedding.cells[p];
      double beta[8];
      const int count =
          cellNodeWeights(mesh.isTetrahedron(cell), embedding.local.row(p).transpose(), beta);
      double expected = 0.0;
      for (int a = 0; a < count; ++a) expected += beta[a] * nodeValues[mesh.cells.row(cell)[a]];
      worst = std::max(worst, std::abs(smooth[p] - expected) / 3e8);
      between += smooth[p] > 3.1e6f && smooth[p] < 2.9e8f;
      ASSERT_EQ(perCellValues[p], cellValues[cell]) << "vertex " << p;
    }
    std::printf(
        "[ measured ] %s: GPU smooth field within %.2e of the range of the CPU's, %d of %u "
        "vertices between the two moduli\n",
        hexahedra ? "hexes" : "tets", worst, between, embedding.numPoints());
    EXPECT_LT(worst, 1e-6) << "float precision";
    EXPECT_GT(between, static_cast<int>(embedding.numPoints() / 10)) << "the field is smooth";
  }
}

}  // namespace
}  // namespace sculpt
