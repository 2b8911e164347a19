// Volume-mesh files: legacy VTK (ASCII, binary, classic and 5.1 cell layouts), Gmsh 2.2 and 4.1,
// TetGen .node/.ele; the pyramid and wedge splits; rejection of broken and hostile files; and
// meshes made by the real `tetgen`.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <numbers>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/file_error.h"
#include "io/gmsh_mesh.h"
#include "io/tetgen_mesh.h"
#include "io/volume_mesh_file.h"
#include "io/vtk_volume_mesh.h"
#include "mesh/volume_mesh.h"
#include "support/tetgen.h"

namespace sculpt {
namespace {

using Cells = std::vector<std::vector<uint32_t>>;

// -------------------------------------------------------------------------------------------
// The test mesh, written by hand in every format: a unit cube as 6 tetrahedra around its
// diagonal 0-6, a hexahedron beside it (x in [1,2]), a pyramid on top of the cube (apex 12), a
// wedge on top of the hexahedron, and (VTK: as a voxel) a hexahedron behind the cube (y in
// [1,2]). VTK and Gmsh files also carry points, lines and triangles, which are skipped.
//
//   nodes 0-7: the cube (hexahedron order), 8-11: the x = 2 side of the hexahedron,
//   12: the apex (0.5, 0.5, 2), 13-15: the wedge top, 16-19: the y = 2 side of the voxel.
// -------------------------------------------------------------------------------------------

const std::vector<std::array<double, 3>> kPoints = {
    {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1},     {1, 1, 1},
    {0, 1, 1}, {2, 0, 0}, {2, 1, 0}, {2, 0, 1}, {2, 1, 1}, {0.5, 0.5, 2}, {1, 0, 2},
    {2, 0, 2}, {2, 1, 2}, {0, 2, 0}, {1, 2, 0}, {0, 2, 1}, {1, 2, 1}};

// What every reader must produce from that file (VTK/Gmsh order of cells).
// clang-format off
const Cells kExpectedCells = {
    {0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6},  // cube
    {1, 8, 9, 2, 5, 10, 11, 6},                                                         // hex
    {4, 5, 6, 12}, {4, 6, 7, 12},  // pyramid: base cut along 4-6 (4 is the smallest)
    {5, 10, 11, 15}, {5, 10, 15, 14}, {5, 14, 15, 13},  // wedge: Dompierre split from node 5
    {3, 2, 17, 16, 7, 6, 19, 18}};                     // the voxel as a hexahedron
// clang-format on
constexpr double kExpectedVolume = 1.0 + 1.0 + 1.0 / 3.0 + 0.5 + 1.0;

struct FileCell {
  int64_t vtkType;
  std::vector<int64_t> nodes;
};
// The cells of the VTK files, in file order (wedge in VTK order, voxel in voxel order).
const std::vector<FileCell> kVtkCells = {{1, {0}},
                                         {10, {0, 1, 2, 6}},
                                         {10, {0, 2, 3, 6}},
                                         {10, {0, 3, 7, 6}},
                                         {10, {0, 7, 4, 6}},
                                         {10, {0, 4, 5, 6}},
                                         {10, {0, 5, 1, 6}},
                                         {12, {1, 8, 9, 2, 5, 10, 11, 6}},
                                         {3, {0, 1}},
                                         {14, {4, 5, 6, 7, 12}},
                                         {13, {5, 11, 10, 13, 15, 14}},
                                         {11, {3, 2, 16, 17, 7, 6, 18, 19}},
                                         {5, {0, 1, 2}}};

const std::string kVtkClassic = R"(# vtk DataFile Version 3.0
mixed cells written by hand
ASCII
DATASET UNSTRUCTURED_GRID
POINTS 20 float
0 0 0  1 0 0  1 1 0  0 1 0
0 0 1  1 0 1  1 1 1  0 1 1
2 0 0  2 1 0  2 0 1  2 1 1
0.5 0.5 2
1 0 2  2 0 2  2 1 2
0 2 0  1 2 0  0 2 1  1 2 1

CELLS 13 70
1 0
4 0 1 2 6
4 0 2 3 6
4 0 3 7 6
4 0 7 4 6
4 0 4 5 6
4 0 5 1 6
8 1 8 9 2 5 10 11 6
2 0 1
5 4 5 6 7 12
6 5 11 10 13 15 14
8 3 2 16 17 7 6 18 19
3 0 1 2

CELL_TYPES 13
1 10 10 10 10 10 10 12 3 14 13 11 5

CELL_DATA 13
SCALARS region int 1
LOOKUP_TABLE default
0 0 0 0 0 0 0 0 0 0 0 0 0
)";

const std::string kVtk51 = R"(# vtk DataFile Version 5.1
vtk output
ASCII
DATASET UNSTRUCTURED_GRID
FIELD FieldData 1
TIME 1 1 double
0.5
POINTS 20 double
0 0 0 1 0 0 1 1 0 0 1 0 0 0 1 1 0 1 1 1 1 0 1 1
2 0 0 2 1 0 2 0 1 2 1 1 0.5 0.5 2 1 0 2 2 0 2 2 1 2
0 2 0 1 2 0 0 2 1 1 2 1
METADATA
INFORMATION 0

CELLS 14 57
OFFSETS vtktypeint64
0 1 5 9 13 17 21 25 33 35 40 46 54 57
CONNECTIVITY vtktypeint64
0
0 1 2 6 0 2 3 6 0 3 7 6 0 7 4 6 0 4 5 6 0 5 1 6
1 8 9 2 5 10 11 6
0 1
4 5 6 7 12
5 11 10 13 15 14
3 2 16 17 7 6 18 19
0 1 2
CELL_TYPES 13
1
10
10
10
10
10
10
12
3
14
13
11
5

POINT_DATA 20
)";

const std::string kGmsh22 = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
1
3 1 "the solid"
$EndPhysicalNames
$Nodes
20
10 0 0 0
20 1 0 0
30 1 1 0
40 0 1 0
50 0 0 1
60 1 0 1
70 1 1 1
80 0 1 1
90 2 0 0
100 2 1 0
110 2 0 1
120 2 1 1
130 0.5 0.5 2
140 1 0 2
150 2 0 2
160 2 1 2
170 0 2 0
180 1 2 0
190 0 2 1
200 1 2 1
$EndNodes
$Elements
13
1 15 2 0 1 10
2 1 2 0 1 10 20
3 2 2 0 1 10 20 30
10 4 2 1 1 10 20 30 70
11 4 2 1 1 10 30 40 70
12 4 2 1 1 10 40 80 70
13 4 2 1 1 10 80 50 70
14 4 2 1 1 10 50 60 70
15 4 2 1 1 10 60 20 70
20 5 2 1 1 20 90 100 30 60 110 120 70
30 7 2 1 1 50 60 70 80 130
40 6 2 1 1 60 110 120 140 150 160
50 5 2 1 1 40 30 180 170 80 70 200 190
$EndElements
)";

