#include "anim/vtk_sequence_writer.h"

#include <bit>
#include <cctype>
#include <charconv>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "anim/frame_pattern.h"
#include "io/atomic_file.h"
#include "io/file_error.h"
#include "io/number_text.h"
#include "io/vtk_binary.h"

#include "anim/written_files.h"
#include "io/vtk_volume_mesh.h"
#include "util/file_extension.h"

namespace sculpt {
namespace {

constexpr uint32_t kVtkTetra = 10;
constexpr uint32_t kVtkHexahedron = 12;

enum class GridFormat { kLegacyBinary, kXml };

struct Frame {
  uint32_t index = 0;
  uint32_t count = 0;
  double time = 0.0;
};

// A frame's solid, checked against its rest mesh.
void checkFrame(const VolumeMesh& rest, const SolidFrameData& frame, uint32_t f,
                const std::filesystem::path& path) {
  const auto problem = [&](const std::string& what) {
    throw FileError(path.string() + ": frame " + std::to_string(f + 1) + ": " + what);
  };
  const auto nodes = static_cast<Eigen::Index>(rest.numNodes());
  if (frame.nodes.rows() != nodes || frame.displacement.rows() != nodes) {
    problem(std::to_string(frame.nodes.rows()) + " nodes and " +
            std::to_string(frame.displacement.rows()) + " displacements for a solid of " +
            std::to_string(nodes) + " nodes");
  }
  const size_t cells = rest.numCells();
  if (frame.fields.youngs.size() != cells || frame.fields.density.size() != cells ||
      frame.fields.damping.size() != cells) {
    problem("the cell fields do not have one value per cell (" + std::to_string(cells) + ")");
  }
  for (uint32_t c = 0; c < rest.numCells(); ++c) {
    if (rest.cells.rowSize(c) != 4 && rest.cells.rowSize(c) != 8) {
      problem("cell " + std::to_string(c) + " has " + std::to_string(rest.cells.rowSize(c)) +
              " nodes (only tetrahedra and hexahedra are written)");
    }
  }
}

uint32_t cellType(const VolumeMesh& mesh, uint32_t c) {
  return mesh.cells.rowSize(c) == 4 ? kVtkTetra : kVtkHexahedron;
}

void appendFloat(std::string& out, float value) {
  char buffer[32];
  const auto result =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 9);
  out.append(buffer, result.ptr);
}

std::string frameTitle(const Frame& frame) {
  std::string out = "frame ";
  appendNumber(out, frame.index + 1);
  out += " of ";
  appendNumber(out, frame.count);
  out += ", t = ";
  appendNumber(out, frame.time);
  out += " s";
  return out;
}

void appendBinaryPoints(std::string& out, const Points& points) {
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    for (Eigen::Index k = 0; k < 3; ++k)
      appendBigEndian(out, std::bit_cast<uint64_t>(points(i, k)), 8);
  out += '\n';
}

void appendBinaryScalars(std::string& out, std::string_view name,
                         const std::vector<float>& values) {
  out += "SCALARS ";
  out += name;
  out += " float 1\nLOOKUP_TABLE default\n";
  for (const float value : values) appendBigEndian(out, std::bit_cast<uint32_t>(value), 4);
  out += '\n';
}

// Legacy VTK 4.2, binary: the grid as io writes volume meshes, then the point and cell data.
std::string legacyGrid(const VolumeMesh& rest, const SolidFrameData& solid, const Frame& frame) {
  const uint32_t nodes = rest.numNodes();
  const uint32_t cells = rest.numCells();
  std::string out = volumeMeshToVtk(rest, true, solid.nodes, frameTitle(frame));
  out.reserve(out.size() + 24 * size_t{nodes} + 12 * size_t{cells} + 256);
  out += "POINT_DATA ";
  appendNumber(out, nodes);
  out += "\nVECTORS displacement double\n";
  appendBinaryPoints(out, solid.displacement);
  out += "CELL_DATA ";
  appendNumber(out, cells);
  out += '\n';
  appendBinaryScalars(out, "youngs_modulus", solid.fields.youngs);
  appendBinaryScalars(out, "density", solid.fields.density);
  appendBinaryScalars(out, "damping", solid.fields.damping);
  return out;
}

void appendXmlPoints(std::string& out, std::string_view name, const Points& points) {
  out += "        <DataArray type=\"Float64\"";
  if (!name.empty()) {
    out += " Name=\"";
    out += name;
    out += '"';
  }
  out += " NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    out += "         ";
    for (Eigen::Index k = 0; k < 3; ++k) {
      out += ' ';
      appendNumber(out, points(i, k));
    }
    out += '\n';
  }
  out += "        </DataArray>\n";
}

void appendXmlScalars(std::string& out, std::string_view name, const std::vector<float>& values) {
  out += "        <DataArray type=\"Float32\" Name=\"";
  out += name;
  out += "\" format=\"ascii\">\n         ";
  for (const float value : values) {
    out += ' ';
    appendFloat(out, value);
  }
  out += "\n        </DataArray>\n";
}

