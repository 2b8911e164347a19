#include "io/vtk_writer.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "io/atomic_file.h"
#include "io/number_text.h"
#include "mesh/cell_shape.h"
#include "mesh/hexahedron.h"

namespace sculpt {
namespace {

void appendPoint(std::string& out, const Points& points, uint32_t row) {
  for (Eigen::Index k = 0; k < 3; ++k) {
    if (k > 0) out += ' ';
    appendNumber(out, points(row, k));
  }
  out += '\n';
}

// VTK names are single tokens.
std::string fieldName(const std::string& name) {
  std::string out = name.empty() ? std::string("field") : name;
  for (char& ch : out) {
    if (ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r') ch = '_';
  }
  return out;
}

}  // namespace

std::string vtkUnstructuredGrid(const CellComplex& complex, const Topology& topology,
                                std::span<const VtkPointVectors> pointVectors) {
  const uint32_t numPoints = complex.numVertices();
  const uint32_t numCells = topology.numCells();
  for (const VtkPointVectors& field : pointVectors) {
    if (field.values == nullptr || field.values->rows() != static_cast<Eigen::Index>(numPoints)) {
      throw std::invalid_argument("vtkUnstructuredGrid: field '" + field.name +
                                  "' must have one row per vertex");
    }
  }

  std::string out;
  out += "# vtk DataFile Version 4.2\nsculpt cell complex\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  out += "POINTS ";
  appendNumber(out, numPoints);
  out += " double\n";
  for (uint32_t v = 0; v < numPoints; ++v) appendPoint(out, complex.positions, v);

  // Cell connectivity. The size on the CELLS line counts every number that follows it.
  std::string cells;
  std::vector<uint8_t> types(numCells);
  std::vector<CellShape> shapes(numCells);
  uint64_t size = 0;
  std::vector<uint32_t> stream;
  for (uint32_t c = 0; c < numCells; ++c) {
    shapes[c] = classifyCellShape(topology, c);
    stream.clear();
    if (const auto hex = vtkHexahedronOrder(topology, c)) {
      types[c] = kVtkHexahedron;
      stream.assign(hex->begin(), hex->end());
    } else {
      // Polyhedron face stream: nFaces, then (nPts, ids...) per face, each loop outward.
      types[c] = kVtkPolyhedron;
      const uint32_t numFaces = topology.cellFaces.rowSize(c);
      stream.push_back(numFaces);
      for (uint32_t j = 0; j < numFaces; ++j) {
        const std::vector<uint32_t> loop = topology.outwardLoop(c, j);
        stream.push_back(static_cast<uint32_t>(loop.size()));
        stream.insert(stream.end(), loop.begin(), loop.end());
      }
    }
    appendNumber(cells, static_cast<uint32_t>(stream.size()));
    for (uint32_t id : stream) {
      cells += ' ';
      appendNumber(cells, id);
    }
    cells += '\n';
    size += 1 + stream.size();
  }
  out += "\nCELLS ";
  appendNumber(out, numCells);
  out += ' ';
  appendNumber(out, size);
  out += '\n';
  out += cells;

  out += "\nCELL_TYPES ";
  appendNumber(out, numCells);
  out += '\n';
  for (uint8_t type : types) {
    appendNumber(out, uint32_t{type});
    out += '\n';
  }

  out += "\nCELL_DATA ";
  appendNumber(out, numCells);
  out += "\nSCALARS shape int 1\nLOOKUP_TABLE default\n";
  for (CellShape shape : shapes) {
    appendNumber(out, static_cast<uint32_t>(shape));
    out += '\n';
  }

  if (!pointVectors.empty()) {
    out += "\nPOINT_DATA ";
    appendNumber(out, numPoints);
    out += '\n';
    for (const VtkPointVectors& field : pointVectors) {
      out += "VECTORS " + fieldName(field.name) + " double\n";
      for (uint32_t v = 0; v < numPoints; ++v) appendPoint(out, *field.values, v);
    }
  }
  return out;
}

void writeVtk(const CellComplex& complex, const Topology& topology,
              const std::filesystem::path& path, std::span<const VtkPointVectors> pointVectors) {
  writeFileAtomically(path, vtkUnstructuredGrid(complex, topology, pointVectors));
}

}  // namespace sculpt
