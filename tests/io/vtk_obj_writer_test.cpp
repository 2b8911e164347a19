// VTK and OBJ export: hexahedra in VTK vertex order, other cells as polyhedron face streams,
// the shape field, and an outward, compacted boundary surface.

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "io/obj_writer.h"
#include "io/vtk_writer.h"
#include "mesh/cell_shape.h"
#include "mesh/standard_cell.h"
#include "mesh/topology.h"
#include "subdiv/mj_refiner.h"
#include "support/mesh_builders.h"

namespace sculpt {
namespace {

using test::Loops;

struct ParsedVtk {
  std::vector<Eigen::Vector3d> points;
  uint64_t cellsSize = 0;  // the size on the CELLS line
  std::vector<std::vector<int64_t>> cells;
  std::vector<int> types;
  std::vector<int> shapes;
  std::map<std::string, std::vector<Eigen::Vector3d>> vectors;
};

// A reader for exactly what vtkUnstructuredGrid writes (sections in order, one cell per line).
ParsedVtk parseVtk(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "# vtk DataFile Version 4.2");
  std::getline(in, line);  // title
  std::getline(in, line);
  EXPECT_EQ(line, "ASCII");
  std::getline(in, line);
  EXPECT_EQ(line, "DATASET UNSTRUCTURED_GRID");
  ParsedVtk vtk;
  std::string keyword;
  while (in >> keyword) {
    if (keyword == "POINTS") {
      size_t n = 0;
      std::string type;
      in >> n >> type;
      EXPECT_EQ(type, "double");
      vtk.points.resize(n);
      for (auto& p : vtk.points) in >> p.x() >> p.y() >> p.z();
    } else if (keyword == "CELLS") {
      size_t n = 0;
      in >> n >> vtk.cellsSize;
      std::getline(in, line);
      for (size_t c = 0; c < n; ++c) {
        std::getline(in, line);
        std::istringstream cellLine(line);
        std::vector<int64_t> values;
        int64_t value = 0;
        while (cellLine >> value) values.push_back(value);
        vtk.cells.push_back(values);
      }
    } else if (keyword == "CELL_TYPES") {
      size_t n = 0;
      in >> n;
      vtk.types.resize(n);
      for (int& t : vtk.types) in >> t;
    } else if (keyword == "CELL_DATA") {
      size_t n = 0;
      std::string scalars, name, type, one, lookup, table;
      in >> n >> scalars >> name >> type >> one >> lookup >> table;
      EXPECT_EQ(scalars + " " + name + " " + type + " " + one, "SCALARS shape int 1");
      vtk.shapes.resize(n);
      for (int& s : vtk.shapes) in >> s;
    } else if (keyword == "POINT_DATA") {
      size_t n = 0;
      in >> n;
      std::string vectors, name, type;
      while (in >> vectors >> name >> type) {
        EXPECT_EQ(vectors, "VECTORS");
        auto& field = vtk.vectors[name];
        field.resize(n);
        for (auto& p : field) in >> p.x() >> p.y() >> p.z();
      }
    } else {
      ADD_FAILURE() << "unexpected keyword " << keyword;
      break;
    }
  }
  return vtk;
}

// The loop rotated to start at its smallest vertex, so that equal cycles compare equal.
std::vector<uint32_t> canonicalLoop(std::vector<uint32_t> loop) {
  std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
  return loop;
}

std::vector<std::vector<uint32_t>> canonicalLoops(const Loops& loops) {
  std::vector<std::vector<uint32_t>> result;
  for (const auto& loop : loops) result.push_back(canonicalLoop(loop));
  std::sort(result.begin(), result.end());
  return result;
}

Eigen::Vector3d newellNormal(const std::vector<Eigen::Vector3d>& p) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < p.size(); ++i) n += p[i].cross(p[(i + 1) % p.size()]);
  return n;
}

