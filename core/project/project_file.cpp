#include "project/project_file.h"

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <variant>

#include "io/atomic_file.h"
#include "io/input_file.h"
#include "io/json_nesting.h"
#include "project/project_validation.h"
#include "util/crc32.h"

namespace sculpt {
namespace {

using nlohmann::json;

constexpr char kMagic[7] = {'S', 'C', 'U', 'L', 'P', 'T', '\0'};
constexpr size_t kHeaderSize = sizeof kMagic + 3 * sizeof(uint32_t);
constexpr const char* kFormatName = "sculpt-project";
constexpr int kMaxNesting = 32;

// Blobs of format version 1, in file order. Each is one little-endian array.
enum class BlobType { F64, U32, Bytes };
struct BlobSpec {
  const char* name;
  BlobType type;
};
constexpr std::array<BlobSpec, 10> kBlobs{{
    {"control.positions", BlobType::F64},      // #V x 3
    {"control.cellFaceBegin", BlobType::U32},  // #C + 1
    {"control.loopBegin", BlobType::U32},      // #loops + 1
    {"control.loopVertices", BlobType::U32},
    {"control.creases", BlobType::U32},  // #creases x 2
    {"control.corners", BlobType::U32},
    {"materials.positions", BlobType::F64},  // #S x 3
    {"materials.values", BlobType::F64},     // #S x 4: E (Pa), nu, density (kg/m^3), damping
    {"pins", BlobType::U32},
    {"surface.obj", BlobType::Bytes},  // OBJ text when embedded, else empty
}};

size_t elementSize(BlobType type) {
  switch (type) {
    case BlobType::F64:
      return 8;
    case BlobType::U32:
      return 4;
    case BlobType::Bytes:
      return 1;
  }
  return 1;
}

const char* typeName(BlobType type) {
  switch (type) {
    case BlobType::F64:
      return "f64";
    case BlobType::U32:
      return "u32";
    case BlobType::Bytes:
      return "bytes";
  }
  return "?";
}

// ---------------------------------------------------------------------------------------------
// Little-endian encoding (explicit shifts: the file is the same on any host).

void putU32(std::string& out, uint32_t value) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xffu));
}

void putF64(std::string& out, double value) {
  uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<char>((bits >> (8 * i)) & 0xffu));
}

uint32_t getU32(const char* p) {
  uint32_t value = 0;
  for (int i = 0; i < 4; ++i) value |= uint32_t{static_cast<unsigned char>(p[i])} << (8 * i);
  return value;
}

