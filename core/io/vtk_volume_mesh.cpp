// [SECTION] index: cell types; big-endian numbers; VtkReader (header, POINTS, CELLS in both
// layouts, CELL_TYPES, skipped FIELD/METADATA, building the mesh); the writer.

#include "io/vtk_volume_mesh.h"

#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include "io/atomic_file.h"
#include "io/input_file.h"
#include "io/number_text.h"
#include "io/text_scanner.h"
#include "io/volume_mesh_file.h"
#include "io/vtk_binary.h"

namespace sculpt {
namespace {

// VTK cell type numbers (vtkCellType.h).
constexpr int64_t kTetra = 10;
constexpr int64_t kVoxel = 11;
constexpr int64_t kHexahedron = 12;
constexpr int64_t kWedge = 13;
constexpr int64_t kPyramid = 14;

/// Cells of dimension 0, 1 or 2 (vertices, lines, polygons, quadratic and Lagrange/Bézier curves
/// and surfaces): writers often add boundary faces, which a volume mesh does not need.
bool isLowerDimensionalCellType(int64_t type) {
  return (type >= 0 && type <= 9) ||  // empty, vertex, line, triangle, polygon, pixel, quad ...
         type == 21 || type == 22 || type == 23 ||  // quadratic edge, triangle, quad
         type == 28 || type == 30 ||                // biquadratic quad, quadratic-linear quad
         (type >= 34 && type <= 36) ||  // biquadratic triangle, cubic line, quadratic polygon
         (type >= 68 && type <= 70) ||  // Lagrange curve, triangle, quadrilateral
         (type >= 75 && type <= 77);    // Bézier curve, triangle, quadrilateral
}

const char* unsupportedCellTypeName(int64_t type) {
  switch (type) {
    case 24:
      return "quadratic tetrahedron";
    case 25:
      return "quadratic hexahedron";
    case 26:
      return "quadratic wedge";
    case 27:
      return "quadratic pyramid";
    case 29:
      return "triquadratic hexahedron";
    case 31:
      return "quadratic-linear wedge";
    case 32:
      return "biquadratic-quadratic wedge";
    case 33:
      return "biquadratic-quadratic hexahedron";
    case 37:
      return "triquadratic pyramid";
    case 41:
      return "convex point set";
    case 42:
      return "polyhedron";
    case 71:
      return "Lagrange tetrahedron";
    case 72:
      return "Lagrange hexahedron";
    case 73:
      return "Lagrange wedge";
    case 74:
      return "Lagrange pyramid";
    case 78:
      return "Bézier tetrahedron";
    case 79:
      return "Bézier hexahedron";
    case 80:
      return "Bézier wedge";
    case 81:
      return "Bézier pyramid";
    default:
      return nullptr;
  }
}

class VtkReader {
 public:
  VtkReader(std::string_view bytes, std::string_view sourceName)
      : scanner_(bytes, sourceName), source_(sourceName) {}

  VolumeMesh read(CellShapeCheck shapes) {
    shapes_ = shapes;
    readHeader();
    // The dataset sections, in any order, until the three that make the mesh are read; what
    // follows them (POINT_DATA, CELL_DATA, FIELD) is not needed.
    while (!havePoints_ || !haveCells_ || !haveCellTypes_) {
      const std::string_view keyword = scanner_.token();
      if (keyword.empty()) scanner_.fail("the file ends before " + missingSections());
      if (equalsIgnoringCase(keyword, "POINTS")) {
        readPoints();
      } else if (equalsIgnoringCase(keyword, "CELLS")) {
        readCells();
      } else if (equalsIgnoringCase(keyword, "CELL_TYPES")) {
        readCellTypes();
      } else if (equalsIgnoringCase(keyword, "FIELD")) {
        skipFieldData();
      } else if (equalsIgnoringCase(keyword, "METADATA")) {
        skipMetadata();
      } else if (equalsIgnoringCase(keyword, "POINT_DATA") ||
                 equalsIgnoringCase(keyword, "CELL_DATA")) {
        scanner_.fail(std::string(keyword) + " comes before " + missingSections());
      } else {
        scanner_.fail("unexpected " + TextScanner::quoted(keyword) +
                      " (expected POINTS, CELLS or CELL_TYPES)");
      }
    }
    return assemble();
  }