TEST(VtkWriter, HexahedronIsType12InVtkOrderWhicheverFaceComesFirst) {
  // A sheared, rotated hexahedron, with its faces listed starting at each face in turn and its
  // loops starting at different vertices.
  std::vector<Eigen::Vector3d> points = test::cubeCorners();
  for (auto& p : points) p = Eigen::Vector3d(p.x() + 0.3 * p.z(), p.y() - 0.2 * p.x(), p.z() * 1.5);
  const Loops hex = test::hexLoops({0, 1, 3, 2, 4, 5, 7, 6});
  for (size_t first = 0; first < hex.size(); ++first) {
    SCOPED_TRACE("first face " + std::to_string(first));
    Loops loops;
    for (size_t j = 0; j < hex.size(); ++j) {
      std::vector<uint32_t> loop = hex[(first + j) % hex.size()];
      std::rotate(loop.begin(), loop.begin() + static_cast<long>((first + j) % 4), loop.end());
      loops.push_back(loop);
    }
    const CellComplex mesh = test::makeComplex(points, {loops});
    const Topology topology = buildTopology(mesh);
    const ParsedVtk vtk = parseVtk(vtkUnstructuredGrid(mesh, topology));
    ASSERT_EQ(vtk.types, std::vector<int>{kVtkHexahedron});
    ASSERT_EQ(vtk.cells.size(), 1u);
    ASSERT_EQ(vtk.cells[0].size(), 9u);
    EXPECT_EQ(vtk.cells[0][0], 8);
    EXPECT_EQ(vtk.cellsSize, 9u);
    EXPECT_EQ(vtk.shapes, std::vector<int>{static_cast<int>(CellShape::Hexahedron)});
    std::vector<uint32_t> order;
    for (size_t i = 1; i < 9; ++i) order.push_back(static_cast<uint32_t>(vtk.cells[0][i]));
    // VTK's own face table over this order gives back exactly the cell's outward faces.
    EXPECT_EQ(canonicalLoops(standardCellFaces(StandardCell::Hexahedron, order)),
              canonicalLoops(loops));
    // The bottom face's normal (0-1-2-3, right-hand rule) points to the top face.
    std::vector<Eigen::Vector3d> bottom, top;
    for (size_t i = 0; i < 4; ++i) bottom.push_back(points[order[i]]);
    for (size_t i = 4; i < 8; ++i) top.push_back(points[order[i]]);
    const Eigen::Vector3d up = (top[0] + top[1] + top[2] + top[3]) / 4.0 -
                               (bottom[0] + bottom[1] + bottom[2] + bottom[3]) / 4.0;
    EXPECT_GT(newellNormal(bottom).dot(up), 0.0);
  }
}

TEST(VtkWriter, PyramidIsPolyhedronWithOutwardFaceStream) {
  const CellComplex mesh = test::singlePyramid();
  const Topology topology = buildTopology(mesh);
  const ParsedVtk vtk = parseVtk(vtkUnstructuredGrid(mesh, topology));
  ASSERT_EQ(vtk.types, std::vector<int>{kVtkPolyhedron});
  EXPECT_EQ(vtk.shapes, std::vector<int>{static_cast<int>(CellShape::Pyramid)});
  ASSERT_EQ(vtk.cells.size(), 1u);
  const std::vector<int64_t>& stream = vtk.cells[0];
  // n_total, nFaces, (nPts, ids...) per face; n_total counts what follows it.
  ASSERT_GE(stream.size(), 2u);
  EXPECT_EQ(stream[0], static_cast<int64_t>(stream.size() - 1));
  EXPECT_EQ(vtk.cellsSize, stream.size());
  ASSERT_EQ(stream[1], 5);
  Loops faces;
  size_t at = 2;
  for (int f = 0; f < 5; ++f) {
    ASSERT_LT(at, stream.size());
    const auto n = static_cast<size_t>(stream[at++]);
    ASSERT_LE(at + n, stream.size());
    std::vector<uint32_t> face;
    for (size_t i = 0; i < n; ++i) face.push_back(static_cast<uint32_t>(stream[at + i]));
    at += n;
    faces.push_back(face);
  }
  EXPECT_EQ(at, stream.size());
  Loops outward;
  for (uint32_t j = 0; j < mesh.numFacesOfCell(0); ++j) {
    const auto loop = mesh.cellFace(0, j);
    outward.emplace_back(loop.begin(), loop.end());
  }
  EXPECT_EQ(canonicalLoops(faces), canonicalLoops(outward));
  // Each face's normal points away from the cell's centre.
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (uint32_t v = 0; v < 5; ++v) centre += test::pos(mesh, v) / 5.0;
  for (const auto& face : faces) {
    std::vector<Eigen::Vector3d> p;
    for (uint32_t v : face) p.push_back(test::pos(mesh, v));
    EXPECT_GT(newellNormal(p).dot(p[0] - centre), 0.0);
  }
}