double getF64(const char* p) {
  uint64_t bits = 0;
  for (int i = 0; i < 8; ++i) bits |= uint64_t{static_cast<unsigned char>(p[i])} << (8 * i);
  double value = 0.0;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

// ---------------------------------------------------------------------------------------------
// Writing.

json vectorJson(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

class BlobWriter {
 public:
  void addF64(const double* values, size_t count) {
    std::string& out = begin(BlobType::F64);
    for (size_t i = 0; i < count; ++i) putF64(out, values[i]);
    finish(count);
  }
  void addU32(const uint32_t* values, size_t count) {
    std::string& out = begin(BlobType::U32);
    for (size_t i = 0; i < count; ++i) putU32(out, values[i]);
    finish(count);
  }
  void addBytes(std::string_view bytes) {
    begin(BlobType::Bytes).append(bytes);
    finish(bytes.size());
  }
  const json& manifest() const { return manifest_; }
  const std::string& data() const { return data_; }

 private:
  std::string& begin(BlobType type) {
    if (kBlobs[next_].type != type) throw std::logic_error("project blob written out of order");
    start_ = data_.size();
    return data_;
  }
  void finish(size_t count) {
    const std::string_view bytes(data_.data() + start_, data_.size() - start_);
    manifest_.push_back({{"name", kBlobs[next_].name},
                         {"type", typeName(kBlobs[next_].type)},
                         {"count", count},
                         {"crc32", crc32(bytes)}});
    ++next_;
  }
  json manifest_ = json::array();
  std::string data_;
  size_t start_ = 0;
  size_t next_ = 0;
};

// ---------------------------------------------------------------------------------------------
// Reading. Every failure is one FileError sentence prefixed by the source name.

class ProjectReader {
 public:
  explicit ProjectReader(std::string_view sourceName) : source_(sourceName) {}

  Project read(std::string_view bytes) {
    // Header: magic, version, manifest length and checksum.
    const size_t magicSeen = std::min(bytes.size(), sizeof kMagic);
    if (magicSeen > 0 && std::memcmp(bytes.data(), kMagic, magicSeen) != 0) {
      fail("not a sculpt project (the file does not start with the SCULPT magic bytes)");
    }
    if (bytes.size() < kHeaderSize) {
      fail("the file is truncated (" + std::to_string(bytes.size()) +
           " bytes, the header alone needs " + std::to_string(kHeaderSize) + ")");
    }
    const uint32_t version = getU32(bytes.data() + 7);
    if (version > kProjectFormatVersion) {
      fail("the project was written by a newer sculpt (format version " + std::to_string(version) +
           "; this build reads versions up to " + std::to_string(kProjectFormatVersion) + ")");
    }
    if (version == 0) fail("format version 0 is not a valid project format version");
    const uint32_t manifestLength = getU32(bytes.data() + 11);
    const uint32_t manifestCrc = getU32(bytes.data() + 15);
    std::string_view rest = bytes.substr(kHeaderSize);
    if (manifestLength > rest.size()) {
      fail("the file is truncated (the manifest needs " + std::to_string(manifestLength) +
           " bytes, " + std::to_string(rest.size()) + " are left)");
    }
    const std::string_view manifestText = rest.substr(0, manifestLength);
    if (crc32(manifestText) != manifestCrc) {
      fail("the manifest checksum does not match (the file is corrupt)");
    }
    rest.remove_prefix(manifestLength);

    const json manifest = parseManifest(manifestText);
    if (text(manifest, "format", "") != kFormatName) {
      fail("the manifest's format is not \"" + std::string(kFormatName) + "\"");
    }
    if (count(manifest, "version", "") != version) {
      fail("the manifest's version does not match the header's (" + std::to_string(version) + ")");
    }

    // Blob table: the expected blobs in order, their sizes adding up to the rest of the file.
    const json& table = require(manifest, "blobs", "");
    if (!table.is_array() || table.size() != kBlobs.size()) {
      fail("the manifest must list " + std::to_string(kBlobs.size()) + " blobs");
    }
    std::array<std::string_view, kBlobs.size()> blobs;
    std::array<uint64_t, kBlobs.size()> counts{};
    uint64_t needed = 0;
    for (size_t i = 0; i < kBlobs.size(); ++i) {
      const std::string where = "blobs[" + std::to_string(i) + "].";
      const json& entry = table[i];
      if (!entry.is_object()) fail("manifest entry " + where + " is not an object");
      if (text(entry, "name", where) != kBlobs[i].name) {
        fail("blob " + std::to_string(i) + " must be \"" + kBlobs[i].name + "\"");
      }
      if (text(entry, "type", where) != typeName(kBlobs[i].type)) {
        fail(std::string("blob \"") + kBlobs[i].name + "\" must have type " +
             typeName(kBlobs[i].type));
      }
      counts[i] = count(entry, "count", where);
      const uint64_t size = elementSize(kBlobs[i].type);
      if (counts[i] > (std::numeric_limits<uint64_t>::max() - needed) / size) {
        fail(std::string("blob \"") + kBlobs[i].name + "\" is impossibly large");
      }
      const uint64_t blobBytes = counts[i] * size;
      if (needed + blobBytes > rest.size()) {
        fail(std::string("the file is truncated (blob \"") + kBlobs[i].name + "\" needs " +
             std::to_string(blobBytes) + " bytes, " +
             std::to_string(rest.size() - std::min<uint64_t>(needed, rest.size())) + " are left)");
      }
      blobs[i] = rest.substr(static_cast<size_t>(needed), static_cast<size_t>(blobBytes));
      needed += blobBytes;
      if (crc32(blobs[i]) != count(entry, "crc32", where)) {
        fail(std::string("the checksum of blob \"") + kBlobs[i].name +
             "\" does not match (the file is corrupt)");
      }
    }
    if (needed != rest.size()) {
      fail("the file has " + std::to_string(rest.size() - needed) +
           " unexpected bytes after the last blob");
    }

    Project project;
    readControlMesh(require(manifest, "controlMesh", ""), blobs, counts, project.controlMesh);
    readMaterials(require(manifest, "materials", ""), blobs, counts, project.materials);
    expectCount(count(manifest, "pins", ""), counts[8], "pins", 1);
    project.pins = u32s(blobs[8]);
    readSurface(require(manifest, "surface", ""), blobs[9], project.surface);
    readCamera(require(manifest, "camera", ""), project.camera);
    readSimulation(require(manifest, "simulation", ""), project.simulation);
    readTools(require(manifest, "tools", ""), project.tools);
    if (const std::string problem = projectProblem(project); !problem.empty()) fail(problem);
    return project;
  }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw FileError(std::string(source_) + ": " + message);
  }

  json parseManifest(std::string_view text) const {
    if (excessiveJsonNesting(text, kMaxNesting) != std::string_view::npos)
      fail("the manifest is not valid JSON (nested too deep)");
    try {
      return json::parse(text.begin(), text.end());
    } catch (const json::exception& error) {
      (void)error;
      fail("the manifest is not valid JSON");
    }
  }

  const json& require(const json& object, const char* key, const std::string& where) const {
    if (!object.is_object()) {
      fail(where.empty() ? std::string("the manifest is not a JSON object")
                         : "manifest entry \"" + where + "\" is not an object");
    }
    const auto it = object.find(key);
    if (it == object.end()) fail("the manifest lacks \"" + where + key + "\"");
    return *it;
  }
  uint64_t count(const json& object, const char* key, const std::string& where) const {
    const json& value = require(object, key, where);
    if (!value.is_number_unsigned()) {
      fail("manifest entry \"" + where + key + "\" is not a non-negative integer");
    }
    return value.get<uint64_t>();
  }
  int integer(const json& object, const char* key, const std::string& where) const {
    const json& value = require(object, key, where);
    if (!value.is_number_integer() || value.get<int64_t>() < 0 ||
        value.get<int64_t>() > kMaxProjectLevel) {
      fail("manifest entry \"" + where + key + "\" is not an integer from 0 to " +
           std::to_string(kMaxProjectLevel));
    }
    return static_cast<int>(value.get<int64_t>());
  }
  double number(const json& value, const std::string& name) const {
    if (!value.is_number()) fail("manifest entry \"" + name + "\" is not a number");
    const double x = value.get<double>();
    if (!std::isfinite(x)) fail("manifest entry \"" + name + "\" is not a finite number");
    return x;
  }
  double number(const json& object, const char* key, const std::string& where) const {
    return number(require(object, key, where), where + key);
  }
  Eigen::Vector3d vector(const json& object, const char* key, const std::string& where) const {
    const json& value = require(object, key, where);
    if (!value.is_array() || value.size() != 3) {
      fail("manifest entry \"" + where + key + "\" is not a list of 3 numbers");
    }
    return {number(value[0], where + key), number(value[1], where + key),
            number(value[2], where + key)};
  }
  bool boolean(const json& object, const char* key, const std::string& where) const {
    const json& value = require(object, key, where);
    if (!value.is_boolean()) fail("manifest entry \"" + where + key + "\" is not true or false");
    return value.get<bool>();
  }
  std::string text(const json& object, const char* key, const std::string& where) const {
    const json& value = require(object, key, where);
    if (!value.is_string()) fail("manifest entry \"" + where + key + "\" is not a string");
    return value.get<std::string>();
  }

  void expectCount(uint64_t declared, uint64_t blobCount, const char* what, uint64_t per) const {
    if (declared > std::numeric_limits<uint64_t>::max() / per || declared * per != blobCount) {
      fail(std::string("inconsistent counts: the manifest declares ") + std::to_string(declared) +
           " " + what + " but the blob holds " + std::to_string(blobCount) + " values");
    }
  }

  std::vector<uint32_t> u32s(std::string_view blob) const {
    std::vector<uint32_t> values(blob.size() / 4);
    for (size_t i = 0; i < values.size(); ++i) values[i] = getU32(blob.data() + 4 * i);
    return values;
  }
  std::vector<double> f64s(std::string_view blob) const {
    std::vector<double> values(blob.size() / 8);
    for (size_t i = 0; i < values.size(); ++i) {
      values[i] = getF64(blob.data() + 8 * i);
      if (!std::isfinite(values[i])) fail("a stored number is not finite (the file is corrupt)");
    }
    return values;
  }

  template <size_t N>
  void readControlMesh(const json& section, const std::array<std::string_view, N>& blobs,
                       const std::array<uint64_t, N>& counts, CellComplex& mesh) const {
    const std::string where = "controlMesh.";
    const uint64_t vertices = count(section, "vertices", where);
    const uint64_t cells = count(section, "cells", where);
    const uint64_t loops = count(section, "faceLoops", where);
    expectCount(vertices, counts[0], "control points (x 3)", 3);
    if (cells == std::numeric_limits<uint64_t>::max() ||
        loops == std::numeric_limits<uint64_t>::max()) {
      fail("inconsistent counts in the control mesh");
    }
    expectCount(cells + 1, counts[1], "cells (+1 offsets)", 1);
    expectCount(loops + 1, counts[2], "face loops (+1 offsets)", 1);
    expectCount(count(section, "loopVertices", where), counts[3], "face loop vertices", 1);
    expectCount(count(section, "creases", where), counts[4], "creases (x 2)", 2);
    expectCount(count(section, "corners", where), counts[5], "corners", 1);

    const std::vector<double> positions = f64s(blobs[0]);
    mesh.positions.resize(static_cast<Eigen::Index>(vertices), 3);
    std::copy(positions.begin(), positions.end(), mesh.positions.data());
    mesh.cellFaceBegin = u32s(blobs[1]);
    mesh.loopBegin = u32s(blobs[2]);
    mesh.loopVertices = u32s(blobs[3]);
    const std::vector<uint32_t> creases = u32s(blobs[4]);
    mesh.creases.resize(creases.size() / 2);
    for (size_t i = 0; i < mesh.creases.size(); ++i) {
      mesh.creases[i] = {creases[2 * i], creases[2 * i + 1]};
    }
    mesh.corners = u32s(blobs[5]);
  }

  template <size_t N>
  void readMaterials(const json& section, const std::array<std::string_view, N>& blobs,
                     const std::array<uint64_t, N>& counts, MaterialSamples& samples) const {
    const std::string where = "materials.";
    samples.level = integer(section, "level", where);
    const uint64_t n = count(section, "samples", where);
    expectCount(n, counts[6], "material sample positions (x 3)", 3);
    expectCount(n, counts[7], "material sample values (x 4)", 4);
    const std::vector<double> positions = f64s(blobs[6]);
    const std::vector<double> values = f64s(blobs[7]);
    samples.restPositions.resize(static_cast<size_t>(n));
    samples.materials.resize(static_cast<size_t>(n));
    for (size_t i = 0; i < samples.size(); ++i) {
      samples.restPositions[i] = {positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]};
      Material& m = samples.materials[i];
      m.youngs = values[4 * i];
      m.poisson = values[4 * i + 1];
      m.density = values[4 * i + 2];
      m.damping = values[4 * i + 3];
    }
  }

  void readSurface(const json& section, std::string_view blob, SurfaceSource& surface) const {
    const std::string where = "surface.";
    surface.path = text(section, "path", where);
    surface.contentHash = text(section, "contentHash", where);
    surface.embedded = boolean(section, "embedded", where);
    if (!surface.embedded && !blob.empty()) {
      fail("the surface is not embedded but the file holds surface data");
    }
    surface.objText = std::string(blob);
  }

  void readCamera(const json& section, CameraState& camera) const {
    const std::string where = "camera.";
    camera.pivot = vector(section, "pivot", where);
    camera.yawRad = number(section, "yawRad", where);
    camera.pitchRad = number(section, "pitchRad", where);
    camera.distance = number(section, "distance", where);
    camera.orthographic = boolean(section, "orthographic", where);
  }

  void readSimulation(const json& section, ProjectSimulation& sim) const {
    const std::string where = "simulation.";
    sim.integrator = text(section, "integrator", where);
    sim.timeStepS = number(section, "timeStepS", where);
    sim.gravity = vector(section, "gravity", where);
    sim.level = integer(section, "level", where);
  }

  void readTools(const json& section, ToolSettings& tools) const {
    if (!section.is_object()) fail("manifest entry \"tools\" is not an object");
    for (const auto& [key, value] : section.items()) {
      if (value.is_boolean()) {
        tools[key] = value.get<bool>();
      } else if (value.is_number()) {
        tools[key] = number(value, "tools." + printable(key));
      } else if (value.is_string()) {
        tools[key] = value.get<std::string>();
      } else {
        fail("tool setting \"" + printable(key) + "\" is not true/false, a number or a string");
      }
    }
  }

  std::string_view source_;
};

}  // namespace