 private:
  void readHeader() {
    constexpr std::string_view kSignature = "# vtk DataFile Version";
    const std::string_view first = scanner_.restOfLine();
    if (first.size() < kSignature.size() ||
        !equalsIgnoringCase(first.substr(0, kSignature.size()), kSignature)) {
      scanner_.failAt(1,
                      "not a legacy VTK file (the first line must be '# vtk DataFile Version "
                      "x.x')");
    }
    scanner_.restOfLine();  // the title: free text
    const size_t encodingLine = scanner_.line();
    std::string_view encoding = scanner_.restOfLine();
    while (!encoding.empty() && (encoding.back() == ' ' || encoding.back() == '\t')) {
      encoding.remove_suffix(1);
    }
    while (!encoding.empty() && (encoding.front() == ' ' || encoding.front() == '\t')) {
      encoding.remove_prefix(1);
    }
    if (equalsIgnoringCase(encoding, "BINARY")) {
      binary_ = true;
    } else if (!equalsIgnoringCase(encoding, "ASCII")) {
      scanner_.failAt(encodingLine, "the third line must be ASCII or BINARY");
    }
    scanner_.expectKeyword("DATASET");
    const std::string_view dataset = scanner_.token();
    if (!equalsIgnoringCase(dataset, "UNSTRUCTURED_GRID")) {
      scanner_.fail("DATASET " + TextScanner::printable(dataset) +
                    " is not supported (only UNSTRUCTURED_GRID holds volume cells)");
    }
  }

  std::string missingSections() const {
    std::string missing;
    for (const auto& [have, name] :
         {std::pair{havePoints_, "POINTS"}, std::pair{haveCells_, "CELLS"},
          std::pair{haveCellTypes_, "CELL_TYPES"}}) {
      if (have) continue;
      if (!missing.empty()) missing += ", ";
      missing += name;
    }
    return "its " + missing + " section" + (missing.find(',') != std::string::npos ? "s" : "");
  }

  // ---- POINTS ---------------------------------------------------------------------------------

  void readPoints() {
    if (havePoints_) scanner_.fail("a second POINTS section");
    const uint64_t count = scanner_.count("the number of points");
    const std::string_view type = scanner_.token();
    size_t size = 0;
    if (equalsIgnoringCase(type, "float")) size = 4;
    if (equalsIgnoringCase(type, "double")) size = 8;
    if (size == 0) {
      scanner_.fail("POINTS of type " + TextScanner::quoted(type) +
                    " are not supported (float or double)");
    }
    // ASCII: at least a digit and a separator per coordinate.
    scanner_.checkCount(count, binary_ ? 3 * size : 6, "points");
    points_.resize(static_cast<Eigen::Index>(count), 3);
    double* coordinates = points_.data();
    const uint64_t numValues = 3 * count;
    if (binary_) {
      scanner_.finishLineBeforeBinary();
      const std::string_view block = scanner_.bytes(numValues * size, "the binary POINTS data");
      for (uint64_t i = 0; i < numValues; ++i)
        coordinates[i] = bigEndianReal(&block[i * size], size);
    } else {
      for (uint64_t i = 0; i < numValues; ++i) {
        if (!scanner_.readReal(coordinates[i])) {
          scanner_.failExpected("coordinate " + std::to_string(i % 3) + " of point " +
                                std::to_string(i / 3) + " (of " + std::to_string(count) + ")");
        }
      }
    }
    havePoints_ = true;
  }

  // ---- CELLS ----------------------------------------------------------------------------------

