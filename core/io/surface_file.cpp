#include "io/surface_file.h"

#include <cctype>
#include <string>

#include "io/file_error.h"
#include "io/obj_surface.h"
#include "util/file_extension.h"

namespace sculpt {
namespace {

enum class SurfaceFormat { kObj, kGltf };

SurfaceFormat formatOf(const std::filesystem::path& path) {
  const std::string extension = lowerExtension(path);
  if (extension == ".obj") return SurfaceFormat::kObj;
  if (extension == ".gltf" || extension == ".glb") return SurfaceFormat::kGltf;
  throw FileError(path.string() + ": unsupported surface file extension '" +
                  path.extension().string() + "' (expected .obj, .gltf or .glb)");
}

/// The original surface with the deformed positions and, when given, normals.
SurfaceMesh withDeformation(const std::filesystem::path& path, const SurfaceMesh& original,
                            const SurfaceMesh& deformed) {
  if (deformed.positions.rows() != original.positions.rows()) {
    throw FileError(path.string() + ": the deformed surface has " +
                    std::to_string(deformed.positions.rows()) + " vertices, the input has " +
                    std::to_string(original.positions.rows()));
  }
  // Deformed normals are optional; they are ignored when the input had none (no corner uses them).
  const bool withNormals = deformed.normals.rows() != 0 && original.normals.rows() != 0;
  if (withNormals && deformed.normals.rows() != original.normals.rows()) {
    throw FileError(path.string() + ": the deformed surface has " +
                    std::to_string(deformed.normals.rows()) + " normals, the input has " +
                    std::to_string(original.normals.rows()));
  }
  SurfaceMesh result = original;
  result.positions = deformed.positions;
  if (withNormals) result.normals = deformed.normals;
  return result;
}

}  // namespace

LoadedSurface::LoadedSurface(std::filesystem::path path, SurfaceMesh surface)
    : path_(std::move(path)), surface_(std::move(surface)) {}

LoadedSurface::LoadedSurface(std::filesystem::path path, GltfSurfaceFile gltf)
    : path_(std::move(path)), gltf_(std::make_shared<const GltfSurfaceFile>(std::move(gltf))) {}

LoadedSurface readSurfaceFile(const std::filesystem::path& path) {
  if (formatOf(path) == SurfaceFormat::kObj) return {path, readObjSurface(path)};
  return {path, GltfSurfaceFile::read(path)};
}

void writeSurfaceFile(const std::filesystem::path& path, const LoadedSurface& original,
                      const SurfaceMesh& deformed) {
  const SurfaceFormat format = formatOf(path);
  if (format == SurfaceFormat::kGltf && original.gltf() != nullptr) {
    original.gltf()->writeDeformed(path, deformed);
    return;
  }
  const SurfaceMesh surface = withDeformation(path, original.surface(), deformed);
  if (format == SurfaceFormat::kObj) {
    writeObjSurface(path, surface);
  } else {
    writeSurfaceGltf(path, surface);
  }
}

}  // namespace sculpt
