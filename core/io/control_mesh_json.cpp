#include "io/control_mesh_json.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

#include "io/atomic_file.h"
#include "io/input_file.h"
#include "io/json_nesting.h"
#include "io/number_text.h"
#include "mesh/standard_cell.h"

namespace sculpt {
namespace {

using nlohmann::json;

constexpr int kFormatVersion = 1;
constexpr const char* kFormatName = "sculpt-control-mesh";
// Hostile-input guards: no real cell comes near these, and they keep memory and stack bounded.
constexpr size_t kMaxFacesPerCell = 10000;
constexpr size_t kMaxVerticesPerFace = 10000;
constexpr int kMaxNesting = 64;
constexpr size_t kMaxQuotedLength = 40;

// Makes user-controlled text safe for a one-line message: printable ASCII only, bounded length.
std::string printable(std::string_view text, size_t maxLength) {
  std::string out;
  for (char ch : text.substr(0, maxLength)) {
    const auto u = static_cast<unsigned char>(ch);
    out.push_back(u >= 0x20 && u < 0x7f ? ch : '?');
  }
  if (text.size() > maxLength) out += "...";
  return out;
}

// Short description of a JSON value for messages: numbers and short strings verbatim, containers
// by kind.
std::string describe(const json& value) {
  switch (value.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::boolean:
      return value.get<bool>() ? "true" : "false";
    case json::value_t::string:
      return "\"" + printable(value.get_ref<const std::string&>(), kMaxQuotedLength) + "\"";
    case json::value_t::array:
      return "an array";
    case json::value_t::object:
      return "an object";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float:
      return value.dump();
    default:
      return "an unsupported value";
  }
}

// The detail of a nlohmann parse error ("unexpected end of input"), without its decoration.
std::string parseErrorDetail(const json::exception& error) {
  std::string_view what = error.what();
  if (const size_t dash = what.find(" - "); dash != std::string_view::npos) {
    what.remove_prefix(dash + 3);
  } else if (const size_t colon = what.rfind(": "); colon != std::string_view::npos) {
    what.remove_prefix(colon + 2);
  } else if (const size_t bracket = what.find("] "); bracket != std::string_view::npos) {
    what.remove_prefix(bracket + 2);
  }
  if (const size_t semi = what.find(';'); semi != std::string_view::npos) {
    what = what.substr(0, semi);
  }
  return printable(what, 100);
}

class ControlMeshParser {
 public:
  explicit ControlMeshParser(std::string_view sourceName) : source_(sourceName) {}

  CellComplex parse(std::string_view text) {
    const json root = parseJson(text);
    if (!root.is_object()) fail("", "the top level must be a JSON object, got " + describe(root));
    checkHeader(root);
    CellComplex mesh;
    parseVertices(require(root, "vertices"), mesh);
    parseCells(require(root, "cells"), mesh);
    if (const auto it = root.find("creases"); it != root.end()) parseCreases(*it, mesh);
    if (const auto it = root.find("corners"); it != root.end()) parseCorners(*it, mesh);
    return mesh;
  }

 private:
  [[noreturn]] void fail(const std::string& element, const std::string& problem) const {
    std::string message(source_);
    message += ": ";
    if (!element.empty()) message += element + ": ";
    throw FileError(message + problem);
  }

  json parseJson(std::string_view text) const {
    if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
      fail("", "not valid JSON (the file is empty)");
    }
    if (const size_t at = excessiveJsonNesting(text, kMaxNesting); at != std::string_view::npos) {
      fail("", "not valid JSON (nested deeper than " + std::to_string(kMaxNesting) +
                   " levels at byte " + std::to_string(at) + ")");
    }
    try {
      return json::parse(text.begin(), text.end());
    } catch (const json::parse_error& error) {
      fail("", "not valid JSON (syntax error at byte " + std::to_string(error.byte) + ": " +
                   parseErrorDetail(error) + ")");
    } catch (const json::exception& error) {
      fail("", "not valid JSON (" + parseErrorDetail(error) + ")");
    }
  }

  const json& require(const json& root, const char* key) const {
    const auto it = root.find(key);
    if (it == root.end()) fail("", std::string("\"") + key + "\" is missing");
    if (!it->is_array()) {
      fail("", std::string("\"") + key + "\" must be an array, got " + describe(*it));
    }
    return *it;
  }