  void readCells() {
    if (haveCells_) scanner_.fail("a second CELLS section");
    const uint64_t first = scanner_.count("the number of cells");
    const uint64_t second = scanner_.count("the size of the CELLS data");
    // VTK 5.1 files follow the CELLS line with OFFSETS; classic ones with the cell data.
    const TextScanner::Mark afterHeader = scanner_.mark();
    const bool offsetsLayout = equalsIgnoringCase(scanner_.peekToken(), "OFFSETS");
    scanner_.restore(afterHeader);
    if (offsetsLayout) {
      readOffsetLayout(first, second);
    } else {
      readClassicLayout(first, second);
    }
    haveCells_ = true;
  }

  // "CELLS numCells size", then per cell "k id_1 ... id_k"; size counts every number.
  void readClassicLayout(uint64_t numCells, uint64_t size) {
    const uint64_t bytesEach = binary_ ? 4 : 2;
    scanner_.checkCount(size, bytesEach, "numbers in CELLS");
    if (numCells > size) {
      scanner_.fail("CELLS declares " + std::to_string(numCells) + " cells in only " +
                    std::to_string(size) + " numbers");
    }
    scanner_.checkCount(numCells, 0, "cells");
    offsets_.assign(1, 0);
    offsets_.reserve(numCells + 1);
    connectivity_.reserve(size - numCells);

    std::string_view block;
    if (binary_) {
      scanner_.finishLineBeforeBinary();
      block = scanner_.bytes(size * 4, "the binary CELLS data");
    }
    uint64_t used = 0;  // numbers of the size consumed so far
    const auto next = [&](auto describe) -> int64_t {
      if (used >= size) {
        scanner_.fail("CELLS declares " + std::to_string(size) + " numbers, but " + describe() +
                      " needs more");
      }
      int64_t value = 0;
      if (binary_) {
        value = bigEndianInteger(&block[used * 4], 4);
      } else if (!scanner_.readInteger(value)) {
        scanner_.failExpected(describe());
      }
      ++used;
      return value;
    };
    for (uint64_t cell = 0; cell < numCells; ++cell) {
      const int64_t numIds = next([&] { return "the node count of cell " + std::to_string(cell); });
      if (numIds < 0 || static_cast<uint64_t>(numIds) > size - used) {
        scanner_.fail("cell " + std::to_string(cell) + ": node count " + std::to_string(numIds) +
                      " does not fit the " + std::to_string(size) + " numbers of CELLS");
      }
      for (int64_t k = 0; k < numIds; ++k) {
        connectivity_.push_back(
            next([&] { return "node " + std::to_string(k) + " of cell " + std::to_string(cell); }));
      }
      offsets_.push_back(connectivity_.size());
    }
    if (used != size) {
      scanner_.fail("CELLS declares " + std::to_string(size) + " numbers, but its " +
                    std::to_string(numCells) + " cells hold " + std::to_string(used));
    }
  }

  // "CELLS numOffsets connectivitySize", "OFFSETS type" + numOffsets values,
  // "CONNECTIVITY type" + connectivitySize values (VTK 5.1).
  void readOffsetLayout(uint64_t numOffsets, uint64_t connectivitySize) {
    const std::vector<int64_t> offsets = readIntegerArray("OFFSETS", numOffsets);
    connectivity_ = readIntegerArray("CONNECTIVITY", connectivitySize);
    offsets_.assign(1, 0);
    if (offsets.empty()) {
      if (connectivitySize != 0) scanner_.fail("CONNECTIVITY without OFFSETS");
      return;
    }
    if (offsets.front() != 0) scanner_.fail("OFFSETS must start at 0");
    offsets_.reserve(offsets.size());
    for (size_t i = 1; i < offsets.size(); ++i) {
      if (offsets[i] < offsets[i - 1] || static_cast<uint64_t>(offsets[i]) > connectivitySize) {
        scanner_.fail("OFFSETS: offset " + std::to_string(i) + " (" + std::to_string(offsets[i]) +
                      ") is smaller than the previous one or beyond the " +
                      std::to_string(connectivitySize) + " CONNECTIVITY values");
      }
      offsets_.push_back(static_cast<uint64_t>(offsets[i]));
    }
    if (offsets_.back() != connectivitySize) {
      scanner_.fail("the last offset (" + std::to_string(offsets_.back()) + ") must equal the " +
                    std::to_string(connectivitySize) + " CONNECTIVITY values");
    }
    scanner_.checkCount(offsets_.size() - 1, 0, "cells");
  }