TEST(VtkWriter, PointsAndVectorFieldsKeepEveryDigit) {
  CellComplex mesh = test::singlePrism();
  mesh.positions(1, 0) = 0.1 + 0.2;
  const Topology topology = buildTopology(mesh);
  Points displacement = mesh.positions * (1.0 / 3.0);
  const std::vector<VtkPointVectors> fields = {{"displacement", &displacement}};
  const ParsedVtk vtk = parseVtk(vtkUnstructuredGrid(mesh, topology, fields));
  ASSERT_EQ(vtk.points.size(), 6u);
  ASSERT_EQ(vtk.vectors.count("displacement"), 1u);
  for (uint32_t v = 0; v < 6; ++v) {
    EXPECT_EQ(vtk.points[v], test::pos(mesh, v));
    EXPECT_EQ(vtk.vectors.at("displacement")[v], test::pos(displacement, v));
  }
  EXPECT_EQ(vtk.types, std::vector<int>{kVtkPolyhedron});
  EXPECT_EQ(vtk.shapes, std::vector<int>{static_cast<int>(CellShape::Prism)});
  Points wrong(2, 3);
  const std::vector<VtkPointVectors> bad = {{"wrong", &wrong}};
  EXPECT_THROW(vtkUnstructuredGrid(mesh, topology, bad), std::invalid_argument);
}

TEST(CellShape, ClassifiesEveryKind) {
  EXPECT_EQ(classifyCellShape(buildTopology(test::regularTet()), 0), CellShape::Tetrahedron);
  EXPECT_EQ(classifyCellShape(buildTopology(test::singlePyramid()), 0), CellShape::Pyramid);
  EXPECT_EQ(classifyCellShape(buildTopology(test::singlePrism()), 0), CellShape::Prism);
  EXPECT_EQ(classifyCellShape(buildTopology(test::unitCube()), 0), CellShape::Hexahedron);

  // A pentagonal prism is none of the named shapes.
  std::vector<Eigen::Vector3d> points;
  for (int z = 0; z < 2; ++z)
    for (int i = 0; i < 5; ++i)
      points.emplace_back(std::cos(1.2566370614359172 * i), std::sin(1.2566370614359172 * i), z);
  Loops pentagonal = {{0, 4, 3, 2, 1}, {5, 6, 7, 8, 9}};
  for (uint32_t i = 0; i < 5; ++i) pentagonal.push_back({i, (i + 1) % 5, (i + 1) % 5 + 5, i + 5});
  EXPECT_EQ(classifyCellShape(buildTopology(test::makeComplex(points, {pentagonal})), 0),
            CellShape::Polyhedron);

  // MJ refinement of a pyramid: 4 hexahedra and one square trapezohedron at the apex.
  const auto refined = subdivide(test::singlePyramid(), 1);
  ASSERT_TRUE(refined);
  std::map<CellShape, int> counts;
  const Topology& fine = refined->finestTopology();
  for (uint32_t c = 0; c < fine.numCells(); ++c) ++counts[classifyCellShape(fine, c)];
  EXPECT_EQ(counts[CellShape::Hexahedron], 4);
  EXPECT_EQ(counts[CellShape::Trapezohedron], 1);
  EXPECT_EQ(counts.size(), 2u);

  EXPECT_STREQ(cellShapeName(CellShape::Trapezohedron), "trapezohedron");
  EXPECT_STREQ(cellShapeName(CellShape::Tetrahedron), "tet");
}

