// sculpt-cli deform end to end: a surface embedded in a tet (or hex) lattice written as VTK is
// moved by a deformed copy of the lattice. Affine maps are reproduced exactly (positions and
// cofactor normals) by linear, vertex and phong; phong beats linear on a bend; frame sequences,
// mismatched meshes, malformed files and points outside the mesh are handled without a crash.


#include "app/deform_cli_fixture.h"

namespace sculpt {
namespace {

using namespace deform_cli;
using test::CliResult;
using test::quote;

TEST_F(DeformCliTest, HelpListsDeform) {
  const CliResult help = run("--help");
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_NE(help.out.find("deform --rest REST --deformed DEF"), std::string::npos);
  const CliResult own = run("deform --help");
  EXPECT_EQ(own.exitCode, 0);
  EXPECT_NE(own.out.find("--normals analytic|recompute|keep"), std::string::npos);
}

TEST_F(DeformCliTest, AffineMapIsReproducedByTheGradientMethods) {
  const SurfaceMesh surface = sphereSurface({0.5, 0.5, 0.5}, 0.3);
  const Points expected = mappedPoints(surface.positions, affine);
  for (bool hexahedra : {false, true}) {
    writeScene(unitLattice(hexahedra), surface, affine);
    for (const char* method : {"phong", "linear", "vertex"})
    for (const char* gradients : {"fit", "average"}) {
      SCOPED_TRACE(std::string(method) + (hexahedra ? " on hexahedra" : " on tetrahedra") +
                   ", gradients " + gradients);
      CliResult result;
      const SurfaceMesh out = deform(
          std::string("--method ") + method + " --gradients " + gradients, "out.obj", &result);
      ASSERT_EQ(out.numVertices(), surface.numVertices());
      EXPECT_EQ(result.lastLine(), "deformed=1 vertices=" + std::to_string(surface.numVertices()) +
                                       " outside=0 method=" + method + " gradients=" + gradients);
      EXPECT_TRUE(result.errLines().empty()) << result.err;
      // Same vertices in the same order, at the affine image.
      EXPECT_LT(maxRowDistance(out.positions, expected), 1e-9);
      // Normals: cof(A) N, normalised.
      ASSERT_EQ(out.normals.rows(), surface.normals.rows());
      for (Eigen::Index j = 0; j < out.normals.rows(); ++j)
        EXPECT_LT(
            (out.normals.row(j).transpose() - cofactorNormal(surface.normals.row(j).transpose()))
                .norm(),
            1e-9)
            << "normal " << j;
      // Texture coordinates and faces untouched.
      EXPECT_EQ(out.texcoords, surface.texcoords);
      ASSERT_EQ(out.faces.values.size(), surface.faces.values.size());
      EXPECT_EQ(out.faces.offsets, surface.faces.offsets);
      for (size_t c = 0; c < out.faces.values.size(); ++c) {
        EXPECT_EQ(out.faces.values[c].position, surface.faces.values[c].position);
        EXPECT_EQ(out.faces.values[c].normal, surface.faces.values[c].normal);
        EXPECT_EQ(out.faces.values[c].texcoord, surface.faces.values[c].texcoord);
      }
    }
  }
}

TEST_F(DeformCliTest, DefaultIsPhongAndAttributeIsCloseWithRecomputedNormals) {
  const SurfaceMesh surface = sphereSurface({0.5, 0.5, 0.5}, 0.3);
  writeScene(unitLattice(), surface, affine);
  CliResult result;
  const SurfaceMesh phong = deform("", "phong.obj", &result);
  EXPECT_NE(result.lastLine().find("method=phong gradients=fit"), std::string::npos);
  EXPECT_LT(maxRowDistance(phong.positions, mappedPoints(surface.positions, affine)), 1e-9);

  // The attribute method is only first-order: close to the map, not exact. Its normals are the
  // area-weighted normals of its own deformed faces.
  const SurfaceMesh attribute = deform("--method attribute", "attribute.obj", &result);
  EXPECT_NE(result.lastLine().find("method=attribute"), std::string::npos);
  ASSERT_EQ(attribute.numVertices(), surface.numVertices());
  EXPECT_LT(maxRowDistance(attribute.positions, mappedPoints(surface.positions, affine)), 0.05);
  const std::vector<uint32_t> anchors = normalAnchors(surface);
  EXPECT_LT(
      maxRowDistance(attribute.normals, recomputedNormals(surface, attribute.positions, anchors)),
      1e-9);
  // An explicit radius is accepted.
  deform("--method attribute --radius 0.5", "attribute_r.obj");
}

TEST_F(DeformCliTest, NormalModes) {
  const SurfaceMesh surface = sphereSurface({0.5, 0.5, 0.5}, 0.3);
  writeScene(unitLattice(), surface, affine);
  const std::vector<uint32_t> anchors = normalAnchors(surface);

  // keep: the file's normals.
  const SurfaceMesh kept = deform("--normals keep", "keep.obj");
  EXPECT_EQ(kept.normals, surface.normals);

  // recompute: under an affine map the area vectors move with cof(A), so the recomputed normal
  // is cof(A) applied to the rest one.
  const SurfaceMesh recomputed = deform("--normals recompute", "recompute.obj");
  const Points restRecomputed = recomputedNormals(surface, surface.positions, anchors);
  ASSERT_EQ(recomputed.normals.rows(), restRecomputed.rows());
  for (Eigen::Index j = 0; j < restRecomputed.rows(); ++j) {
    EXPECT_LT(
        (recomputed.normals.row(j).transpose() - cofactorNormal(restRecomputed.row(j).transpose()))
            .norm(),
        1e-9);
    // Close to the sphere's own normals at rest.
    EXPECT_GT(restRecomputed.row(j).dot(surface.normals.row(j)), 0.95);
  }
}

TEST_F(DeformCliTest, RecomputedNormalsKeepFlatShadingAndFileOrientation) {
  // A box whose 6 normals each belong to one face: recomputing must give the face normals, not
  // the smooth normals of the anchor corner.
  SurfaceMesh box = boxSurface({0.2, 0.3, 0.25}, {0.7, 0.6, 0.8});
  writeScene(unitLattice(), box, affine);
  const SurfaceMesh out = deform("--normals recompute", "box.obj");
  ASSERT_EQ(out.normals.rows(), 6);
  for (Eigen::Index j = 0; j < 6; ++j)
    EXPECT_LT(
        (out.normals.row(j).transpose() - cofactorNormal(box.normals.row(j).transpose())).norm(),
        1e-10)
        << "normal " << j;

  // Inward normals (a file with the opposite convention) stay inward.
  box.normals = -box.normals;
  const Points moved = mappedPoints(box.positions, affine);
  const Points inward = recomputedNormals(box, moved, normalAnchors(box));
  for (Eigen::Index j = 0; j < 6; ++j)
    EXPECT_LT((inward.row(j).transpose() - cofactorNormal(box.normals.row(j).transpose())).norm(),
              1e-10);
  // Collapsed faces keep the rest normal.
  const Points collapsed = recomputedNormals(box, Points::Zero(8, 3), normalAnchors(box));
  EXPECT_EQ(collapsed, box.normals);
}

TEST_F(DeformCliTest, PhongBeatsLinearOnABend) {
  const double linear = bendError(0.35, "--method linear", "linear.obj");
  const double phong = bendError(0.35, "--method phong", "phong.obj");
  EXPECT_GT(linear, 1e-4);  // the bend is not affine
  EXPECT_LT(phong, 0.5 * linear) << "phong " << phong << " linear " << linear;
}

TEST_F(DeformCliTest, FitGradientsBeatTheAverageNearTheMeshBoundary) {
  // A sphere nearly touching the unit cube's faces: most of it lies in boundary cells, where the
  // averaged node gradients are one-sided and the fitted ones are not.
  const double average = bendError(0.48, "--gradients average", "average.obj");
  const double fit = bendError(0.48, "--gradients fit", "fit.obj");
  std::printf("[ measured ] rms error near the boundary: average %.3e, fit %.3e (%.1fx)\n", average,
              fit, average / fit);
  EXPECT_LT(fit, 0.5 * average);
}

TEST_F(DeformCliTest, FrameSequence) {
  const VolumeMesh rest = unitLattice();
  const SurfaceMesh surface = sphereSurface({0.5, 0.5, 0.5}, 0.3);
  writeVtkVolumeMesh(path("rest.vtk"), rest, false);
  writeObjSurface(path("surface.obj"), surface);
  fs::create_directories(dir_ / "frames");
  // Frame k moves everything by (k, 0, 0) after the affine map.
  const auto frameMap = [](int k) {
    return [k](const Eigen::Vector3d& X) -> Eigen::Vector3d {
      return affine(X) + Eigen::Vector3d(k, 0, 0);
    };
  };
  for (int k = 1; k <= 3; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "frames/sim_%04d.vtk", k);
    writeVtkVolumeMesh(path(name), mapped(rest, frameMap(k)), false);
  }
  writeText(path("frames/sim_12.vtk"), "not a frame");    // too few digits: not matched
  writeText(path("frames/sim_0002.txt"), "not a frame");  // other suffix
  const std::string base = "deform --rest " + quote(path("rest.vtk")) + " --surface " +
                           quote(path("surface.obj")) + " --deformed " +
                           quote(path("frames/sim_####.vtk"));