// VTK XML UnstructuredGrid, ASCII: 17 significant digits for doubles, 9 for floats.
std::string xmlGrid(const VolumeMesh& rest, const SolidFrameData& solid, const Frame& frame) {
  const uint32_t cells = rest.numCells();
  std::string out;
  out += "<?xml version=\"1.0\"?>\n<!-- ";
  out += frameTitle(frame);
  out += " -->\n";
  out += "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
  out += "  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"";
  appendNumber(out, rest.numNodes());
  out += "\" NumberOfCells=\"";
  appendNumber(out, cells);
  out += "\">\n      <PointData Vectors=\"displacement\">\n";
  appendXmlPoints(out, "displacement", solid.displacement);
  out += "      </PointData>\n      <CellData Scalars=\"youngs_modulus\">\n";
  appendXmlScalars(out, "youngs_modulus", solid.fields.youngs);
  appendXmlScalars(out, "density", solid.fields.density);
  appendXmlScalars(out, "damping", solid.fields.damping);
  out += "      </CellData>\n      <Points>\n";
  appendXmlPoints(out, "", solid.nodes);
  out += "      </Points>\n      <Cells>\n";
  out += "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (uint32_t c = 0; c < cells; ++c) {
    out += "         ";
    for (const uint32_t node : rest.cells.row(c)) {
      out += ' ';
      appendNumber(out, node);
    }
    out += '\n';
  }
  out += "        </DataArray>\n";
  out += "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n         ";
  for (uint32_t c = 0; c < cells; ++c) {
    out += ' ';
    appendNumber(out, rest.cells.offsets[c + 1]);
  }
  out += "\n        </DataArray>\n";
  out += "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n         ";
  for (uint32_t c = 0; c < cells; ++c) {
    out += ' ';
    appendNumber(out, cellType(rest, c));
  }
  out += "\n        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n";
  out += "</VTKFile>\n";
  return out;
}

void appendXmlAttribute(std::string& out, std::string_view value) {
  for (const char c : value) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
}

struct ListedFrame {
  std::string name;  ///< relative to the collection's directory
  double time = 0.0;
};

std::string pvdCollection(const std::vector<ListedFrame>& frames) {
  std::string out = "<?xml version=\"1.0\"?>\n";
  out += "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
  out += "  <Collection>\n";
  for (const ListedFrame& frame : frames) {
    out += "    <DataSet timestep=\"";
    appendNumber(out, frame.time);
    out += "\" group=\"\" part=\"0\" file=\"";
    appendXmlAttribute(out, frame.name);
    out += "\"/>\n";
  }
  out += "  </Collection>\n</VTKFile>\n";
  return out;
}

std::string fileSeries(const std::vector<ListedFrame>& frames) {
  nlohmann::json files = nlohmann::json::array();
  for (const ListedFrame& frame : frames)
    files.push_back({{"name", frame.name}, {"time", frame.time}});
  const nlohmann::json series = {{"file-series-version", "1.0"}, {"files", std::move(files)}};
  return series.dump(2) + "\n";
}

GridFormat formatOf(const std::filesystem::path& pattern) {
  const std::string extension = lowerExtension(pattern);
  if (extension == ".vtk") return GridFormat::kLegacyBinary;
  if (extension == ".vtu") return GridFormat::kXml;
  throw std::invalid_argument("'" + pattern.string() +
                              "' is not a VTK sequence pattern: end it in .vtk (legacy) or .vtu "
                              "(XML), e.g. name_####.vtu");
}

}  // namespace

ExportResult writeVtkSequence(const AnimatedSurface& animation,
                              const std::filesystem::path& pattern, ProgressReporter* progress) {
  const FramePattern names = framePatternOrThrow(pattern);
  const GridFormat format = formatOf(pattern);
  const uint32_t frames = animation.frameCount();
  ExportResult result;
  WrittenFiles written;
  std::vector<ListedFrame> listed;
  SolidFrameData solid;
  for (uint32_t f = 0; f < frames; ++f) {
    const std::filesystem::path path = framePath(names, f + 1);
    const VolumeMesh& rest = animation.restSolid(animation.segmentOf(f));
    animation.evaluateSolid(f, solid);
    checkFrame(rest, solid, f, path);
    const Frame frame{f, frames, animation.frameTime(f)};
    const std::string contents = format == GridFormat::kLegacyBinary
                                     ? legacyGrid(rest, solid, frame)
                                     : xmlGrid(rest, solid, frame);
    writeFileAtomically(path, contents);
    written.add(path);
    result.bytes += contents.size();
    listed.push_back({path.filename().string(), frame.time});
    if (progress && !progress->report(double(f + 1) / frames, "VTK sequence")) {
      ExportResult cancelled;
      cancelled.cancelled = true;
      return cancelled;  // `written` removes the frames
    }
  }

  const auto writeCollection = [&](const std::filesystem::path& path, const std::string& text) {
    writeFileAtomically(path, text);
    written.add(path);
    result.bytes += text.size();
  };
  if (format == GridFormat::kLegacyBinary) {
    writeCollection(collectionPath(names, ".vtk.series"), fileSeries(listed));
  }
  writeCollection(collectionPath(names, ".pvd"), pvdCollection(listed));
  result.files = written.keep();
  result.frames = frames;
  return result;
}

}  // namespace sculpt