  void checkHeader(const json& root) const {
    const auto format = root.find("format");
    if (format == root.end()) {
      fail("", std::string("\"format\" must be \"") + kFormatName + "\" (missing)");
    }
    if (!format->is_string() || format->get_ref<const std::string&>() != kFormatName) {
      fail("", std::string("\"format\" must be \"") + kFormatName + "\", got " + describe(*format));
    }
    const auto version = root.find("version");
    if (version == root.end()) fail("", "\"version\" is missing");
    if (!version->is_number_integer() || version->get<int64_t>() < 1) {
      fail("", "\"version\" must be a positive integer, got " + describe(*version));
    }
    if (version->is_number_unsigned() && version->get<uint64_t>() > uint64_t{kFormatVersion}) {
      fail("", "version " + version->dump() + " is newer than this program understands (" +
                   std::to_string(kFormatVersion) + ")");
    }
  }

  // A vertex id: a non-negative integer (3.0 is accepted, 2.5 is not). Range against the
  // vertex count is validate()'s job, where it can name the cell.
  uint32_t parseIndex(const json& value, const std::string& element) const {
    constexpr uint64_t kMax = std::numeric_limits<uint32_t>::max() - 1;
    if (value.is_number_unsigned()) {
      const uint64_t u = value.get<uint64_t>();
      if (u > kMax) fail(element, "vertex index " + value.dump() + " is too large");
      return static_cast<uint32_t>(u);
    }
    if (value.is_number_integer()) fail(element, "vertex index " + value.dump() + " is negative");
    if (value.is_number_float()) {
      const double d = value.get<double>();
      if (d >= 0.0 && d <= static_cast<double>(kMax) && std::floor(d) == d) {
        return static_cast<uint32_t>(d);
      }
      fail(element, "vertex index " + value.dump() + " is not a non-negative integer");
    }
    fail(element, "vertex index must be a non-negative integer, got " + describe(value));
  }

  void parseVertices(const json& vertices, CellComplex& mesh) const {
    if (vertices.size() >= std::numeric_limits<uint32_t>::max()) fail("", "too many vertices");
    mesh.positions.resize(static_cast<Eigen::Index>(vertices.size()), 3);
    for (size_t i = 0; i < vertices.size(); ++i) {
      const json& v = vertices[i];
      const std::string element = "vertex " + std::to_string(i);
      if (!v.is_array()) fail(element, "must be [x, y, z], got " + describe(v));
      if (v.size() != 3) fail(element, "must have 3 coordinates, got " + std::to_string(v.size()));
      for (size_t k = 0; k < 3; ++k) {
        if (!v[k].is_number()) {
          fail(element,
               "coordinate " + std::to_string(k) + " must be a number, got " + describe(v[k]));
        }
        mesh.positions(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) =
            v[k].get<double>();
      }
    }
  }

  void parseCells(const json& cells, CellComplex& mesh) const {
    std::vector<uint32_t> loop;
    for (size_t c = 0; c < cells.size(); ++c) {
      const json& cell = cells[c];
      const std::string element = "cell " + std::to_string(c);
      if (cell.is_object()) {
        parseTypedCell(cell, element, mesh);
        continue;
      }
      if (!cell.is_array()) {
        fail(element, "must be a list of faces or {\"type\": ..., \"vertices\": [...]}, got " +
                          describe(cell));
      }
      if (cell.empty()) fail(element, "has no faces");
      if (cell.size() > kMaxFacesPerCell) {
        fail(element, "has " + std::to_string(cell.size()) + " faces (at most " +
                          std::to_string(kMaxFacesPerCell) + " are accepted)");
      }
      for (size_t f = 0; f < cell.size(); ++f) {
        const json& face = cell[f];
        const std::string faceElement = element + ", face " + std::to_string(f);
        if (!face.is_array()) {
          fail(faceElement, "must be a list of vertex indices, got " + describe(face));
        }
        if (face.size() < 3) {
          fail(faceElement, "a face needs at least 3 vertices, got " + std::to_string(face.size()));
        }
        if (face.size() > kMaxVerticesPerFace) {
          fail(faceElement, "has " + std::to_string(face.size()) + " vertices (at most " +
                                std::to_string(kMaxVerticesPerFace) + " are accepted)");
        }
        loop.clear();
        for (const json& index : face) loop.push_back(parseIndex(index, faceElement));
        mesh.addLoop(loop);
      }
      mesh.finishCell();
    }
  }