const std::string kGmsh41 = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
1
3 1 "the solid"
$EndPhysicalNames
$Entities
1 0 1 1
1 0 0 0 0
1 0 0 0 2 2 0 0 0
1 0 0 0 2 2 2 1 1 0
$EndEntities
$Nodes
3 20 10 200
0 1 0 1
10
0 0 0
2 1 1 3
20
30
40
1 0 0 0.25 0.5
1 1 0 0.5 0.5
0 1 0 0.75 0.5
3 1 0 16
50
60
70
80
90
100
110
120
130
140
150
160
170
180
190
200
0 0 1
1 0 1
1 1 1
0 1 1
2 0 0
2 1 0
2 0 1
2 1 1
0.5 0.5 2
1 0 2
2 0 2
2 1 2
0 2 0
1 2 0
0 2 1
1 2 1
$EndNodes
$Elements
7 13 1 13
0 1 15 1
1 10
2 1 2 2
2 10 20 30
3 10 30 40
3 1 4 6
4 10 20 30 70
5 10 30 40 70
6 10 40 80 70
7 10 80 50 70
8 10 50 60 70
9 10 60 20 70
3 1 5 1
10 20 90 100 30 60 110 120 70
3 1 7 1
11 50 60 70 80 130
3 1 6 1
12 60 110 120 140 150 160
3 2 5 1
13 40 30 180 170 80 70 200 190
$EndElements
)";

// TetGen: the cube alone (TetGen writes only tetrahedra), 1-based, with a point attribute,
// boundary markers, a region attribute and comments.
const std::string kTetGenNode = R"(# the unit cube
8 3 1 1
1 0 0 0 0.5 1
2 1 0 0 0.5 1
3 1 1 0 0.5 1  # attributes and markers are skipped
4 0 1 0 0.5 1
5 0 0 1 0.5 1
6 1 0 1 0.5 1
7 1 1 1 0.5 1
8 0 1 1 0.5 1
)";
const std::string kTetGenEle = R"(6 4 1
1 1 2 3 7 1
2 1 3 4 7 1
3 1 4 8 7 1
4 1 8 5 7 1
5 1 5 6 7 1
6 1 6 2 7 1
# Generated by hand
)";
const Cells kCubeCells = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                          {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};

// -------------------------------------------------------------------------------------------
// Helpers
// -------------------------------------------------------------------------------------------

Cells cellsOf(const VolumeMesh& mesh) {
  Cells cells;
  for (uint32_t c = 0; c < mesh.numCells(); ++c) {
    const auto row = mesh.cells.row(c);
    cells.emplace_back(row.begin(), row.end());
  }
  return cells;
}

double totalVolume(const VolumeMesh& mesh) {
  // Hexahedra here are unit cubes; tetrahedra by their signed volume.
  double volume = 0.0;
  for (uint32_t c = 0; c < mesh.numCells(); ++c) {
    volume += mesh.isTetrahedron(c) ? tetrahedronSignedVolume(mesh, c) : 1.0;
  }
  return volume;
}

void expectTestMesh(const VolumeMesh& mesh) {
  ASSERT_EQ(mesh.numNodes(), kPoints.size());
  for (uint32_t n = 0; n < mesh.numNodes(); ++n) {
    for (int k = 0; k < 3; ++k) EXPECT_EQ(mesh.positions(n, k), kPoints[n][static_cast<size_t>(k)]);
  }
  EXPECT_EQ(cellsOf(mesh), kExpectedCells);
  EXPECT_NEAR(totalVolume(mesh), kExpectedVolume, 1e-12);
  EXPECT_EQ(findVolumeMeshProblem(mesh), "");
}

bool sameBits(const VolumeMesh& a, const VolumeMesh& b) {
  return a.positions.rows() == b.positions.rows() &&
         std::memcmp(a.positions.data(), b.positions.data(),
                     sizeof(double) * static_cast<size_t>(a.positions.size())) == 0 &&
         a.cells.offsets == b.cells.offsets && a.cells.values == b.cells.values;
}

/// Success when `load` throws a one-line FileError that mentions `expected`.
testing::AssertionResult rejectedWith(const std::function<void()>& load,
                                      std::string_view expected) {
  try {
    load();
  } catch (const FileError& e) {
    const std::string_view message = e.what();
    if (message.find('\n') != std::string_view::npos) {
      return testing::AssertionFailure() << "message is not one line: " << message;
    }
    if (message.find(expected) == std::string_view::npos) {
      return testing::AssertionFailure()
             << "message '" << message << "' does not mention '" << expected << "'";
    }
    return testing::AssertionSuccess() << message;
  } catch (const std::exception& e) {
    return testing::AssertionFailure() << "threw something other than FileError: " << e.what();
  }
  return testing::AssertionFailure() << "loaded without an error";
}