struct ParsedObj {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::vector<int>> faces;  // 1-based
  std::string header;
};

ParsedObj parseObj(const std::string& text) {
  ParsedObj obj;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string kind;
    words >> kind;
    if (kind == "#") {
      obj.header = line;
    } else if (kind == "v") {
      Eigen::Vector3d p;
      words >> p.x() >> p.y() >> p.z();
      obj.vertices.push_back(p);
    } else if (kind == "f") {
      std::vector<int> face;
      int index = 0;
      while (words >> index) face.push_back(index);
      obj.faces.push_back(face);
    } else {
      ADD_FAILURE() << "unexpected line: " << line;
    }
  }
  return obj;
}

// Volume enclosed by a closed polygon surface (divergence theorem, faces fanned).
double enclosedVolume(const ParsedObj& obj) {
  double volume = 0.0;
  for (const auto& face : obj.faces) {
    const Eigen::Vector3d& a = obj.vertices[static_cast<size_t>(face[0] - 1)];
    for (size_t i = 1; i + 1 < face.size(); ++i) {
      const Eigen::Vector3d& b = obj.vertices[static_cast<size_t>(face[i] - 1)];
      const Eigen::Vector3d& c = obj.vertices[static_cast<size_t>(face[i + 1] - 1)];
      volume += a.dot(b.cross(c)) / 6.0;
    }
  }
  return volume;
}

TEST(ObjWriter, BoundaryOfTwoByOneByOneBlockIsOutward) {
  const CellComplex mesh = test::hexGrid(2, 1, 1);
  const Topology topology = buildTopology(mesh);
  BoundarySurfaceCounts counts;
  const ParsedObj obj = parseObj(boundaryObj(mesh, topology, &counts));
  EXPECT_EQ(counts.vertices, 12u);
  EXPECT_EQ(counts.faces, 10u);
  EXPECT_NE(obj.header.find("12 vertices, 10 faces"), std::string::npos) << obj.header;
  ASSERT_EQ(obj.vertices.size(), 12u);
  ASSERT_EQ(obj.faces.size(), 10u);
  // Every vertex is on the boundary, so the OBJ keeps the original order.
  for (uint32_t v = 0; v < 12; ++v) EXPECT_EQ(obj.vertices[v], test::pos(mesh, v));
  const Eigen::Vector3d centre(1.0, 0.5, 0.5);
  for (const auto& face : obj.faces) {
    ASSERT_EQ(face.size(), 4u);
    std::vector<Eigen::Vector3d> p;
    for (int i : face) {
      ASSERT_GE(i, 1);
      ASSERT_LE(i, 12);
      p.push_back(obj.vertices[static_cast<size_t>(i - 1)]);
    }
    EXPECT_GT(newellNormal(p).dot((p[0] + p[2]) / 2.0 - centre), 0.0);
  }
  EXPECT_NEAR(enclosedVolume(obj), 2.0, 1e-12);
}

TEST(ObjWriter, InteriorVerticesAreLeftOutAndIndicesCompacted) {
  const CellComplex mesh = test::hexGrid(3, 3, 3);
  const Topology topology = buildTopology(mesh);
  const ParsedObj obj = parseObj(boundaryObj(mesh, topology));
  ASSERT_EQ(obj.vertices.size(), 64u - 8u);
  ASSERT_EQ(obj.faces.size(), 54u);
  // Vertices appear in increasing original order: skip the 8 interior ones.
  size_t next = 0;
  for (uint32_t v = 0; v < mesh.numVertices(); ++v) {
    if (!topology.vertexIsBoundary[v]) continue;
    ASSERT_LT(next, obj.vertices.size());
    EXPECT_EQ(obj.vertices[next++], test::pos(mesh, v));
  }
  EXPECT_NEAR(enclosedVolume(obj), 27.0, 1e-12);
}

}  // namespace
}  // namespace sculpt
