#pragma once
// Detailed surfaces in glTF 2.0 files (.gltf with external or data-URI buffers, .glb).
//
// Reading gathers every triangle primitive (triangles, strips and fans; points and lines are
// skipped) of every mesh that a node of the default scene instances, into one SurfaceMesh in
// scene space: positions are multiplied by the node's world matrix, normals by its inverse
// transpose. Each glTF vertex becomes one SurfaceMesh position, normal and texture coordinate
// with the same index, blocks of vertices following the depth-first node order, then the
// primitive order; primitives that share their vertex accessors share their block.
//
// The loaded document is kept, so that writing back after deformation rewrites only the POSITION
// and NORMAL data (in each node's local space, accessor min/max updated) and keeps materials,
// textures, animations and everything else. See docs/file-formats.md, "Surfaces (OBJ, glTF)",
// for what is rejected (sparse or compressed geometry, meshes instanced twice, ...).
//
// Texture coordinates follow the OBJ convention in SurfaceMesh (v grows upwards): the reader and
// writers flip glTF's v to 1 - v.

#include <filesystem>
#include <memory>

#include "mesh/surface_mesh.h"

namespace sculpt {

/// A glTF document and the surface gathered from it. tiny_gltf.h stays out of this header.
class GltfSurfaceFile {
 public:
  /// Reads a .gltf or .glb file (chosen by content: binary files start with "glTF"). Throws
  /// FileError ("<path>: <element>: <problem>") for invalid, truncated or unsupported files.
  static GltfSurfaceFile read(const std::filesystem::path& path);

  GltfSurfaceFile(GltfSurfaceFile&&) noexcept;
  GltfSurfaceFile& operator=(GltfSurfaceFile&&) noexcept;
  ~GltfSurfaceFile();

  /// The surface in scene space (positions #V by 3; normals and texcoords #V rows or none).
  const SurfaceMesh& surface() const;

  /// Writes the document with `deformed`'s positions and normals (scene space, the same count
  /// and order as surface(); without normals the file keeps its own) as `path`: binary when it
  /// ends in .glb, else JSON with every buffer embedded as a data URI. External image files keep
  /// their URIs. Atomic. Throws FileError.
  void writeDeformed(const std::filesystem::path& path, const SurfaceMesh& deformed) const;

 private:
  struct Document;
  explicit GltfSurfaceFile(std::unique_ptr<Document> document);
  std::unique_ptr<Document> document_;
};

/// Writes a plain surface as a fresh glTF file with one mesh, one triangle primitive (polygons
/// fanned from their first corner), one node and one scene: binary when `path` ends in .glb,
/// else JSON with an embedded buffer. NORMAL and TEXCOORD_0 are written when every corner has
/// one. When every corner uses the same index for its position and those attributes (and the
/// attribute lists are as long as the position list), vertex i of the file is position i;
/// otherwise one vertex is written per distinct (v, vt, vn) corner tuple, in order of first
/// use, so the vertex count changes and unused positions are dropped. Throws FileError.
void writeSurfaceGltf(const std::filesystem::path& path, const SurfaceMesh& surface);

}  // namespace sculpt