  CliResult result = run(base + " --out " + quote(path("out_####.obj")));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_EQ(result.lastLine(), "deformed=3 vertices=" + std::to_string(surface.numVertices()) +
                                   " outside=0 method=phong gradients=fit");
  const auto lines = result.errLines();
  ASSERT_EQ(lines.size(), 3u) << result.err;
  for (int k = 1; k <= 3; ++k) {
    const std::string number = "000" + std::to_string(k);
    EXPECT_EQ(lines[k - 1], "frame " + std::to_string(k) +
                                "/3: " + path("frames/sim_" + number + ".vtk") + " -> " +
                                path("out_" + number + ".obj"));
    const SurfaceMesh out = readSurfaceFile(path("out_" + number + ".obj")).surface();
    EXPECT_LT(maxRowDistance(out.positions, mappedPoints(surface.positions, frameMap(k))), 1e-9);
  }

  // A missing frame in the middle: a warning, the others are done.
  fs::remove(path("frames/sim_0002.vtk"));
  result = run(base + " --out " + quote(path("gap_##.glb")));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_NE(result.lastLine().find("deformed=2 "), std::string::npos) << result.out;
  EXPECT_NE(result.err.find("warning: frame 2 is missing"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("frame 3/3: "), std::string::npos) << result.err;
  EXPECT_TRUE(fs::exists(path("gap_01.glb")));
  EXPECT_FALSE(fs::exists(path("gap_02.glb")));
  EXPECT_TRUE(fs::exists(path("gap_03.glb")));

  // A sequence needs a '#' run in OUT; a pattern that matches nothing is an error.
  expectBadInput(base + " --out " + quote(path("single.obj")), "needs a run of '#'");
  expectBadInput("deform --rest " + quote(path("rest.vtk")) + " --surface " +
                     quote(path("surface.obj")) + " --deformed " +
                     quote(path("frames/none_###.vtk")) + " --out " + quote(path("o_#.obj")),
                 "no frame file");
  expectBadInput(base + " --out " + quote(path("o_#_#.obj")), "more than one run of '#'");
}

TEST_F(DeformCliTest, MismatchedMeshesAreExit2NamingTheMismatch) {
  const VolumeMesh rest = unitLattice();
  const SurfaceMesh surface = sphereSurface({0.5, 0.5, 0.5}, 0.3);
  writeScene(rest, surface, affine);
  const std::string out = " --out " + quote(path("out.obj"));

  // Different node count.
  LatticeSpec bigger;
  bigger.cubes = {5, 4, 4};
  bigger.spacing = 0.25;
  writeVtkVolumeMesh(path("bigger.vtk"), tetLattice(bigger), false);
  expectBadInput(
      sceneArgs("bigger.vtk") + out,
      path("bigger.vtk") + ": 150 nodes but the rest mesh " + path("rest.vtk") + " has 125");

  // Same nodes, cell 17 listed in another (even, so still positive) order.
  VolumeMesh reordered = mapped(rest, affine);
  uint32_t* cell = reordered.cells.values.data() + reordered.cells.offsets[17];
  std::rotate(cell, cell + 1, cell + 3);  // (a b c d) -> (b c a d)
  writeVtkVolumeMesh(path("reordered.vtk"), reordered, false);
  expectBadInput(sceneArgs("reordered.vtk") + out,
                 path("reordered.vtk") + ": cell 17 differs from the rest mesh");

  // One cell more.
  VolumeMesh extra = mapped(rest, affine);
  extra.addTetrahedron({0, 1, 6, 31});
  writeVtkVolumeMesh(path("extra.vtk"), extra, false);
  expectBadInput(sceneArgs("extra.vtk") + out, ": 385 cells but the rest mesh");
  EXPECT_FALSE(fs::exists(path("out.obj")));
}

TEST_F(DeformCliTest, MalformedInputIsOneErrorLine) {
  const SurfaceMesh surface = sphereSurface({0.5, 0.5, 0.5}, 0.3);
  writeScene(unitLattice(), surface, affine);
  const std::string out = " --out " + quote(path("out.obj"));
  const std::string rest = " --rest " + quote(path("rest.vtk"));
  const std::string deformed = " --deformed " + quote(path("deformed.vtk"));
  const std::string obj = " --surface " + quote(path("surface.obj"));

  // Missing files.
  expectBadInput("deform --rest " + quote(path("none.vtk")) + deformed + obj + out, "none.vtk");
  expectBadInput("deform" + rest + " --deformed " + quote(path("none.vtk")) + obj + out,
                 "none.vtk");
  expectBadInput("deform" + rest + deformed + " --surface " + quote(path("none.obj")) + out,
                 "none.obj");

  // Truncated VTK, as rest and as deformed mesh.
  const std::string vtk = readText(path("deformed.vtk"));
  for (size_t length : {size_t{0}, size_t{30}, vtk.size() / 3, vtk.size() - 20}) {
    const std::string name = "truncated_" + std::to_string(length) + ".vtk";
    writeText(path(name), vtk.substr(0, length));
    expectBadInput("deform --rest " + quote(path(name)) + deformed + obj + out, name);
    expectBadInput("deform" + rest + " --deformed " + quote(path(name)) + obj + out, name);
  }

  // Bad OBJ files.
  const std::vector<std::string> badObj = {"", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n",
                                           "v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
                                           "v 0 0\nf 1 1 1\n", std::string(1000, '\xff')};
  for (size_t i = 0; i < badObj.size(); ++i) {
    const std::string name = "bad_" + std::to_string(i) + ".obj";
    writeText(path(name), badObj[i]);
    expectBadInput("deform" + rest + deformed + " --surface " + quote(path(name)) + out, name);
  }
  writeText(path("bad.glb"), "glTF\x02garbage");
  expectBadInput("deform" + rest + deformed + " --surface " + quote(path("bad.glb")) + out,
                 "bad.glb");

  // Bad options.
  const std::string scene = "deform" + rest + deformed + obj;
  expectBadInput(scene, "--out is required");
  expectBadInput("deform" + rest + obj + out, "--deformed is required");
  expectBadInput(scene + " --eps -1" + out, "--eps");
  expectBadInput(scene + " --eps nan" + out, "--eps");
  expectBadInput(scene + " --radius 0" + out, "--radius");
  expectBadInput(scene + " --radius -2 --method attribute" + out, "--radius");
  expectBadInput(scene + " --radius inf --method attribute" + out, "--radius");
  expectBadInput(scene + " --method cubic" + out, "unknown method 'cubic'");
  expectBadInput(scene + " --gradients quadratic" + out, "unknown scheme 'quadratic'");
  expectBadInput(scene + " --normals smooth" + out, "unknown mode 'smooth'");
  expectBadInput(scene + " --out " + quote(path("out.stl")), "unknown extension");
  expectBadInput(scene + " extra" + out, "no positional argument");
  EXPECT_FALSE(fs::exists(path("out.obj")));
}

TEST_F(DeformCliTest, AttributeRadiusThatWouldExhaustMemoryIsRefused) {
  // 9261 nodes and 29802 points: a radius around everything would weigh 2.8e8 pairs.
  LatticeSpec spec;
  spec.cubes = {20, 20, 20};
  spec.spacing = 0.05;
  writeScene(tetLattice(spec), sphereSurface({0.5, 0.5, 0.5}, 0.3, 150, 200), affine);
  expectBadInput(sceneArgs() + " --method attribute --radius 1e9 --out " + quote(path("o.obj")),
                 "use a smaller radius");
  EXPECT_FALSE(fs::exists(path("o.obj")));
}

TEST_F(DeformCliTest, GlbOutputLoadsBackWithTheSameVertices) {
  const SurfaceMesh surface = sphereSurface({0.5, 0.5, 0.5}, 0.3);
  writeScene(unitLattice(), surface, affine);
  const Points expected = mappedPoints(surface.positions, affine);
  for (const char* name : {"out.glb", "out.gltf"}) {
    SCOPED_TRACE(name);
    const SurfaceMesh out = deform("", name);
    ASSERT_EQ(out.numVertices(), surface.numVertices());
    EXPECT_LT(maxRowDistance(out.positions, expected), 1e-6);  // 32-bit floats in glTF
    ASSERT_EQ(out.normals.rows(), surface.normals.rows());
    for (Eigen::Index j = 0; j < out.normals.rows(); ++j)
      EXPECT_LT(
          (out.normals.row(j).transpose() - cofactorNormal(surface.normals.row(j).transpose()))
              .norm(),
          1e-6);
    EXPECT_LT((out.texcoords - surface.texcoords).cwiseAbs().maxCoeff(), 1e-6);
  }
  // glb in, obj out.
  writeSurfaceFile(path("surface.glb"), readSurfaceFile(path("surface.obj")), surface);
  const CliResult result = run(
      "deform --rest " + quote(path("rest.vtk")) + " --deformed " + quote(path("deformed.vtk")) +
      " --surface " + quote(path("surface.glb")) + " --out " + quote(path("from_glb.obj")));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const SurfaceMesh fromGlb = readSurfaceFile(path("from_glb.obj")).surface();
  EXPECT_LT(maxRowDistance(fromGlb.positions, expected), 1e-6);
}

TEST_F(DeformCliTest, PointsOutsideTheMeshAreExtrapolatedWithAWarning) {
  // The sphere pokes out of the top of the unit cube (z up to 1.25).
  const SurfaceMesh surface = sphereSurface({0.5, 0.5, 0.95}, 0.3);
  writeScene(unitLattice(), surface, affine);
  for (const char* method : {"phong", "linear", "attribute"}) {
    SCOPED_TRACE(method);
    CliResult result;
    const SurfaceMesh out = deform(std::string("--method ") + method, "out.obj", &result);
    ASSERT_EQ(out.numVertices(), surface.numVertices());
    EXPECT_TRUE(out.positions.allFinite());
    EXPECT_TRUE(out.normals.allFinite());
    const auto lines = result.errLines();
    ASSERT_EQ(lines.size(), 1u) << result.err;
    EXPECT_EQ(lines[0].rfind("warning: ", 0), 0u) << lines[0];
    EXPECT_NE(lines[0].find("outside the rest mesh"), std::string::npos) << lines[0];
    const std::string last = result.lastLine();
    const size_t at = last.find("outside=");
    ASSERT_NE(at, std::string::npos) << last;
    const int outside = std::atoi(last.c_str() + at + 8);
    EXPECT_GT(outside, 0);
    EXPECT_LT(outside, static_cast<int>(surface.numVertices()));
    EXPECT_NE(lines[0].find(std::to_string(outside) + " of "), std::string::npos) << lines[0];
    // Extrapolating an affine map from the nearest cell is still exact for the gradient methods.
    if (std::string(method) != "attribute") {
      EXPECT_LT(maxRowDistance(out.positions, mappedPoints(surface.positions, affine)), 1e-9);
    }
  }
}

}  // namespace
}  // namespace sculpt
