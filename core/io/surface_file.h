#pragma once
// Reading a detailed surface from any supported file, and writing it back after deformation in
// the format the output name asks for. Formats: OBJ (.obj) and glTF 2.0 (.gltf, .glb); see
// docs/file-formats.md, "Surfaces (OBJ, glTF)".

#include <filesystem>
#include <memory>

#include "io/gltf_surface.h"
#include "mesh/surface_mesh.h"

namespace sculpt {

/// A surface as read, with the glTF document it came from (if any) so that a glTF output can
/// keep everything the deformation does not touch. Cheap to copy (the document is shared).
class LoadedSurface {
 public:
  LoadedSurface(std::filesystem::path path, SurfaceMesh surface);
  LoadedSurface(std::filesystem::path path, GltfSurfaceFile gltf);

  const std::filesystem::path& path() const { return path_; }
  /// The surface to deform (scene space for glTF).
  const SurfaceMesh& surface() const { return gltf_ ? gltf_->surface() : surface_; }
  /// The glTF document, or null when the input was OBJ.
  const GltfSurfaceFile* gltf() const { return gltf_.get(); }

 private:
  std::filesystem::path path_;
  SurfaceMesh surface_;  // OBJ input only; a glTF document holds its own
  std::shared_ptr<const GltfSurfaceFile> gltf_;
};

/// Reads .obj, .gltf or .glb (by extension, any letter case). Throws FileError
/// ("<path>: ...") for unsupported extensions and invalid files.
LoadedSurface readSurfaceFile(const std::filesystem::path& path);

/// Writes `original` with the positions and normals of `deformed` (same counts and order;
/// `deformed` may have no normals: then the original ones are kept), in the format of `path`'s
/// extension: .obj as OBJ text (17 significant digits); .glb or .gltf as the original document
/// rewritten when the input was glTF, else as a fresh glTF file (writeSurfaceGltf). Faces and
/// texture coordinates always come from `original`. Atomic. Throws FileError.
void writeSurfaceFile(const std::filesystem::path& path, const LoadedSurface& original,
                      const SurfaceMesh& deformed);

}  // namespace sculpt