  std::vector<int64_t> readIntegerArray(std::string_view keyword, uint64_t count) {
    scanner_.expectKeyword(keyword);
    const std::string_view type = scanner_.token();
    const size_t size = integerTypeSize(type);
    if (size == 0) {
      scanner_.fail(std::string(keyword) + " of type " + TextScanner::quoted(type) +
                    " is not supported (vtktypeint64 or vtktypeint32)");
    }
    scanner_.checkCount(count, binary_ ? size : 2, "values in " + std::string(keyword),
                        std::numeric_limits<uint64_t>::max());
    std::vector<int64_t> values(count);
    if (binary_) {
      scanner_.finishLineBeforeBinary();
      const std::string_view block =
          scanner_.bytes(count * size, "the binary " + std::string(keyword) + " data");
      for (uint64_t i = 0; i < count; ++i) values[i] = bigEndianInteger(&block[i * size], size);
    } else {
      for (uint64_t i = 0; i < count; ++i) {
        if (!scanner_.readInteger(values[i])) {
          scanner_.failExpected("value " + std::to_string(i) + " of " + std::to_string(count) +
                                " in " + std::string(keyword));
        }
      }
    }
    return values;
  }

  // ---- CELL_TYPES -----------------------------------------------------------------------------

  void readCellTypes() {
    if (haveCellTypes_) scanner_.fail("a second CELL_TYPES section");
    const uint64_t count = scanner_.count("the number of cell types");
    scanner_.checkCount(count, binary_ ? 4 : 2, "cell types");
    cellTypes_.resize(count);
    if (binary_) {
      scanner_.finishLineBeforeBinary();
      const std::string_view block = scanner_.bytes(count * 4, "the binary CELL_TYPES data");
      for (uint64_t i = 0; i < count; ++i) cellTypes_[i] = bigEndianInteger(&block[i * 4], 4);
    } else {
      for (uint64_t i = 0; i < count; ++i) {
        if (!scanner_.readInteger(cellTypes_[i])) {
          scanner_.failExpected("the type of cell " + std::to_string(i) + " (of " +
                                std::to_string(count) + ")");
        }
      }
    }
    haveCellTypes_ = true;
  }

  // ---- Sections that are skipped --------------------------------------------------------------

  // "FIELD name numArrays", then per array "name numComponents numTuples type" and its values.
  void skipFieldData() {
    scanner_.token();  // the field's name
    const uint64_t numArrays = scanner_.count("the number of FIELD arrays");
    scanner_.checkCount(numArrays, 8, "FIELD arrays");
    for (uint64_t a = 0; a < numArrays; ++a) {
      const std::string_view arrayName = scanner_.token();
      if (equalsIgnoringCase(arrayName, "NULL_ARRAY")) continue;
      const std::string name = TextScanner::quoted(arrayName);
      const uint64_t components = scanner_.count("the number of components of FIELD array " + name);
      const uint64_t tuples = scanner_.count("the number of tuples of FIELD array " + name);
      const std::string_view type = scanner_.token();
      const size_t size = dataTypeSize(type);
      if (size == 0) {
        scanner_.fail("FIELD array " + name + " has type " + TextScanner::quoted(type) +
                      ", which this reader cannot skip");
      }
      if (tuples != 0 && components > std::numeric_limits<uint64_t>::max() / tuples) {
        scanner_.fail("FIELD array " + name + " is too large");
      }
      const uint64_t values = components * tuples;
      scanner_.checkCount(values, binary_ ? size : 2, "values in FIELD array " + name,
                          std::numeric_limits<uint64_t>::max());
      if (binary_) {
        scanner_.finishLineBeforeBinary();
        scanner_.bytes(values * size, "the binary data of FIELD array " + name);
      } else {
        for (uint64_t i = 0; i < values; ++i) {
          if (scanner_.token().empty()) scanner_.fail("the file ends inside FIELD array " + name);
        }
      }
      if (equalsIgnoringCase(scanner_.peekToken(), "METADATA")) {
        scanner_.token();
        skipMetadata();
      }
    }
  }