std::string replaced(std::string text, std::string_view from, std::string_view to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "test data lacks '" << from << "'";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

std::string cutBefore(const std::string& text, std::string_view marker) {
  const size_t at = text.find(marker);
  EXPECT_NE(at, std::string::npos) << "test data lacks '" << marker << "'";
  return text.substr(0, at);
}

/// Legacy VTK binary data is big-endian.
struct BigEndianBytes {
  std::string bytes;
  void text(std::string_view s) { bytes += s; }
  void bits(uint64_t value, int size) {
    for (int i = size - 1; i >= 0; --i) bytes += static_cast<char>((value >> (8 * i)) & 0xff);
  }
  void f32(float v) { bits(std::bit_cast<uint32_t>(v), 4); }
  void f64(double v) { bits(std::bit_cast<uint64_t>(v), 8); }
  void i32(int64_t v) { bits(static_cast<uint32_t>(static_cast<int32_t>(v)), 4); }
  void i64(int64_t v) { bits(static_cast<uint64_t>(v), 8); }
};

enum class BinaryLayout { ClassicFloat, Offsets64Double, Offsets32Float };

/// The test mesh as a binary VTK file, encoded here independently of the writer.
std::string binaryVtk(BinaryLayout layout) {
  const bool doubles = layout == BinaryLayout::Offsets64Double;
  BigEndianBytes out;
  out.text(layout == BinaryLayout::ClassicFloat ? "# vtk DataFile Version 4.2\n"
                                                : "# vtk DataFile Version 5.1\n");
  out.text("binary test\nBINARY\nDATASET UNSTRUCTURED_GRID\n");
  out.text("POINTS " + std::to_string(kPoints.size()) + (doubles ? " double\n" : " float\n"));
  for (const auto& p : kPoints) {
    for (const double x : p) doubles ? out.f64(x) : out.f32(static_cast<float>(x));
  }
  out.text("\n");
  size_t connectivity = 0;
  for (const FileCell& cell : kVtkCells) connectivity += cell.nodes.size();
  if (layout == BinaryLayout::ClassicFloat) {
    out.text("CELLS " + std::to_string(kVtkCells.size()) + " " +
             std::to_string(connectivity + kVtkCells.size()) + "\n");
    for (const FileCell& cell : kVtkCells) {
      out.i32(static_cast<int64_t>(cell.nodes.size()));
      for (const int64_t n : cell.nodes) out.i32(n);
    }
  } else {
    const bool wide = layout == BinaryLayout::Offsets64Double;
    const auto integer = [&](int64_t v) { wide ? out.i64(v) : out.i32(v); };
    const std::string type = wide ? "vtktypeint64" : "vtktypeint32";
    out.text("CELLS " + std::to_string(kVtkCells.size() + 1) + " " + std::to_string(connectivity) +
             "\nOFFSETS " + type + "\n");
    int64_t offset = 0;
    integer(0);
    for (const FileCell& cell : kVtkCells)
      integer(offset += static_cast<int64_t>(cell.nodes.size()));
    out.text("\nCONNECTIVITY " + type + "\n");
    for (const FileCell& cell : kVtkCells) {
      for (const int64_t n : cell.nodes) integer(n);
    }
  }
  out.text("\nCELL_TYPES " + std::to_string(kVtkCells.size()) + "\n");
  for (const FileCell& cell : kVtkCells) out.i32(cell.vtkType);
  out.text("\nCELL_DATA 13\nSCALARS region int 1\nLOOKUP_TABLE default\n");
  for (size_t i = 0; i < kVtkCells.size(); ++i) out.i32(0);
  out.text("\n");
  return out.bytes;
}

// -------------------------------------------------------------------------------------------
// Pyramid and wedge splits
// -------------------------------------------------------------------------------------------

VolumeMesh meshWithPositions(const std::vector<Eigen::Vector3d>& points) {
  VolumeMesh mesh;
  mesh.positions.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t i = 0; i < points.size(); ++i) {
    mesh.positions.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
  }
  return mesh;
}

/// Which diagonal of the quadrilateral loop q the tetrahedra of `mesh` use: 0 for q0-q2, 1 for
/// q1-q3, -1 for none or both.
int diagonalUsed(const VolumeMesh& mesh, const std::array<uint32_t, 4>& q) {
  std::set<std::pair<uint32_t, uint32_t>> edges;
  for (uint32_t c = 0; c < mesh.numCells(); ++c) {
    const auto v = mesh.cells.row(c);
    for (size_t i = 0; i < v.size(); ++i) {
      for (size_t j = i + 1; j < v.size(); ++j) edges.insert(std::minmax(v[i], v[j]));
    }
  }
  const bool first = edges.count(std::minmax(q[0], q[2])) > 0;
  const bool second = edges.count(std::minmax(q[1], q[3])) > 0;
  return first == second ? -1 : (first ? 0 : 1);
}

TEST(VolumeMeshSplit, WedgeGivesThreePositiveTetrahedraForEveryNumbering) {
  // A slanted wedge in Gmsh order (triangle 0,1,2 counter-clockwise seen from 3,4,5). Its sides
  // are planar, so that every split has the same volume.
  const std::vector<Eigen::Vector3d> corners = {{0, 0, 0},     {1, 0, 0},     {0, 1, 0},
                                                {0.2, 0.1, 1}, {1.2, 0.1, 1}, {0.2, 1.1, 1}};
  // Reference volume: the same wedge split by hand in one valid way.
  VolumeMesh reference = meshWithPositions(corners);
  reference.addTetrahedron({0, 1, 2, 5});
  reference.addTetrahedron({0, 1, 5, 4});
  reference.addTetrahedron({0, 4, 5, 3});
  const double wedgeVolume = totalVolume(reference);
  ASSERT_GT(wedgeVolume, 0.0);

  std::array<uint32_t, 6> ids{0, 1, 2, 3, 4, 5};
  int numberings = 0;
  do {  // node ids[k] sits at corner k
    std::vector<Eigen::Vector3d> points(6);
    for (size_t k = 0; k < 6; ++k) points[ids[k]] = corners[k];
    VolumeMesh mesh = meshWithPositions(points);
    splitWedge(mesh, ids);
    ASSERT_EQ(mesh.numCells(), 3u);
    for (uint32_t c = 0; c < 3; ++c) ASSERT_GT(tetrahedronSignedVolume(mesh, c), 0.0);
    EXPECT_NEAR(totalVolume(mesh), wedgeVolume, 1e-12);
    // Each quadrilateral side is cut along the diagonal through its smallest id.
    for (const auto& side : {std::array<size_t, 4>{0, 1, 4, 3}, std::array<size_t, 4>{1, 2, 5, 4},
                             std::array<size_t, 4>{2, 0, 3, 5}}) {
      const std::array<uint32_t, 4> q{ids[side[0]], ids[side[1]], ids[side[2]], ids[side[3]]};
      const int expected = std::min(q[0], q[2]) < std::min(q[1], q[3]) ? 0 : 1;
      EXPECT_EQ(diagonalUsed(mesh, q), expected);
    }
    ++numberings;
  } while (std::next_permutation(ids.begin(), ids.end()));
  EXPECT_EQ(numberings, 720);
}

TEST(VolumeMeshSplit, PyramidGivesTwoPositiveTetrahedraForEveryNumbering) {
  const std::vector<Eigen::Vector3d> corners = {
      {0, 0, 0}, {2, 0, 0}, {2.2, 1.5, 0}, {-0.1, 1, 0}, {0.7, 0.6, 1.3}};
  std::array<uint32_t, 5> ids{0, 1, 2, 3, 4};
  double firstVolume = 0.0;
  do {
    std::vector<Eigen::Vector3d> points(5);
    for (size_t k = 0; k < 5; ++k) points[ids[k]] = corners[k];
    VolumeMesh mesh = meshWithPositions(points);
    splitPyramid(mesh, ids);
    ASSERT_EQ(mesh.numCells(), 2u);
    for (uint32_t c = 0; c < 2; ++c) ASSERT_GT(tetrahedronSignedVolume(mesh, c), 0.0);
    const double volume = totalVolume(mesh);
    if (firstVolume == 0.0) firstVolume = volume;
    EXPECT_NEAR(volume, firstVolume, 1e-12);
    const std::array<uint32_t, 4> base{ids[0], ids[1], ids[2], ids[3]};
    EXPECT_EQ(diagonalUsed(mesh, base),
              std::min(base[0], base[2]) < std::min(base[1], base[3]) ? 0 : 1);
  } while (std::next_permutation(ids.begin(), ids.end()));
  // A pyramid over a planar base has volume base area * height / 3.
  const Eigen::Vector3d diagonalA = corners[2] - corners[0], diagonalB = corners[3] - corners[1];
  EXPECT_NEAR(firstVolume, 0.5 * diagonalA.cross(diagonalB).norm() * 1.3 / 3.0, 1e-12);
}

