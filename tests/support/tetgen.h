#pragma once
#include "support/required_tool.h"
#include "support/shell_quote.h"
// TetGen for tests: closed triangulated surfaces (a box, an icosphere), meshed into tetrahedra by
// the real `tetgen` program and loaded with our TetGen reader. It gives tests realistic
// unstructured volume meshes of known volume without storing them. Everything depends only on
// `tetgen` being on PATH; tetgenMesh returns nullopt when it is not, and tests fail:
//
//   SCULPT_REQUIRE_TOOL(test::tetgenAvailable(), "tetgen");
//   test::ScopedTempDir dir("box");
//   std::string error;
//   const auto mesh = test::tetgenMesh(test::boxSurface(lo, hi), 0.01, dir.path(), &error);
//   ASSERT_TRUE(mesh) << error;

#include <unistd.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <atomic>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "io/file_error.h"
#include "io/tetgen_mesh.h"
#include "mesh/volume_mesh.h"

namespace sculpt::test {

/// A closed triangulated surface: `triangles` index `vertices` and are counter-clockwise seen from
/// outside (outward normals).
struct TriangleSurface {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<uint32_t, 3>> triangles;
};

/// The axis-aligned box [lo, hi] as 12 triangles.
inline TriangleSurface boxSurface(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  TriangleSurface box;
  for (int corner = 0; corner < 8; ++corner) {  // bit 0: x, bit 1: y, bit 2: z
    box.vertices.emplace_back((corner & 1) ? hi.x() : lo.x(), (corner & 2) ? hi.y() : lo.y(),
                              (corner & 4) ? hi.z() : lo.z());
  }
  // Outward quads (counter-clockwise seen from outside), two triangles each.
  const std::array<std::array<uint32_t, 4>, 6> quads = {{{0, 2, 3, 1},    // z = lo
                                                         {4, 5, 7, 6},    // z = hi
                                                         {0, 1, 5, 4},    // y = lo
                                                         {2, 6, 7, 3},    // y = hi
                                                         {0, 4, 6, 2},    // x = lo
                                                         {1, 3, 7, 5}}};  // x = hi
  for (const auto& q : quads) {
    box.triangles.push_back({q[0], q[1], q[2]});
    box.triangles.push_back({q[0], q[2], q[3]});
  }
  return box;
}

/// A sphere approximated by an icosahedron whose faces are split in 4, `subdivisions` times, with
/// every vertex pushed onto the sphere: 20 * 4^subdivisions triangles.
inline TriangleSurface icosphereSurface(const Eigen::Vector3d& center, double radius,
                                        int subdivisions) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> unit = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                       {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                       {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (auto& v : unit) v.normalize();
  std::vector<std::array<uint32_t, 3>> faces = {
      {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;  // shared by both triangles
    const auto midpoint = [&](uint32_t a, uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto [it, inserted] = midpoints.try_emplace(key, static_cast<uint32_t>(unit.size()));
      if (inserted) unit.push_back((unit[a] + unit[b]).normalized());
      return it->second;
    };
    std::vector<std::array<uint32_t, 3>> finer;
    for (const auto& f : faces) {
      const uint32_t ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]),
                     ca = midpoint(f[2], f[0]);
      finer.push_back({f[0], ab, ca});
      finer.push_back({f[1], bc, ab});
      finer.push_back({f[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    faces = std::move(finer);
  }
  TriangleSurface sphere;
  for (const auto& v : unit) sphere.vertices.push_back(center + radius * v);
  sphere.triangles = std::move(faces);
  return sphere;
}

/// The volume enclosed by a closed outward surface (divergence theorem).
inline double enclosedVolume(const TriangleSurface& surface) {
  double volume = 0.0;
  for (const auto& t : surface.triangles) {
    volume += surface.vertices[t[0]].dot(surface.vertices[t[1]].cross(surface.vertices[t[2]]));
  }
  return volume / 6.0;
}

/// The sum of the signed volumes of the tetrahedra (TetGen writes no hexahedra).
inline double totalTetrahedronVolume(const VolumeMesh& mesh) {
  double volume = 0.0;
  for (uint32_t c = 0; c < mesh.numCells(); ++c) {
    if (mesh.isTetrahedron(c)) volume += tetrahedronSignedVolume(mesh, c);
  }
  return volume;
}

/// Whether an executable `tetgen` is on PATH.
inline bool tetgenAvailable() {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return false;
  std::istringstream dirs(path);
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const std::filesystem::path candidate =
        std::filesystem::path(dir.empty() ? "." : dir) / "tetgen";
    std::error_code ec;
    if (std::filesystem::is_regular_file(candidate, ec) && ::access(candidate.c_str(), X_OK) == 0) {
      return true;
    }
  }
  return false;
}

/// A fresh directory under the system temporary directory (unique per process and call), removed
/// with its contents when this goes out of scope unless SCULPT_KEEP_TEMP is set.
class ScopedTempDir {
 public:
  explicit ScopedTempDir(const std::string& label) {
    static std::atomic<unsigned> counter{0};
    const auto base = std::filesystem::temp_directory_path();
    for (int attempt = 0; attempt < 100 && path_.empty(); ++attempt) {
      const auto dir = base / ("sculpt_" + label + "_" + std::to_string(::getpid()) + "_" +
                               std::to_string(counter.fetch_add(1)));
      std::error_code ec;
      if (std::filesystem::create_directory(dir, ec)) path_ = dir;
    }
  }
  ScopedTempDir(const ScopedTempDir&) = delete;
  ScopedTempDir& operator=(const ScopedTempDir&) = delete;
  ~ScopedTempDir() {
    if (path_.empty() || std::getenv("SCULPT_KEEP_TEMP") != nullptr) return;
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  /// Empty when no directory could be created.
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

namespace tetgen_detail {

inline std::string number(double value) {
  char buffer[40];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);  // shortest exact
  return std::string(buffer, result.ptr);
}

/// The surface as a TetGen .smesh file (1-based numbering, no holes, no regions).
inline std::string smeshText(const TriangleSurface& surface) {
  std::string out = "# part 1: nodes\n" + std::to_string(surface.vertices.size()) + " 3 0 0\n";
  for (size_t i = 0; i < surface.vertices.size(); ++i) {
    const Eigen::Vector3d& v = surface.vertices[i];
    out += std::to_string(i + 1) + " " + number(v.x()) + " " + number(v.y()) + " " + number(v.z()) +
           "\n";
  }
  out += "# part 2: facets\n" + std::to_string(surface.triangles.size()) + " 0\n";
  for (const auto& t : surface.triangles) {
    out += "3 " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " +
           std::to_string(t[2] + 1) + "\n";
  }
  out += "# part 3: holes\n0\n# part 4: regions\n0\n";
  return out;
}

}  // namespace tetgen_detail

/// Meshes the inside of `surface` with `tetgen -pq1.4a<maxTetVolume>Q` in `workDir` (created if
/// needed; surface.smesh, surface.1.node, surface.1.ele and tetgen.log are left there) and loads
/// the result with readTetGenMesh, which validates it. Returns nullopt, with *error set, when
/// tetgen is not on PATH, fails, or writes a mesh that does not load.
inline std::optional<VolumeMesh> tetgenMesh(const TriangleSurface& surface, double maxTetVolume,
                                            const std::filesystem::path& workDir,
                                            std::string* error = nullptr) {
  std::string sink;
  std::string& err = error != nullptr ? *error : sink;
  if (!tetgenAvailable()) {
    err = "tetgen not found on PATH";
    return std::nullopt;
  }
  std::error_code ec;
  std::filesystem::create_directories(workDir, ec);
  {
    std::ofstream smesh(workDir / "surface.smesh", std::ios::binary);
    smesh << tetgen_detail::smeshText(surface);
    if (!smesh.flush()) {
      err = "cannot write " + (workDir / "surface.smesh").string();
      return std::nullopt;
    }
  }
  const std::string command = "cd " + shellQuote(workDir.string()) +
                              " && tetgen -pq1.4a" + tetgen_detail::number(maxTetVolume) +
                              "Q surface.smesh > tetgen.log 2>&1";
  if (std::system(command.c_str()) != 0) {
    err = "tetgen failed (" + command + "); see " + (workDir / "tetgen.log").string();
    return std::nullopt;
  }
  try {
    return readTetGenMesh(workDir / "surface.1.ele");
  } catch (const FileError& e) {
    err = e.what();
    return std::nullopt;
  }
}

}  // namespace sculpt::test