  // VTK 9 writes "METADATA" followed by information lines up to an empty line.
  void skipMetadata() {
    scanner_.restOfLine();
    while (scanner_.bytesLeft() > 0) {
      const std::string_view line = scanner_.restOfLine();
      if (line.find_first_not_of(" \t") == std::string_view::npos) return;
    }
  }

  // ---- Building the mesh ----------------------------------------------------------------------

  [[noreturn]] void failCell(uint64_t cell, const std::string& problem) const {
    throw FileError(source_ + ": cell " + std::to_string(cell) + ": " + problem);
  }

  VolumeMesh assemble() {
    const uint64_t numCells = offsets_.size() - 1;
    if (cellTypes_.size() != numCells) {
      throw FileError(source_ + ": CELL_TYPES lists " + std::to_string(cellTypes_.size()) +
                      " types for " + std::to_string(numCells) + " cells");
    }
    VolumeMesh mesh;
    mesh.positions = std::move(points_);
    const uint64_t numNodes = static_cast<uint64_t>(mesh.positions.rows());
    std::vector<uint64_t> fileCellOfCell;

    for (uint64_t cell = 0; cell < numCells; ++cell) {
      const int64_t type = cellTypes_[cell];
      if (isLowerDimensionalCellType(type)) continue;
      const size_t expected = type == kTetra                            ? 4
                              : (type == kVoxel || type == kHexahedron) ? 8
                              : type == kWedge                          ? 6
                              : type == kPyramid                        ? 5
                                                                        : 0;
      if (expected == 0) {
        const char* name = unsupportedCellTypeName(type);
        failCell(cell, "VTK cell type " + std::to_string(type) +
                           (name ? " (" + std::string(name) + ")" : std::string(" (unknown)")) +
                           " is not supported; only tetrahedra (10), voxels (11), hexahedra (12), "
                           "wedges (13) and pyramids (14) are read");
      }
      const uint64_t begin = offsets_[cell];
      const uint64_t size = offsets_[cell + 1] - begin;
      if (size != expected) {
        failCell(cell, "a cell of type " + std::to_string(type) + " needs " +
                           std::to_string(expected) + " nodes, not " + std::to_string(size));
      }
      std::array<uint32_t, 8> v{};
      for (size_t k = 0; k < expected; ++k) {
        const int64_t id = connectivity_[begin + k];
        if (id < 0 || static_cast<uint64_t>(id) >= numNodes) {
          failCell(cell, "node id " + std::to_string(id) + " out of range (the mesh has " +
                             std::to_string(numNodes) + " nodes)");
        }
        v[k] = static_cast<uint32_t>(id);
      }
      if (type == kTetra) {
        mesh.addTetrahedron({v[0], v[1], v[2], v[3]});
      } else if (type == kHexahedron) {
        mesh.addHexahedron(v);
      } else if (type == kVoxel) {  // an axis-aligned hexahedron with its nodes in x-y-z order
        mesh.addHexahedron({v[0], v[1], v[3], v[2], v[4], v[5], v[7], v[6]});
      } else if (type == kWedge) {
        // VTK's triangle (0,1,2) faces away from (3,4,5); splitWedge wants Gmsh's order, where it
        // faces towards it.
        splitWedge(mesh, {v[0], v[2], v[1], v[3], v[5], v[4]});
      } else {
        splitPyramid(mesh, {v[0], v[1], v[2], v[3], v[4]});
      }
      fileCellOfCell.resize(mesh.numCells(), cell);
    }
    throwOnVolumeMeshProblem(mesh, fileCellOfCell, "VTK cell", source_, shapes_);
    return mesh;
  }