TEST(VolumeMeshSplit, NeighboursSharingAQuadrilateralCutItTheSameWay) {
  // Two wedges over the triangles (0,1,2) and (1,3,2) of the unit square, extruded by 1: they
  // share the side 1,2,6,5. A pyramid on the far side of wedge B's side 3,2,6,7 shares that one.
  const std::vector<Eigen::Vector3d> corners = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                                                {1, 1, 0}, {0, 0, 1}, {1, 0, 1},
                                                {0, 1, 1}, {1, 1, 1}, {0.5, 2, 0.5}};
  std::array<uint32_t, 9> ids{};
  std::iota(ids.begin(), ids.end(), 0u);
  std::mt19937 random(7);
  for (int trial = 0; trial < 3000; ++trial) {
    std::shuffle(ids.begin(), ids.end(), random);
    std::vector<Eigen::Vector3d> points(9);
    for (size_t k = 0; k < 9; ++k) points[ids[k]] = corners[k];
    VolumeMesh a = meshWithPositions(points), b = a, p = a;
    splitWedge(a, {ids[0], ids[1], ids[2], ids[4], ids[5], ids[6]});
    splitWedge(b, {ids[1], ids[3], ids[2], ids[5], ids[7], ids[6]});
    splitPyramid(p, {ids[3], ids[2], ids[6], ids[7], ids[8]});
    for (const VolumeMesh* m : {&a, &b, &p}) EXPECT_EQ(findVolumeMeshProblem(*m), "");

    const std::array<uint32_t, 4> sharedAB{ids[1], ids[2], ids[6], ids[5]};
    ASSERT_NE(diagonalUsed(a, sharedAB), -1);
    EXPECT_EQ(diagonalUsed(a, sharedAB), diagonalUsed(b, sharedAB));
    const std::array<uint32_t, 4> sharedBP{ids[3], ids[2], ids[6], ids[7]};
    ASSERT_NE(diagonalUsed(p, sharedBP), -1);
    EXPECT_EQ(diagonalUsed(b, sharedBP), diagonalUsed(p, sharedBP));
  }
}

// -------------------------------------------------------------------------------------------
// findVolumeMeshProblem
// -------------------------------------------------------------------------------------------

TEST(VolumeMeshProblem, NamesTheCellAndTheProblem) {
  VolumeMesh mesh = meshWithPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
  EXPECT_EQ(findVolumeMeshProblem(mesh), "the mesh has no cells");
  mesh.addTetrahedron({0, 1, 2, 3});
  EXPECT_EQ(findVolumeMeshProblem(mesh), "");
  mesh.addTetrahedron({0, 2, 1, 3});
  EXPECT_EQ(findVolumeMeshProblem(mesh), "cell 1 (tetrahedron): inverted, signed volume -0.167");
  mesh.cells.values[5] = 99;
  EXPECT_EQ(findVolumeMeshProblem(mesh), "cell 1: node id 99 out of range (the mesh has 4 nodes)");
  mesh.cells.values[5] = 0;
  EXPECT_EQ(findVolumeMeshProblem(mesh), "cell 1: node 0 appears twice");
  mesh.cells.values[5] = 2;
  mesh.positions(2, 1) = std::nan("");
  EXPECT_EQ(findVolumeMeshProblem(mesh), "node 2: coordinate is not finite");
}

TEST(VolumeMeshProblem, ChecksTheHexahedronJacobianAtEveryCorner) {
  std::vector<Eigen::Vector3d> cube;
  for (const auto& p : std::vector<std::array<double, 3>>(kPoints.begin(), kPoints.begin() + 8)) {
    cube.emplace_back(p[0], p[1], p[2]);
  }
  VolumeMesh mesh = meshWithPositions(cube);
  mesh.addHexahedron({0, 1, 2, 3, 4, 5, 6, 7});
  EXPECT_EQ(findVolumeMeshProblem(mesh), "");
  // Upside down: every corner negative.
  mesh.cells.values = {4, 5, 6, 7, 0, 1, 2, 3};
  EXPECT_NE(findVolumeMeshProblem(mesh).find("cell 0 (hexahedron): inverted"), std::string::npos);
  // One top corner pushed below the bottom face: positive volume overall, but not at corner 6.
  mesh.cells.values = {0, 1, 2, 3, 4, 5, 6, 7};
  mesh.positions.row(6) << 1.0, 1.0, -0.5;
  EXPECT_NE(findVolumeMeshProblem(mesh).find("corner"), std::string::npos);
}

// -------------------------------------------------------------------------------------------
// VTK
// -------------------------------------------------------------------------------------------

TEST(VtkVolumeMesh, ReadsTheClassicAsciiLayout) {
  expectTestMesh(parseVtkVolumeMesh(kVtkClassic, "mixed.vtk"));
}

TEST(VtkVolumeMesh, ReadsTheVtk51AsciiLayoutWithFieldAndMetadata) {
  expectTestMesh(parseVtkVolumeMesh(kVtk51, "mixed51.vtk"));
}

TEST(VtkVolumeMesh, ReadsBinaryFilesInEveryLayout) {
  for (const BinaryLayout layout :
       {BinaryLayout::ClassicFloat, BinaryLayout::Offsets64Double, BinaryLayout::Offsets32Float}) {
    SCOPED_TRACE(static_cast<int>(layout));
    expectTestMesh(parseVtkVolumeMesh(binaryVtk(layout), "binary.vtk"));
  }
}

TEST(VtkVolumeMesh, AsciiAndBinaryRoundTripThroughTheWriterBitForBit) {
  VolumeMesh mesh = parseVtkVolumeMesh(kVtkClassic, "mixed.vtk");
  // Positions no short decimal can hold.
  std::mt19937 random(3);
  std::uniform_real_distribution<double> jitter(-1e-3, 1e-3);
  for (Eigen::Index i = 0; i < mesh.positions.size(); ++i)
    mesh.positions.data()[i] += jitter(random) / 3.0;
  mesh.positions(0, 0) = -0.0;
  mesh.positions(1, 2) = 1e-300;
  ASSERT_EQ(findVolumeMeshProblem(mesh), "");

  for (const bool binary : {false, true}) {
    SCOPED_TRACE(binary ? "binary" : "ascii");
    const std::string text = volumeMeshToVtk(mesh, binary);
    const VolumeMesh back = parseVtkVolumeMesh(text, "roundtrip.vtk");
    EXPECT_TRUE(sameBits(mesh, back));
    EXPECT_EQ(std::signbit(back.positions(0, 0)), true);
    EXPECT_EQ(volumeMeshToVtk(back, binary), text);
  }

  test::ScopedTempDir dir("vtk_writer");
  ASSERT_FALSE(dir.path().empty());
  writeVtkVolumeMesh(dir.path() / "mesh.vtk", mesh, true);
  EXPECT_TRUE(sameBits(mesh, readVolumeMesh(dir.path() / "mesh.vtk")));
}

