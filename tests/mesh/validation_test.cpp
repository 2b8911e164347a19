// Validation reports every defect with its kind, the element
// index and a sentence naming the element.

#include "mesh/validation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "io/control_mesh_json.h"
#include "mesh/topology.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

using Kind = ValidationIssue::Kind;
using Element = ValidationIssue::Element;
using Severity = ValidationIssue::Severity;
using test::gridVertex;
using test::hexLoops;

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return s;
}

std::string describe(const std::vector<ValidationIssue>& issues) {
  std::string out;
  for (const auto& i : issues)
    out += "  [" + std::to_string(static_cast<int>(i.kind)) + "] index " + std::to_string(i.index) +
           ": " + i.message + "\n";
  return out;
}

/// The issues of one kind.
std::vector<ValidationIssue> ofKind(const std::vector<ValidationIssue>& issues, Kind kind) {
  std::vector<ValidationIssue> out;
  for (const auto& i : issues)
    if (i.kind == kind) out.push_back(i);
  return out;
}

/// True when the message names the element: contains the word and the index as a whole number.
bool names(const std::string& message, const std::string& word, uint32_t index) {
  const std::string m = lower(message);
  if (m.find(word) == std::string::npos) return false;
  const std::string number = std::to_string(index);
  for (size_t at = m.find(number); at != std::string::npos; at = m.find(number, at + 1)) {
    const bool before = at == 0 || !std::isdigit(static_cast<unsigned char>(m[at - 1]));
    const size_t end = at + number.size();
    const bool after = end >= m.size() || !std::isdigit(static_cast<unsigned char>(m[end]));
    if (before && after) return true;
  }
  return false;
}

/// Expects exactly one error of `kind` about the element (element, index) whose message names it.
void expectIssue(const std::vector<ValidationIssue>& issues, Kind kind, Element element,
                 const std::set<uint32_t>& indices, const std::string& word,
                 Severity severity = Severity::Error) {
  const auto found = ofKind(issues, kind);
  ASSERT_FALSE(found.empty()) << "no issue of kind " << static_cast<int>(kind) << "; got\n"
                              << describe(issues);
  bool matched = false;
  for (const auto& i : found) {
    if (i.element != element || !indices.count(i.index)) continue;
    matched = true;
    EXPECT_EQ(i.severity, severity);
    EXPECT_TRUE(names(i.message, word, i.index))
        << "message does not name the " << word << " " << i.index << ": " << i.message;
    EXPECT_FALSE(i.message.empty());
  }
  EXPECT_TRUE(matched) << "no issue of kind " << static_cast<int>(kind)
                       << " on the expected element; got\n"
                       << describe(issues);
  if (severity == Severity::Error) {
    EXPECT_FALSE(isValid(issues));
  }
}

CellComplex twoCubes() { return test::hexGrid(2, 1, 1); }

TEST(Validation, CleanMeshesHaveNoIssues) {
  for (const CellComplex& m :
       {test::unitCube(), test::hexGrid(2, 2, 2), test::hexGrid(3, 2, 1), test::kuhnCube(),
        test::pyramidCube({0.5, 0.5, 0.75}), test::prismCube(), test::regularTet(),
        test::octahedron(), test::singlePrism(), test::singlePyramid(), test::mixedMesh()}) {
    const auto issues = validate(m);
    EXPECT_TRUE(issues.empty()) << describe(issues);
    EXPECT_TRUE(isValid(issues));
  }
}

TEST(Validation, IndexOutOfRange) {
  CellComplex m = twoCubes();  // 12 vertices
  // Cell 1 refers to vertex 99.
  m.loopVertices[m.loopBegin[m.cellFaceBegin[1]]] = 99;
  const auto issues = validate(m);
  expectIssue(issues, Kind::IndexOutOfRange, Element::Cell, {1}, "cell");
  for (const auto& i : ofKind(issues, Kind::IndexOutOfRange))
    EXPECT_NE(i.message.find("99"), std::string::npos) << i.message;
}

TEST(Validation, NonFiniteCoordinate) {
  for (double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity()}) {
    CellComplex m = twoCubes();
    m.positions(5, 1) = bad;
    const auto issues = validate(m);
    expectIssue(issues, Kind::NonFiniteCoordinate, Element::Vertex, {5}, "vertex");
    EXPECT_EQ(ofKind(issues, Kind::NonFiniteCoordinate).size(), 1u) << describe(issues);
  }
}