  TextScanner scanner_;
  std::string source_;
  CellShapeCheck shapes_ = CellShapeCheck::Required;
  bool binary_ = false;
  bool havePoints_ = false, haveCells_ = false, haveCellTypes_ = false;
  Points points_;
  std::vector<uint64_t> offsets_{0};  ///< #cells+1 into connectivity_
  std::vector<int64_t> connectivity_;
  std::vector<int64_t> cellTypes_;
};

}  // namespace

VolumeMesh parseVtkVolumeMesh(std::string_view bytes, std::string_view sourceName,
                              CellShapeCheck shapes) {
  return VtkReader(bytes, sourceName).read(shapes);
}

VolumeMesh readVtkVolumeMesh(const std::filesystem::path& path, CellShapeCheck shapes) {
  const std::string bytes = readInputFile(path, kVolumeMeshInput);
  return parseVtkVolumeMesh(bytes, path.string(), shapes);
}

std::string volumeMeshToVtk(const VolumeMesh& mesh, bool binary) {
  return volumeMeshToVtk(mesh, binary, mesh.positions, "sculpt volume mesh");
}

std::string volumeMeshToVtk(const VolumeMesh& mesh, bool binary, const Points& positions,
                            std::string_view title) {
  if (positions.rows() != mesh.positions.rows())
    throw std::invalid_argument("volumeMeshToVtk: " + std::to_string(positions.rows()) +
                                " positions for " + std::to_string(mesh.numNodes()) + " nodes");
  const uint32_t numNodes = mesh.numNodes();
  const uint32_t numCells = mesh.numCells();
  uint64_t cellsSize = 0;
  for (uint32_t c = 0; c < numCells; ++c) {
    const uint32_t size = mesh.cells.rowSize(c);
    if (size != 4 && size != 8) {
      throw std::invalid_argument("volumeMeshToVtk: cell " + std::to_string(c) + " has " +
                                  std::to_string(size) + " nodes (expected 4 or 8)");
    }
    cellsSize += 1 + size;
  }
  if (binary && numNodes > static_cast<uint32_t>(std::numeric_limits<int32_t>::max())) {
    throw std::invalid_argument("volumeMeshToVtk: too many nodes for binary VTK");
  }

  std::string out = "# vtk DataFile Version 4.2\n";
  out += title;
  out += '\n';
  out += binary ? "BINARY\n" : "ASCII\n";
  out += "DATASET UNSTRUCTURED_GRID\nPOINTS ";
  appendNumber(out, numNodes);
  out += " double\n";
  for (uint32_t n = 0; n < numNodes; ++n) {
    for (Eigen::Index k = 0; k < 3; ++k) {
      const double x = positions(n, k);
      if (binary) {
        appendBigEndian(out, std::bit_cast<uint64_t>(x), 8);
      } else {
        if (k > 0) out += ' ';
        appendNumber(out, x);
      }
    }
    if (!binary) out += '\n';
  }
  if (binary) out += '\n';

  // Every integer goes through here: a 4-byte big-endian int in binary, a word in ASCII.
  const auto appendInteger = [&](uint32_t value, char separator) {
    if (binary) {
      appendBigEndian(out, value, 4);
    } else {
      appendNumber(out, value);
      out += separator;
    }
  };
  out += "CELLS ";
  appendNumber(out, numCells);
  out += ' ';
  appendNumber(out, cellsSize);
  out += '\n';
  for (uint32_t c = 0; c < numCells; ++c) {
    const std::span<const uint32_t> nodes = mesh.cells.row(c);
    appendInteger(static_cast<uint32_t>(nodes.size()), ' ');
    for (size_t k = 0; k < nodes.size(); ++k)
      appendInteger(nodes[k], k + 1 < nodes.size() ? ' ' : '\n');
  }
  if (binary) out += '\n';
  out += "CELL_TYPES ";
  appendNumber(out, numCells);
  out += '\n';
  for (uint32_t c = 0; c < numCells; ++c) {
    appendInteger(static_cast<uint32_t>(mesh.isTetrahedron(c) ? kTetra : kHexahedron), '\n');
  }
  if (binary) out += '\n';
  return out;
}

void writeVtkVolumeMesh(const std::filesystem::path& path, const VolumeMesh& mesh, bool binary) {
  writeFileAtomically(path, volumeMeshToVtk(mesh, binary));
}

}  // namespace sculpt
