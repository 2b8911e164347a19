#include "io/volume_mesh_file.h"

#include <string>

#include "io/file_error.h"
#include "io/gmsh_mesh.h"
#include "io/tetgen_mesh.h"
#include "io/text_scanner.h"
#include "io/vtk_volume_mesh.h"

namespace sculpt {
namespace {

// Inserts "from <noun> <number>" after the "cell N" that starts a findVolumeMeshProblem message.
std::string withFileElement(const std::string& problem, std::span<const uint64_t> fileElementOfCell,
                            std::string_view elementNoun) {
  constexpr std::string_view kPrefix = "cell ";
  if (problem.compare(0, kPrefix.size(), kPrefix) != 0) return problem;
  size_t end = kPrefix.size();
  uint64_t cell = 0;
  while (end < problem.size() && problem[end] >= '0' && problem[end] <= '9' &&
         cell < (1ull << 40)) {
    cell = cell * 10 + static_cast<uint64_t>(problem[end] - '0');
    ++end;
  }
  if (end == kPrefix.size() || cell >= fileElementOfCell.size()) return problem;
  const std::string source =
      "from " + std::string(elementNoun) + " " + std::to_string(fileElementOfCell[cell]);
  if (problem.compare(end, 2, " (") == 0) {
    const size_t close = problem.find(')', end);
    if (close != std::string::npos)
      return problem.substr(0, close) + ", " + source + problem.substr(close);
  }
  return problem.substr(0, end) + " (" + source + ")" + problem.substr(end);
}

}  // namespace

void throwOnVolumeMeshProblem(const VolumeMesh& mesh, std::span<const uint64_t> fileElementOfCell,
                              std::string_view elementNoun, std::string_view sourceName,
                              CellShapeCheck shapes) {
  const std::string problem = findVolumeMeshProblem(mesh, shapes);
  if (problem.empty()) return;
  throw FileError(std::string(sourceName) + ": " +
                  withFileElement(problem, fileElementOfCell, elementNoun));
}

VolumeMesh readVolumeMesh(const std::filesystem::path& path, CellShapeCheck shapes) {
  const std::string extension = path.extension().string();
  if (equalsIgnoringCase(extension, ".vtk")) return readVtkVolumeMesh(path, shapes);
  if (equalsIgnoringCase(extension, ".msh")) return readGmshMesh(path, shapes);
  if (equalsIgnoringCase(extension, ".node") || equalsIgnoringCase(extension, ".ele")) {
    return readTetGenMesh(path, shapes);
  }
  throw FileError(path.string() + ": unknown volume mesh extension '" + extension +
                  "' (expected .vtk, .msh, .node or .ele)");
}

}  // namespace sculpt