TEST(Validation, CellNotClosed) {
  // Cell 1 is a hex missing its top face.
  CellComplex m;
  m.positions = twoCubes().positions;
  auto g = [](int i, int j, int k) { return gridVertex(2, 1, i, j, k); };
  m.addCell(hexLoops({g(0, 0, 0), g(1, 0, 0), g(1, 1, 0), g(0, 1, 0), g(0, 0, 1), g(1, 0, 1),
                      g(1, 1, 1), g(0, 1, 1)}));
  auto open = hexLoops({g(1, 0, 0), g(2, 0, 0), g(2, 1, 0), g(1, 1, 0), g(1, 0, 1), g(2, 0, 1),
                        g(2, 1, 1), g(1, 1, 1)});
  open.erase(open.begin() + 1);  // the top face
  m.addCell(open);
  const auto issues = validate(m);
  expectIssue(issues, Kind::CellNotClosed, Element::Cell, {1}, "cell");
  for (const auto& i : ofKind(issues, Kind::CellNotClosed)) EXPECT_EQ(i.index, 1u);
}

TEST(Validation, FaceReversedInsideOneCell) {
  CellComplex m = twoCubes();
  // Reverse the 3rd face loop of cell 1.
  const uint32_t loop = m.cellFaceBegin[1] + 2;
  std::reverse(m.loopVertices.begin() + m.loopBegin[loop],
               m.loopVertices.begin() + m.loopBegin[loop + 1]);
  const auto issues = validate(m);
  expectIssue(issues, Kind::InconsistentOrientation, Element::Cell, {1}, "cell");
}

TEST(Validation, SharedFaceWithSameOrientation) {
  // Cell 1 turned inside out: internally consistent, but it sees the shared face with the same
  // orientation as cell 0 (and has negative volume).
  CellComplex m = twoCubes();
  for (uint32_t loop = m.cellFaceBegin[1]; loop < m.cellFaceBegin[2]; ++loop)
    std::reverse(m.loopVertices.begin() + m.loopBegin[loop],
                 m.loopVertices.begin() + m.loopBegin[loop + 1]);
  const auto issues = validate(m);
  expectIssue(issues, Kind::InconsistentOrientation, Element::Cell, {0, 1}, "cell");
}

TEST(Validation, FaceSharedByMoreThanTwoCells) {
  // A third hex on the face x = 1 of the two-cube block, sheared away in y.
  CellComplex m = twoCubes();
  auto g = [](int i, int j, int k) { return gridVertex(2, 1, i, j, k); };
  const uint32_t n = m.numVertices();
  m.positions.conservativeResize(n + 4, 3);
  m.positions.row(n + 0) << 2.0, 3.0, 0.0;
  m.positions.row(n + 1) << 2.0, 4.0, 0.0;
  m.positions.row(n + 2) << 2.0, 3.0, 1.0;
  m.positions.row(n + 3) << 2.0, 4.0, 1.0;
  // Corners: face x = 1 (1,0,0),(1,1,0),(1,1,1),(1,0,1) and the new x = 2 face.
  m.addCell(hexLoops({g(1, 0, 0), n + 0, n + 1, g(1, 1, 0), g(1, 0, 1), n + 2, n + 3, g(1, 1, 1)}));
  const auto issues = validate(m);
  expectIssue(issues, Kind::FaceSharedByMoreThanTwoCells, Element::Cell, {0, 1, 2}, "cell");
}

TEST(Validation, InteriorEdgeWithTwoFaces) {
  // Two hexes glued along two faces around the vertical edge O_b - O_t: in the xy plane the
  // upper cell is O, R1, U, R2 and the lower one O, R2, D, R1 (O is a reflex corner of it).
  std::vector<Eigen::Vector3d> p;
  const double xy[5][2] = {{0, 0}, {1, 0.2}, {0, 1}, {-1, 0.2}, {0, -1}};  // O R1 U R2 D
  for (double z : {0.0, 1.0})
    for (const auto& q : xy) p.emplace_back(q[0], q[1], z);
  const uint32_t O = 0, R1 = 1, U = 2, R2 = 3, D = 4;
  auto top = [](uint32_t v) { return v + 5; };
  std::vector<test::Loops> cells = {hexLoops({O, R1, U, R2, top(O), top(R1), top(U), top(R2)}),
                                    hexLoops({O, R2, D, R1, top(O), top(R2), top(D), top(R1)})};
  const CellComplex m = test::makeComplex(p, cells);
  ASSERT_EQ(test::closedOrientedCheck(m), "");
  ASSERT_GT(test::signedVolume(m, 0), 0.0);
  ASSERT_GT(test::signedVolume(m, 1), 0.0);
  const auto issues = validate(m);
  expectIssue(issues, Kind::InteriorEdgeValenceTwo, Element::Edge, {O, top(O)}, "edge");
  // The cells themselves are fine.
  EXPECT_TRUE(ofKind(issues, Kind::CellNotClosed).empty()) << describe(issues);
  EXPECT_TRUE(ofKind(issues, Kind::NonPositiveVolume).empty()) << describe(issues);
}