TEST(VtkVolumeMesh, RejectsBrokenFiles) {
  const auto parse = [](const std::string& text) {
    return [text] { parseVtkVolumeMesh(text, "bad.vtk"); };
  };
  // Truncated in the middle of CELLS, and before CELL_TYPES.
  EXPECT_TRUE(rejectedWith(parse(cutBefore(kVtkClassic, "4 0 7 4 6")),
                           "line 13: the file ends too soon for 70 numbers in CELLS"));
  EXPECT_TRUE(rejectedWith(parse(cutBefore(kVtkClassic, "CELL_TYPES")), "CELL_TYPES section"));
  // Fewer cells than declared.
  EXPECT_TRUE(rejectedWith(parse(replaced(kVtkClassic, "CELLS 13 70", "CELLS 14 72")), "cell 13"));
  EXPECT_TRUE(rejectedWith(parse(replaced(kVtkClassic, "CELL_TYPES 13\n1 10", "CELL_TYPES 12\n10")),
                           "CELL_TYPES lists 12 types for 13 cells"));
  EXPECT_TRUE(rejectedWith(parse(replaced(kVtkClassic, "CELLS 13 70", "CELLS 13 71")),
                           "CELLS declares 71 numbers"));
  // A node index out of range, and negative.
  EXPECT_TRUE(rejectedWith(parse(replaced(kVtkClassic, "4 0 1 2 6", "4 0 1 2 99")),
                           "cell 1: node id 99 out of range (the mesh has 20 nodes)"));
  EXPECT_TRUE(rejectedWith(parse(replaced(kVtkClassic, "4 0 1 2 6", "4 0 1 2 -1")),
                           "node id -1 out of range"));
  // An inverted tetrahedron: the message names the mesh cell and the VTK cell.
  EXPECT_TRUE(rejectedWith(parse(replaced(kVtkClassic, "4 0 2 3 6", "4 0 3 2 6")),
                           "cell 1 (tetrahedron, from VTK cell 2): inverted"));
  // A NaN coordinate.
  EXPECT_TRUE(rejectedWith(parse(replaced(kVtkClassic, "0.5 0.5 2", "nan 0.5 2")),
                           "node 12: coordinate is not finite"));
  EXPECT_TRUE(rejectedWith(parse(replaced(kVtkClassic, "0.5 0.5 2", "0.5 x 2")),
                           "expected coordinate 1 of point 12"));
  // Unsupported and unknown cell types.
  EXPECT_TRUE(rejectedWith(parse(replaced(kVtkClassic, "1 10 10", "1 24 10")),
                           "VTK cell type 24 (quadratic tetrahedron) is not supported"));
  EXPECT_TRUE(rejectedWith(parse(replaced(kVtkClassic, "1 10 10", "1 42 10")), "polyhedron"));
  EXPECT_TRUE(rejectedWith(parse(replaced(kVtkClassic, "1 10 10", "1 99 10")),
                           "VTK cell type 99 (unknown)"));
  EXPECT_TRUE(
      rejectedWith(parse(replaced(kVtkClassic, "1 10 10", "1 12 10")), "needs 8 nodes, not 4"));
  // Not a volume mesh file at all.
  EXPECT_TRUE(rejectedWith(parse(replaced(kVtkClassic, "UNSTRUCTURED_GRID", "POLYDATA")),
                           "DATASET POLYDATA is not supported"));
  EXPECT_TRUE(rejectedWith(parse(replaced(kVtkClassic, "# vtk DataFile", "# stl")),
                           "not a legacy VTK file"));
  EXPECT_TRUE(rejectedWith(parse(""), "not a legacy VTK file"));
  // VTK 5.1: offsets that do not add up.
  EXPECT_TRUE(rejectedWith(parse(replaced(kVtk51, "46 54 57", "46 54 56")), "last offset"));
  EXPECT_TRUE(rejectedWith(parse(replaced(kVtk51, "0 1 5 9 13", "0 1 5 3 13")), "OFFSETS"));
}

TEST(VtkVolumeMesh, RejectsTruncatedBinaryFiles) {
  for (const BinaryLayout layout :
       {BinaryLayout::ClassicFloat, BinaryLayout::Offsets64Double, BinaryLayout::Offsets32Float}) {
    const std::string bytes = binaryVtk(layout);
    // Cut in the middle of the POINTS block.
    const size_t pointsStart = bytes.find('\n', bytes.find("POINTS")) + 1;
    EXPECT_TRUE(
        rejectedWith([&] { parseVtkVolumeMesh(bytes.substr(0, pointsStart + 100), "cut.vtk"); },
                     "the file ends too soon for 20 points"));
    // Cut inside the cell data.
    const size_t cellsStart =
        bytes.find('\n', bytes.find(layout == BinaryLayout::ClassicFloat ? "CELLS" : "OFFSETS")) +
        1;
    EXPECT_TRUE(rejectedWith(
        [&] { parseVtkVolumeMesh(bytes.substr(0, cellsStart + 10), "cut.vtk"); }, "the file ends"));
  }
}

TEST(VtkVolumeMesh, RejectsAbsurdCountsWithoutAllocating) {
  const auto parse = [](const std::string& text) {
    return [text] { parseVtkVolumeMesh(text, "huge.vtk"); };
  };
  EXPECT_TRUE(
      rejectedWith(parse(replaced(kVtkClassic, "POINTS 20 float", "POINTS 4000000000000 float")),
                   "the file ends too soon for 4000000000000 points"));
  EXPECT_TRUE(rejectedWith(
      parse(replaced(kVtkClassic, "POINTS 20 float", "POINTS 18446744073709551615 float")),
      "the file ends too soon"));
  EXPECT_TRUE(rejectedWith(parse(replaced(kVtkClassic, "CELLS 13 70", "CELLS 13 4000000000000")),
                           "the file ends too soon for 4000000000000 numbers in CELLS"));
  EXPECT_TRUE(rejectedWith(parse(replaced(kVtkClassic, "CELLS 13 70", "CELLS 4000000000000 70")),
                           "cells in only 70 numbers"));
  EXPECT_TRUE(
      rejectedWith(parse(replaced(kVtkClassic, "CELL_TYPES 13", "CELL_TYPES 4000000000000")),
                   "the file ends too soon for 4000000000000 cell types"));
  EXPECT_TRUE(rejectedWith(parse(replaced(kVtk51, "CELLS 14 57", "CELLS 4000000000000 57")),
                           "values in OFFSETS"));
  const std::string binary = binaryVtk(BinaryLayout::ClassicFloat);
  EXPECT_TRUE(rejectedWith(parse(replaced(binary, "POINTS 20 float", "POINTS 4000000000000 float")),
                           "the file ends too soon for 4000000000000 points"));
}