  void parseTypedCell(const json& cell, const std::string& element, CellComplex& mesh) const {
    const auto type = cell.find("type");
    if (type == cell.end()) fail(element, "\"type\" is missing");
    if (!type->is_string()) fail(element, "\"type\" must be a string, got " + describe(*type));
    const std::string& name = type->get_ref<const std::string&>();
    const auto shape = parseStandardCell(name);
    if (!shape) {
      fail(element,
           "unknown cell type " + describe(*type) + " (expected hex, tet, prism or pyramid)");
    }
    const auto vertices = cell.find("vertices");
    if (vertices == cell.end()) fail(element, "\"vertices\" is missing");
    if (!vertices->is_array()) {
      fail(element, "\"vertices\" must be an array, got " + describe(*vertices));
    }
    const auto expected = static_cast<size_t>(standardCellVertexCount(*shape));
    if (vertices->size() != expected) {
      fail(element, "a " + printable(name, kMaxQuotedLength) + " needs " +
                        std::to_string(expected) + " vertices, got " +
                        std::to_string(vertices->size()));
    }
    std::vector<uint32_t> ids;
    for (const json& index : *vertices) ids.push_back(parseIndex(index, element));
    for (const auto& loop : standardCellFaces(*shape, ids)) mesh.addLoop(loop);
    mesh.finishCell();
  }

  void parseCreases(const json& creases, CellComplex& mesh) const {
    if (!creases.is_array()) fail("", "\"creases\" must be an array, got " + describe(creases));
    for (size_t i = 0; i < creases.size(); ++i) {
      const json& pair = creases[i];
      const std::string element = "crease " + std::to_string(i);
      if (!pair.is_array() || pair.size() != 2) {
        fail(element, "must be a pair of vertex indices [a, b], got " + describe(pair));
      }
      mesh.creases.push_back({parseIndex(pair[0], element), parseIndex(pair[1], element)});
    }
  }

  void parseCorners(const json& corners, CellComplex& mesh) const {
    if (!corners.is_array()) fail("", "\"corners\" must be an array, got " + describe(corners));
    for (size_t i = 0; i < corners.size(); ++i) {
      mesh.corners.push_back(parseIndex(corners[i], "corner " + std::to_string(i)));
    }
  }

  std::string_view source_;
};

void appendIndexList(std::string& out, std::span<const uint32_t> ids) {
  out += '[';
  for (size_t i = 0; i < ids.size(); ++i) {
    if (i > 0) out += ", ";
    appendNumber(out, ids[i]);
  }
  out += ']';
}

}  // namespace

CellComplex parseControlMeshJson(std::string_view text, std::string_view sourceName) {
  return ControlMeshParser(sourceName).parse(text);
}

CellComplex loadControlMeshJson(const std::filesystem::path& path) {
  return parseControlMeshJson(readInputFile(path, kControlMeshInput), path.string());
}

std::string controlMeshToJson(const CellComplex& mesh) {
  std::string out;
  out += "{\n  \"format\": \"";
  out += kFormatName;
  out += "\",\n  \"version\": " + std::to_string(kFormatVersion) + ",\n  \"vertices\": [";
  for (uint32_t v = 0; v < mesh.numVertices(); ++v) {
    out += v > 0 ? ",\n    [" : "\n    [";
    for (Eigen::Index k = 0; k < 3; ++k) {
      const double x = mesh.positions(v, k);
      // JSON has no inf or nan; writing them would give a file that cannot be read back.
      if (!std::isfinite(x)) {
        throw std::domain_error("controlMeshToJson: vertex " + std::to_string(v) +
                                " has a non-finite coordinate");
      }
      if (k > 0) out += ", ";
      appendNumber(out, x);
    }
    out += ']';
  }
  out += mesh.numVertices() > 0 ? "\n  ],\n  \"cells\": [" : "],\n  \"cells\": [";
  for (uint32_t c = 0; c < mesh.numCells(); ++c) {
    out += c > 0 ? ",\n    [" : "\n    [";
    for (uint32_t j = 0; j < mesh.numFacesOfCell(c); ++j) {
      if (j > 0) out += ", ";
      appendIndexList(out, mesh.cellFace(c, j));
    }
    out += ']';
  }
  out += mesh.numCells() > 0 ? "\n  ]" : "]";
  if (!mesh.creases.empty()) {
    out += ",\n  \"creases\": [";
    for (size_t i = 0; i < mesh.creases.size(); ++i) {
      if (i > 0) out += ", ";
      appendIndexList(out, mesh.creases[i]);
    }
    out += ']';
  }
  if (!mesh.corners.empty()) {
    out += ",\n  \"corners\": ";
    appendIndexList(out, mesh.corners);
  }
  out += "\n}\n";
  return out;
}

void saveControlMeshJson(const CellComplex& mesh, const std::filesystem::path& path) {
  writeFileAtomically(path, controlMeshToJson(mesh));
}

}  // namespace sculpt