TEST(Validation, NonManifoldBoundaryEdge) {
  // Two unit cubes sharing only the edge (1,1,0)-(1,1,1).
  std::vector<Eigen::Vector3d> p;
  auto add = [&](double x, double y, double z) {
    p.emplace_back(x, y, z);
    return static_cast<uint32_t>(p.size() - 1);
  };
  std::array<uint32_t, 8> a{}, b{};
  const double cube[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                             {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int i = 0; i < 8; ++i) a[static_cast<size_t>(i)] = add(cube[i][0], cube[i][1], cube[i][2]);
  for (int i = 0; i < 8; ++i) {
    const double x = cube[i][0] + 1, y = cube[i][1] + 1, z = cube[i][2];
    if (i == 0)
      b[0] = a[2];  // (1,1,0)
    else if (i == 4)
      b[4] = a[6];  // (1,1,1)
    else
      b[static_cast<size_t>(i)] = add(x, y, z);
  }
  const CellComplex m = test::makeComplex(p, {hexLoops(a), hexLoops(b)});
  const auto issues = validate(m);
  expectIssue(issues, Kind::NonManifoldBoundaryEdge, Element::Edge, {a[2], a[6]}, "edge");
}

TEST(Validation, NonManifoldBoundaryVertex) {
  // Two unit cubes touching at the vertex (1,1,1) only: two boundary fans there.
  std::vector<Eigen::Vector3d> p;
  std::array<uint32_t, 8> a{}, b{};
  const double cube[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                             {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int i = 0; i < 8; ++i) {
    p.emplace_back(cube[i][0], cube[i][1], cube[i][2]);
    a[static_cast<size_t>(i)] = static_cast<uint32_t>(i);
  }
  for (int i = 0; i < 8; ++i) {
    if (i == 0) {
      b[0] = a[6];
      continue;
    }
    p.emplace_back(cube[i][0] + 1, cube[i][1] + 1, cube[i][2] + 1);
    b[static_cast<size_t>(i)] = static_cast<uint32_t>(p.size() - 1);
  }
  const CellComplex m = test::makeComplex(p, {hexLoops(a), hexLoops(b)});
  const auto issues = validate(m);
  expectIssue(issues, Kind::NonManifoldBoundaryVertex, Element::Vertex, {a[6]}, "vertex");
  EXPECT_TRUE(ofKind(issues, Kind::NonManifoldBoundaryEdge).empty()) << describe(issues);
}

TEST(Validation, ZeroVolumeCell) {
  CellComplex m = twoCubes();
  // Flatten cell 1 ([1,2] x [0,1] x [0,1]) onto the plane x = 1: its x = 2 vertices (used by
  // cell 1 only) move to x = 1. Cell 0 stays intact.
  for (int j = 0; j <= 1; ++j)
    for (int k = 0; k <= 1; ++k) m.positions(gridVertex(2, 1, 2, j, k), 0) = 1.0;
  const auto issues = validate(m);
  expectIssue(issues, Kind::NonPositiveVolume, Element::Cell, {1}, "cell");
  for (const auto& i : ofKind(issues, Kind::NonPositiveVolume)) EXPECT_EQ(i.index, 1u);
}

TEST(Validation, NegativeVolumeCell) {
  // A single hex mirrored in z with unchanged loops: closed, consistent, but inside out.
  CellComplex m = test::unitCube();
  m.positions.col(2) *= -1.0;
  const auto issues = validate(m);
  expectIssue(issues, Kind::NonPositiveVolume, Element::Cell, {0}, "cell");
  EXPECT_LT(cellVolume(m, 0), 0.0);
  EXPECT_NEAR(cellVolume(m, 0), -1.0, 1e-14);
}

TEST(Validation, CellOfTwoDisjointSolidsIsRefused) {
  // Two tetrahedra listed as one cell: every edge is used twice, once each way, and the volume
  // is positive, but the cell is two solids.
  const std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                          {3, 0, 0}, {4, 0, 0}, {3, 1, 0}, {3, 0, 1}};
  test::Loops loops = test::tetLoops({0, 1, 2, 3});
  const test::Loops second = test::tetLoops({4, 5, 6, 7});
  loops.insert(loops.end(), second.begin(), second.end());
  const auto issues = validate(test::makeComplex(p, {loops}));
  expectIssue(issues, Kind::CellNotBall, Element::Cell, {0}, "cell");
  EXPECT_EQ(ofKind(issues, Kind::CellNotBall)[0].message,
            "cell 0 is not one solid: its faces form 2 separate closed surfaces (list each part "
            "as a cell of its own)");
  EXPECT_EQ(issues.size(), 1u) << describe(issues);  // its corners are not judged as well
  // Listed as two cells they are fine.
  const auto apart = validate(test::makeComplex(p, {test::tetLoops({0, 1, 2, 3}), second}));
  EXPECT_TRUE(apart.empty()) << describe(apart);
}

TEST(Validation, CellWithAHoleIsRefused) {
  // A square frame (outer square 3 wide, a hole 1 wide) as one cell of 16 quadrilaterals: closed,
  // connected and of positive volume, but a torus (vertices - edges + faces = 16 - 32 + 16).
  std::vector<Eigen::Vector3d> p;
  const double outer[4][2] = {{0, 0}, {3, 0}, {3, 3}, {0, 3}};
  const double inner[4][2] = {{1, 1}, {2, 1}, {2, 2}, {1, 2}};
  for (int z = 0; z < 2; ++z)
    for (int i = 0; i < 4; ++i) {
      p.emplace_back(outer[i][0], outer[i][1], z);
      p.emplace_back(inner[i][0], inner[i][1], z);
    }
  const auto o = [](int i, int z) { return test::u32(8 * z + 2 * (i % 4)); };
  const auto n = [](int i, int z) { return test::u32(8 * z + 2 * (i % 4) + 1); };
  test::Loops loops;
  for (int i = 0; i < 4; ++i) {
    loops.push_back({o(i, 1), o(i + 1, 1), n(i + 1, 1), n(i, 1)});  // top
    loops.push_back({n(i, 0), n(i + 1, 0), o(i + 1, 0), o(i, 0)});  // bottom
    loops.push_back({o(i, 0), o(i + 1, 0), o(i + 1, 1), o(i, 1)});  // outside
    loops.push_back({n(i + 1, 0), n(i, 0), n(i, 1), n(i + 1, 1)});  // around the hole
  }
  const CellComplex frame = test::makeComplex(p, {loops});
  EXPECT_NEAR(cellVolume(frame, 0), 8.0, 1e-12);
  const auto issues = validate(frame);
  expectIssue(issues, Kind::CellNotBall, Element::Cell, {0}, "cell");
  EXPECT_NE(ofKind(issues, Kind::CellNotBall)[0].message.find("vertices - edges + faces = 0"),
            std::string::npos)
      << describe(issues);
}

TEST(Validation, UnusedVertexIsAWarning) {
  CellComplex m = twoCubes();
  const uint32_t extra = m.numVertices();
  m.positions.conservativeResize(extra + 1, 3);
  m.positions.row(extra) << 5.0, 5.0, 5.0;
  const auto issues = validate(m);
  expectIssue(issues, Kind::UnusedVertex, Element::Vertex, {extra}, "vertex", Severity::Warning);
  EXPECT_TRUE(isValid(issues)) << describe(issues);
  EXPECT_EQ(issues.size(), 1u) << describe(issues);
}

TEST(Validation, DegenerateFace) {
  // Cell 1 of the two-cube block has a face loop with a repeated vertex.
  CellComplex m = twoCubes();
  const uint32_t loop = m.cellFaceBegin[1] + 2;
  const uint32_t begin = m.loopBegin[loop];
  m.loopVertices[begin + 1] = m.loopVertices[begin];
  const auto issues = validate(m);
  const auto found = ofKind(issues, Kind::DegenerateFace);
  ASSERT_FALSE(found.empty()) << describe(issues);
  bool matched = false;
  for (const auto& i : found) {
    if (i.index != 1u) continue;
    matched = true;
    EXPECT_TRUE(i.element == Element::Cell || i.element == Element::Face);
    EXPECT_TRUE(names(i.message, "cell", 1)) << i.message;
    EXPECT_NE(lower(i.message).find("face"), std::string::npos) << i.message;
  }
  EXPECT_TRUE(matched) << describe(issues);
  EXPECT_FALSE(isValid(issues));
  // A two-vertex "face" is degenerate too.
  CellComplex sliver = test::unitCube();
  sliver.cellFaceBegin.pop_back();
  sliver.addLoop(std::vector<uint32_t>{0, 1});
  sliver.finishCell();
  const auto issues2 = validate(sliver);
  EXPECT_FALSE(ofKind(issues2, Kind::DegenerateFace).empty()) << describe(issues2);
}

TEST(Validation, BadTags) {
  const CellComplex block = test::hexGrid(2, 2, 2);
  auto g = [](int i, int j, int k) { return gridVertex(2, 2, i, j, k); };
  {
    // Crease on an interior edge.
    CellComplex m = block;
    m.creases = {{g(1, 1, 1), g(1, 1, 2)}};
    const auto issues = validate(m);
    expectIssue(issues, Kind::BadTag, Element::Edge, {g(1, 1, 1), g(1, 1, 2)}, "edge");
  }
  {
    // Crease between vertices that share no edge.
    CellComplex m = block;
    m.creases = {{g(0, 0, 0), g(2, 2, 2)}};
    const auto issues = validate(m);
    expectIssue(issues, Kind::BadTag, Element::Edge, {g(0, 0, 0), g(2, 2, 2)}, "edge");
  }
  {
    // Corner on an interior vertex.
    CellComplex m = block;
    m.corners = {g(1, 1, 1)};
    const auto issues = validate(m);
    expectIssue(issues, Kind::BadTag, Element::Vertex, {g(1, 1, 1)}, "vertex");
  }
  {
    // Boundary tags are fine.
    CellComplex m = block;
    m.creases = {{g(0, 0, 0), g(1, 0, 0)}, {g(1, 1, 0), g(1, 2, 0)}};
    m.corners = {g(0, 0, 0), g(1, 1, 0)};
    const auto issues = validate(m);
    EXPECT_TRUE(issues.empty()) << describe(issues);
  }
}

TEST(Validation, EmptyMesh) {
  const auto issues = validate(CellComplex{});
  ASSERT_FALSE(ofKind(issues, Kind::EmptyMesh).empty()) << describe(issues);
  EXPECT_EQ(ofKind(issues, Kind::EmptyMesh)[0].element, Element::Mesh);
  EXPECT_FALSE(ofKind(issues, Kind::EmptyMesh)[0].message.empty());
  EXPECT_FALSE(isValid(issues));
  // Vertices but no cells is also empty.
  CellComplex points;
  points.positions = test::unitCube().positions;
  EXPECT_FALSE(ofKind(validate(points), Kind::EmptyMesh).empty());
  EXPECT_FALSE(isValid(validate(points)));
}

TEST(Validation, FrozenKindValues) {
  EXPECT_EQ(static_cast<int>(Kind::IndexOutOfRange), 1);
  EXPECT_EQ(static_cast<int>(Kind::InteriorEdgeValenceTwo), 6);
  EXPECT_EQ(static_cast<int>(Kind::NonPositiveVolume), 9);
  EXPECT_EQ(static_cast<int>(Kind::BadTag), 13);
  EXPECT_EQ(static_cast<int>(Kind::CellNotBall), 14);
  EXPECT_EQ(static_cast<int>(Kind::InvertedCorner), 15);
}

TEST(Validation, AssetsAreClean) {
  const std::filesystem::path dir = std::filesystem::path(SCULPT_SOURCE_DIR) / "assets";
  ASSERT_TRUE(std::filesystem::is_directory(dir)) << "no assets folder " << dir.string();
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().filename().string());
    {  // the mock stylus' device scripts live here too (docs/file-formats.md)
      std::ifstream in(entry.path());
      const std::string text((std::istreambuf_iterator<char>(in)),
                             std::istreambuf_iterator<char>());
      if (text.find("\"format\": \"sculpt-device-script\"") != std::string::npos) continue;
    }
    CellComplex m;
    try {
      m = loadControlMeshJson(entry.path());
    } catch (const std::exception& e) {
      ADD_FAILURE() << "cannot load: " << e.what();
      continue;
    }
    const auto issues = validate(m);
    EXPECT_TRUE(issues.empty()) << describe(issues);
    EXPECT_TRUE(test::closedOrientedCheck(m).empty()) << test::closedOrientedCheck(m);
    for (uint32_t c = 0; c < m.numCells(); ++c) EXPECT_GT(test::signedVolume(m, c), 0.0);
    ++checked;
  }
  EXPECT_GE(checked, 5) << "the bundled control meshes are missing from " << dir.string();
}

}  // namespace
}  // namespace sculpt