// -------------------------------------------------------------------------------------------
// Gmsh
// -------------------------------------------------------------------------------------------

TEST(GmshMesh, ReadsVersion22WithSparseNodeTags) {
  expectTestMesh(parseGmshMesh(kGmsh22, "mixed.msh"));
}

TEST(GmshMesh, ReadsVersion41WithBlocksAndParametricNodes) {
  expectTestMesh(parseGmshMesh(kGmsh41, "mixed41.msh"));
}

TEST(GmshMesh, MapsNodeTagsInFileOrderEvenWhenHugeAndUnsorted) {
  // Tags far apart (a sorted index, not a table) and out of order.
  const std::string text =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n"
      "90000000000 0 0 1\n7 0 0 0\n123456789012 1 0 0\n5 0 1 0\n$EndNodes\n"
      "$Elements\n1\n1 4 0 7 123456789012 5 90000000000\n$EndElements\n";
  const VolumeMesh mesh = parseGmshMesh(text, "sparse.msh");
  EXPECT_EQ(cellsOf(mesh), (Cells{{1, 2, 3, 0}}));
  EXPECT_EQ(mesh.positions(0, 2), 1.0);
}

TEST(GmshMesh, RejectsBrokenFiles) {
  const auto parse = [](const std::string& text) {
    return [text] { parseGmshMesh(text, "bad.msh"); };
  };
  // Truncated (in $Nodes for each version, and in $Elements).
  EXPECT_TRUE(rejectedWith(parse(cutBefore(kGmsh22, "90 2 0 0")),
                           "line 9: the file ends too soon for 20 nodes"));
  EXPECT_TRUE(rejectedWith(parse(cutBefore(kGmsh41, "0.5 0.5 2")), "end of the file"));
  EXPECT_TRUE(rejectedWith(parse(cutBefore(kGmsh41, "13 40 30")), "end of the file"));
  EXPECT_TRUE(rejectedWith(parse(cutBefore(kGmsh22, "$EndNodes")), "end of the file"));
  // Fewer entries than declared.
  EXPECT_TRUE(rejectedWith(parse(replaced(kGmsh22, "$Elements\n13", "$Elements\n14")),
                           "found '$EndElements' where the tag of element number 13 should be"));
  EXPECT_TRUE(rejectedWith(parse(replaced(kGmsh22, "$Nodes\n20", "$Nodes\n21")),
                           "the section holds fewer entries than it declares"));
  EXPECT_TRUE(rejectedWith(parse(replaced(kGmsh41, "7 13 1 13", "7 14 1 13")),
                           "the element blocks hold 13 elements, not the 14 declared"));
  EXPECT_TRUE(rejectedWith(parse(replaced(kGmsh41, "3 20 10 200", "3 19 10 200")),
                           "beyond the 19 declared"));
  EXPECT_TRUE(
      rejectedWith(parse(replaced(kGmsh22, "10 4 2 1 1 10 20 30 70", "10 4 2 1 1 10 20 30")),
                   "element 10: the line ends before a node tag"));
  // A node tag that is not defined.
  EXPECT_TRUE(
      rejectedWith(parse(replaced(kGmsh22, "10 4 2 1 1 10 20 30 70", "10 4 2 1 1 10 20 30 999")),
                   "element 10: node tag 999 is not in $Nodes"));
  EXPECT_TRUE(
      rejectedWith(parse(replaced(kGmsh22, "40 0 1 0", "30 0 1 0")), "node tag 30 appears twice"));
  // Inverted tetrahedron; a prism listed upside down.
  EXPECT_TRUE(
      rejectedWith(parse(replaced(kGmsh22, "11 4 2 1 1 10 30 40 70", "11 4 2 1 1 10 40 30 70")),
                   "cell 1 (tetrahedron, from element 11): inverted"));
  EXPECT_TRUE(rejectedWith(
      parse(replaced(kGmsh41, "12 60 110 120 140 150 160", "12 140 150 160 60 110 120")),
      "from element 12): inverted"));
  // NaN coordinate.
  EXPECT_TRUE(rejectedWith(parse(replaced(kGmsh22, "130 0.5 0.5 2", "130 0.5 NaN 2")),
                           "node 12: coordinate is not finite"));
  // Element types that are not read.
  EXPECT_TRUE(rejectedWith(parse(replaced(kGmsh22, "10 4 2 1 1 10 20 30 70",
                                          "10 11 2 1 1 10 20 30 70 10 20 30 70 10 20")),
                           "element 10: element type 11 (10-node tetrahedron) is not supported"));
  EXPECT_TRUE(
      rejectedWith(parse(replaced(kGmsh41, "3 1 4 6", "3 1 99 6")), "element type 99 (unknown)"));
  // Other encodings and versions.
  EXPECT_TRUE(rejectedWith(parse("$MeshFormat\n4.1 1 8\n\x01\x00\x00\x00\n$EndMeshFormat\n"),
                           "binary .msh is not supported; save the mesh as ASCII 4.1 or 2.2"));
  EXPECT_TRUE(
      rejectedWith(parse(replaced(kGmsh41, "4.1 0 8", "4 0 8")), "MSH version 4 is not supported"));
  EXPECT_TRUE(rejectedWith(parse("$NOD\n1\n1 0 0 0\n$ENDNOD\n"), "not a Gmsh .msh file"));
  EXPECT_TRUE(rejectedWith(parse(cutBefore(kGmsh22, "$Elements")), "no $Elements section"));
  EXPECT_TRUE(rejectedWith(parse(cutBefore(kGmsh22, "$EndPhysicalNames")),
                           "inside the $PhysicalNames section"));
}