std::string serializeProject(const Project& project) {
  if (const std::string problem = projectProblem(project); !problem.empty()) {
    throw std::invalid_argument("cannot save the project: " + problem);
  }
  const CellComplex& mesh = project.controlMesh;
  const MaterialSamples& samples = project.materials;

  // Blobs, in the order of kBlobs.
  BlobWriter blobs;
  blobs.addF64(mesh.positions.data(), static_cast<size_t>(mesh.positions.size()));
  blobs.addU32(mesh.cellFaceBegin.data(), mesh.cellFaceBegin.size());
  blobs.addU32(mesh.loopBegin.data(), mesh.loopBegin.size());
  blobs.addU32(mesh.loopVertices.data(), mesh.loopVertices.size());
  std::vector<uint32_t> creases;
  for (const auto& edge : mesh.creases) creases.insert(creases.end(), edge.begin(), edge.end());
  blobs.addU32(creases.data(), creases.size());
  blobs.addU32(mesh.corners.data(), mesh.corners.size());
  std::vector<double> positions, values;
  positions.reserve(3 * samples.size());
  values.reserve(4 * samples.size());
  for (size_t i = 0; i < samples.size(); ++i) {
    const Eigen::Vector3d& x = samples.restPositions[i];
    positions.insert(positions.end(), {x.x(), x.y(), x.z()});
    const Material& m = samples.materials[i];
    values.insert(values.end(), {m.youngs, m.poisson, m.density, m.damping});
  }
  blobs.addF64(positions.data(), positions.size());
  blobs.addF64(values.data(), values.size());
  blobs.addU32(project.pins.data(), project.pins.size());
  blobs.addBytes(project.surface.embedded ? std::string_view(project.surface.objText) : "");

  // Manifest: nlohmann's objects are sorted by key, so the text is a function of the project.
  json tools = json::object();
  for (const auto& [key, value] : project.tools) {
    // clang 14 cannot capture a structured binding (C++20 allows it): the lambda takes the key.
    std::visit([&tools, &name = key](const auto& v) { tools[name] = v; }, value);
  }
  const json manifest = {
      {"format", kFormatName},
      {"version", kProjectFormatVersion},
      {"blobs", blobs.manifest()},
      {"controlMesh",
       {{"vertices", mesh.numVertices()},
        {"cells", mesh.numCells()},
        {"faceLoops", mesh.loopBegin.size() - 1},
        {"loopVertices", mesh.loopVertices.size()},
        {"creases", mesh.creases.size()},
        {"corners", mesh.corners.size()}}},
      {"materials", {{"level", samples.level}, {"samples", samples.size()}}},
      {"pins", project.pins.size()},
      {"surface",
       {{"path", project.surface.path},
        {"contentHash", project.surface.contentHash},
        {"embedded", project.surface.embedded}}},
      {"camera",
       {{"pivot", vectorJson(project.camera.pivot)},
        {"yawRad", project.camera.yawRad},
        {"pitchRad", project.camera.pitchRad},
        {"distance", project.camera.distance},
        {"orthographic", project.camera.orthographic}}},
      {"simulation",
       {{"integrator", project.simulation.integrator},
        {"timeStepS", project.simulation.timeStepS},
        {"gravity", vectorJson(project.simulation.gravity)},
        {"level", project.simulation.level}}},
      {"tools", tools},
  };
  std::string manifestText;
  try {
    manifestText = manifest.dump(1) + "\n";
  } catch (const json::type_error&) {
    throw std::invalid_argument("cannot save the project: a name or path is not valid UTF-8");
  }
  if (manifestText.size() > std::numeric_limits<uint32_t>::max()) {
    throw std::invalid_argument("cannot save the project: the manifest exceeds 4 GiB");
  }

  std::string out(kMagic, sizeof kMagic);
  putU32(out, kProjectFormatVersion);
  putU32(out, static_cast<uint32_t>(manifestText.size()));
  putU32(out, crc32(manifestText));
  out += manifestText;
  out += blobs.data();
  return out;
}

Project parseProject(std::string_view bytes, std::string_view sourceName) {
  return ProjectReader(sourceName).read(bytes);
}

void saveProject(const Project& project, const std::filesystem::path& path) {
  writeFileAtomically(path, serializeProject(project));
}

Project loadProject(const std::filesystem::path& path) {
  const std::string bytes = readInputFile(path, kProjectInput);
  return parseProject(bytes, path.filename().string());
}

}  // namespace sculpt
