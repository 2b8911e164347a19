// sculpt-cli deform with rest meshes in either orientation convention (re-oriented with a note,
// the same surface as the positively oriented mesh) and with simulation frames that fold some
// cells (deformed anyway; the same mesh as REST is refused).

#include "app/deform_cli_fixture.h"

namespace sculpt {
namespace {

using namespace deform_cli;

TEST_F(DeformCliTest, NegativelyOrientedAndMixedRestMeshesGiveTheSameSurface) {
  // Other programs order cell nodes for the other orientation: every cell mirrored, or some.
  const SurfaceMesh surface = sphereSurface({0.5, 0.5, 0.5}, 0.4, 12, 16);
  for (bool hexahedra : {false, true}) {
    const VolumeMesh positive = unitLattice(hexahedra);
    writeScene(positive, surface, bend);
    const SurfaceMesh reference = deform("", "positive.obj");
    for (bool everyCell : {true, false}) {
      SCOPED_TRACE(std::string(hexahedra ? "hexahedra" : "tetrahedra") +
                   (everyCell ? ", every cell mirrored" : ", every other cell mirrored"));
      VolumeMesh mirrored = positive;
      for (uint32_t c = 0; c < mirrored.numCells(); c += everyCell ? 1 : 2) {
        uint32_t* nodes = mirrored.cells.values.data() + mirrored.cells.offsets[c];
        if (hexahedra)
          std::swap_ranges(nodes, nodes + 4, nodes + 4);
        else
          std::swap(nodes[1], nodes[2]);
      }
      writeScene(mirrored, surface, bend);
      CliResult result;
      const SurfaceMesh out = deform("", "mirrored.obj", &result);
      const uint32_t expected = everyCell ? positive.numCells() : (positive.numCells() + 1) / 2;
      EXPECT_NE(result.err.find("note: " + path("rest.vtk") + ": " + std::to_string(expected) +
                                " of " + std::to_string(positive.numCells()) +
                                " cells are negatively oriented"),
                std::string::npos)
          << result.err;
      EXPECT_LT(maxRowDistance(out.positions, reference.positions), 1e-12);
      ASSERT_EQ(out.normals.rows(), reference.normals.rows());
      EXPECT_LT(maxRowDistance(out.normals, reference.normals), 1e-12);
    }
  }
  // A flat cell is still refused: re-orienting cannot give it a volume.
  VolumeMesh flat = unitLattice(false);
  flat.positions.row(flat.cells.row(0)[3]) = flat.positions.row(flat.cells.row(0)[0]) +
                                             0.5 * (flat.positions.row(flat.cells.row(0)[1]) -
                                                    flat.positions.row(flat.cells.row(0)[0]));
  writeScene(flat, surface, bend);
  expectBadInput(sceneArgs() + " --out " + quote(path("flat.obj")), "rest.vtk");
}

// A simulation frame may contain inverted cells (a rest mesh may not): the frame is deformed
// anyway, with finite output, while the same mesh as REST is refused.
TEST_F(DeformCliTest, DeformedFramesMayContainInvertedCells) {
  const VolumeMesh rest = unitLattice();
  const SurfaceMesh surface = sphereSurface({0.5, 0.5, 0.5}, 0.3);
  writeScene(rest, surface, affine);
  VolumeMesh folded = mapped(rest, affine);
  // Push one interior node through its neighbours: several of its tetrahedra invert.
  const uint32_t node = 2 + 5 * (2 + 5 * 2);
  folded.positions.row(node) += Eigen::RowVector3d(0.6, 0.0, 0.0);
  bool inverted = false;
  for (uint32_t c = 0; c < folded.numCells(); ++c)
    inverted = inverted || tetrahedronSignedVolume(folded, c) < 0.0;
  ASSERT_TRUE(inverted);
  writeVtkVolumeMesh(path("folded.vtk"), folded, false);
  const CliResult result =
      run(sceneArgs("folded.vtk") + " --out " + quote(path("folded.obj")));
  EXPECT_EQ(result.exitCode, 0) << result.err;
  const SurfaceMesh out = readSurfaceFile(path("folded.obj")).surface();
  EXPECT_EQ(out.numVertices(), surface.numVertices());
  EXPECT_TRUE(out.positions.allFinite());
  expectBadInput("deform --rest " + quote(path("folded.vtk")) + " --deformed " +
                     quote(path("folded.vtk")) + " --surface " + quote(path("surface.obj")) +
                     " --out " + quote(path("x.obj")),
                 "inverted");
}

}  // namespace
}  // namespace sculpt