TEST(GmshMesh, RejectsAbsurdCountsWithoutAllocating) {
  const auto parse = [](const std::string& text) {
    return [text] { parseGmshMesh(text, "huge.msh"); };
  };
  EXPECT_TRUE(
      rejectedWith(parse(replaced(kGmsh41, "3 20 10 200", "1 4000000000000 1 4000000000000")),
                   "the file ends too soon for 4000000000000 nodes"));
  EXPECT_TRUE(rejectedWith(parse(replaced(kGmsh22, "$Nodes\n20", "$Nodes\n4000000000000")),
                           "the file ends too soon for 4000000000000 nodes"));
  EXPECT_TRUE(rejectedWith(parse(replaced(kGmsh22, "$Elements\n13", "$Elements\n4000000000000")),
                           "the file ends too soon for 4000000000000 elements"));
  EXPECT_TRUE(rejectedWith(parse(replaced(kGmsh41, "3 1 4 6", "3 1 4 4000000000000")),
                           "beyond the 13 declared"));
}

// -------------------------------------------------------------------------------------------
// TetGen
// -------------------------------------------------------------------------------------------

TEST(TetGenMesh, ReadsOneBasedFilesWithAttributesMarkersAndComments) {
  const VolumeMesh mesh = parseTetGenMesh(kTetGenNode, kTetGenEle, "cube.node", "cube.ele");
  ASSERT_EQ(mesh.numNodes(), 8u);
  for (uint32_t n = 0; n < 8; ++n) {
    for (int k = 0; k < 3; ++k) EXPECT_EQ(mesh.positions(n, k), kPoints[n][static_cast<size_t>(k)]);
  }
  EXPECT_EQ(cellsOf(mesh), kCubeCells);
  EXPECT_NEAR(totalVolume(mesh), 1.0, 1e-15);
}

TEST(TetGenMesh, ReadsZeroBasedFilesAndTenNodeTetrahedra) {
  const std::string node =
      "8 3 0 0\n0 0 0 0\n1 1 0 0\n2 1 1 0\n3 0 1 0\n4 0 0 1\n5 1 0 1\n6 1 1 1\n7 0 1 1\n";
  const std::string ele =
      "6 4 0\n0 0 1 2 6\n1 0 2 3 6\n2 0 3 7 6\n3 0 7 4 6\n4 0 4 5 6\n5 0 5 1 6\n";
  EXPECT_EQ(cellsOf(parseTetGenMesh(node, ele, "zero.node", "zero.ele")), kCubeCells);
  // Trailing header numbers may be left out (dimension 3, 4 nodes, no attributes).
  EXPECT_EQ(cellsOf(parseTetGenMesh(replaced(node, "8 3 0 0", "8"), replaced(ele, "6 4 0", "6"),
                                    "short.node", "short.ele")),
            kCubeCells);
  // Second order: the corners come first, the 6 edge nodes after them are dropped.
  const std::string ele10 =
      "6 10 0\n0 0 1 2 6 1 2 3 4 5 7\n1 0 2 3 6 1 2 3 4 5 7\n2 0 3 7 6 1 2 3 4 5 7\n"
      "3 0 7 4 6 1 2 3 4 5 7\n4 0 4 5 6 1 2 3 4 5 7\n5 0 5 1 6 1 2 3 4 5 7\n";
  EXPECT_EQ(cellsOf(parseTetGenMesh(node, ele10, "quadratic.node", "quadratic.ele")), kCubeCells);
}

TEST(TetGenMesh, RejectsBrokenFiles) {
  const auto parse = [](const std::string& node, const std::string& ele) {
    return [node, ele] { parseTetGenMesh(node, ele, "bad.node", "bad.ele"); };
  };
  // Truncated .ele and .node; fewer tetrahedra than declared.
  EXPECT_TRUE(rejectedWith(parse(kTetGenNode, cutBefore(kTetGenEle, "4 1 8 5")),
                           "bad.ele: line 1: the file ends too soon for 6 tetrahedra"));
  EXPECT_TRUE(
      rejectedWith(parse(kTetGenNode, replaced(kTetGenEle, "6 1 6 2 7 1", "6 1 6 2")),
                   "bad.ele: line 9: expected a node of tetrahedron 6, found the end of the file"));
  EXPECT_TRUE(rejectedWith(parse(cutBefore(kTetGenNode, "6 1 0 1"), kTetGenEle), "bad.node"));
  EXPECT_TRUE(rejectedWith(parse(kTetGenNode, replaced(kTetGenEle, "6 4 1", "7 4 1")),
                           "tetrahedron 6 (of 7), found the end of the file"));
  // Node index out of range (1-based: 0 and 9 are both outside).
  EXPECT_TRUE(
      rejectedWith(parse(kTetGenNode, replaced(kTetGenEle, "2 1 3 4 7", "2 1 3 9 7")),
                   "tetrahedron 2: node id 9 out of range (the mesh has 8 nodes numbered from 1)"));
  EXPECT_TRUE(rejectedWith(parse(kTetGenNode, replaced(kTetGenEle, "2 1 3 4 7", "2 0 3 4 7")),
                           "out of range"));
  // Inverted, in TetGen's own (positive) convention.
  EXPECT_TRUE(rejectedWith(parse(kTetGenNode, replaced(kTetGenEle, "5 1 5 6 7", "5 1 6 5 7")),
                           "bad.ele: cell 4 (tetrahedron, from tetrahedron 5): inverted"));
  // NaN coordinate; non-consecutive numbering; wrong dimension; a bad node count.
  EXPECT_TRUE(rejectedWith(parse(replaced(kTetGenNode, "7 1 1 1", "7 1 nan 1"), kTetGenEle),
                           "bad.node: line 9: coordinate 1 of point 7 is not finite"));
  EXPECT_TRUE(rejectedWith(parse(replaced(kTetGenNode, "\n5 0 0 1", "\n6 0 0 1"), kTetGenEle),
                           "numbers must be consecutive"));
  EXPECT_TRUE(
      rejectedWith(parse(replaced(kTetGenNode, "8 3 1 1", "8 2 1 1"), kTetGenEle), "dimension 2"));
  EXPECT_TRUE(rejectedWith(parse(kTetGenNode, replaced(kTetGenEle, "6 4 1", "6 8 1")),
                           "8 nodes per tetrahedron (must be 4 or 10)"));
  // Absurd counts.
  EXPECT_TRUE(
      rejectedWith(parse(replaced(kTetGenNode, "8 3 1 1", "4000000000000 3 1 1"), kTetGenEle),
                   "bad.node: line 2: the file ends too soon for 4000000000000 points"));
  EXPECT_TRUE(rejectedWith(parse(kTetGenNode, replaced(kTetGenEle, "6 4 1", "4000000000000 4 1")),
                           "the file ends too soon for 4000000000000 tetrahedra"));
  EXPECT_TRUE(
      rejectedWith(parse(replaced(kTetGenNode, "8 3 1 1", "8 3 4000000000000 1"), kTetGenEle),
                   "the file ends too soon"));
}

// -------------------------------------------------------------------------------------------
// Every reader, on every prefix and on corrupted bytes: a FileError or a valid mesh, never
// anything else (no crash, no other exception, no huge allocation).
// -------------------------------------------------------------------------------------------

void expectFileErrorOrValidMesh(const std::function<VolumeMesh(const std::string&)>& parse,
                                const std::string& text, const char* what) {
  try {
    const VolumeMesh mesh = parse(text);
    EXPECT_EQ(findVolumeMeshProblem(mesh), "") << what;
  } catch (const FileError&) {
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ": " << e.what();
  }
}

TEST(VolumeMeshFiles, EveryPrefixAndCorruptionIsRejectedCleanly) {
  const std::vector<std::pair<std::string, std::function<VolumeMesh(const std::string&)>>> cases = {
      {kVtkClassic, [](const std::string& t) { return parseVtkVolumeMesh(t, "f.vtk"); }},
      {kVtk51, [](const std::string& t) { return parseVtkVolumeMesh(t, "f.vtk"); }},
      {binaryVtk(BinaryLayout::ClassicFloat),
       [](const std::string& t) { return parseVtkVolumeMesh(t, "f.vtk"); }},
      {binaryVtk(BinaryLayout::Offsets64Double),
       [](const std::string& t) { return parseVtkVolumeMesh(t, "f.vtk"); }},
      {kGmsh22, [](const std::string& t) { return parseGmshMesh(t, "f.msh"); }},
      {kGmsh41, [](const std::string& t) { return parseGmshMesh(t, "f.msh"); }},
      {kTetGenEle,
       [](const std::string& t) { return parseTetGenMesh(kTetGenNode, t, "f.node", "f.ele"); }},
      {kTetGenNode,
       [](const std::string& t) { return parseTetGenMesh(t, kTetGenEle, "f.node", "f.ele"); }},
  };
  std::mt19937 random(11);
  const std::string interesting = std::string("0129-+.e \n\t$#xnN") + '\0' + '\xff' + '\x7f';
  for (const auto& [text, parse] : cases) {
    for (size_t length = 0; length < text.size(); ++length) {
      expectFileErrorOrValidMesh(parse, text.substr(0, length), "prefix");
    }
    for (int trial = 0; trial < 1500; ++trial) {
      std::string corrupted = text;
      const int edits = 1 + trial % 3;
      for (int e = 0; e < edits; ++e) {
        corrupted[random() % corrupted.size()] = interesting[random() % interesting.size()];
      }
      expectFileErrorOrValidMesh(parse, corrupted, "corrupted");
    }
  }
}

// -------------------------------------------------------------------------------------------
// readVolumeMesh: dispatch by extension, paths in messages
// -------------------------------------------------------------------------------------------

void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

TEST(ReadVolumeMesh, DispatchesOnTheExtension) {
  test::ScopedTempDir dir("volume_mesh_io");
  ASSERT_FALSE(dir.path().empty());
  writeText(dir.path() / "mixed.vtk", kVtkClassic);
  writeText(dir.path() / "MIXED.VTK", binaryVtk(BinaryLayout::Offsets64Double));
  writeText(dir.path() / "mixed.msh", kGmsh41);
  writeText(dir.path() / "cube.1.node", kTetGenNode);
  writeText(dir.path() / "cube.1.ele", kTetGenEle);
  expectTestMesh(readVolumeMesh(dir.path() / "mixed.vtk"));
  expectTestMesh(readVolumeMesh(dir.path() / "MIXED.VTK"));
  expectTestMesh(readVolumeMesh(dir.path() / "mixed.msh"));
  EXPECT_EQ(cellsOf(readVolumeMesh(dir.path() / "cube.1.node")), kCubeCells);
  EXPECT_EQ(cellsOf(readVolumeMesh(dir.path() / "cube.1.ele")), kCubeCells);

  // Messages start with the path of the file at fault.
  const std::filesystem::path broken = dir.path() / "broken.msh";
  writeText(broken, replaced(kGmsh22, "$Elements\n13", "$Elements\n14"));
  EXPECT_TRUE(rejectedWith([&] { readVolumeMesh(broken); }, broken.string() + ": line "));
  writeText(dir.path() / "lonely.node", kTetGenNode);
  EXPECT_TRUE(rejectedWith([&] { readVolumeMesh(dir.path() / "lonely.node"); },
                           (dir.path() / "lonely.ele").string() + ": cannot open"));
  EXPECT_TRUE(rejectedWith([&] { readVolumeMesh(dir.path() / "mesh.stl"); },
                           "unknown volume mesh extension '.stl'"));
}

// -------------------------------------------------------------------------------------------
// Meshes made by the real TetGen
// -------------------------------------------------------------------------------------------

TEST(TetGenRun, BoxMeshHasTheBoxVolumeAndIsValid) {
  SCULPT_REQUIRE_TOOL(test::tetgenAvailable(), "tetgen");
  test::ScopedTempDir dir("tetgen_box");
  std::string error;
  const Eigen::Vector3d lo(-1.0, 0.0, 0.5), hi(1.0, 1.0, 1.0);
  const auto mesh = test::tetgenMesh(test::boxSurface(lo, hi), 0.005, dir.path(), &error);
  ASSERT_TRUE(mesh) << error;
  EXPECT_GT(mesh->numCells(), 100u);
  EXPECT_EQ(findVolumeMeshProblem(*mesh), "");
  // TetGen's tetrahedra are positive in our convention (no reordering in the reader).
  for (uint32_t c = 0; c < mesh->numCells(); ++c) ASSERT_GT(tetrahedronSignedVolume(*mesh, c), 0.0);
  EXPECT_NEAR(test::totalTetrahedronVolume(*mesh), (hi - lo).prod(), 1e-9);
}

TEST(TetGenRun, SphereMeshVolumeIsCloseToTheBall) {
  SCULPT_REQUIRE_TOOL(test::tetgenAvailable(), "tetgen");
  test::ScopedTempDir dir("tetgen_sphere");
  std::string error;
  const double radius = 0.8;
  const test::TriangleSurface sphere =
      test::icosphereSurface(Eigen::Vector3d(0.1, 0.2, 0.3), radius, 4);
  ASSERT_EQ(sphere.triangles.size(), 5120u);
  const auto mesh = test::tetgenMesh(sphere, 0.002, dir.path(), &error);
  ASSERT_TRUE(mesh) << error;
  EXPECT_EQ(findVolumeMeshProblem(*mesh), "");
  const double ball = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  const double volume = test::totalTetrahedronVolume(*mesh);
  EXPECT_NEAR(volume, ball, 0.02 * ball);
  // TetGen fills exactly the polyhedron it was given.
  EXPECT_NEAR(volume, test::enclosedVolume(sphere), 1e-9);
}

}  // namespace
}  // namespace sculpt
