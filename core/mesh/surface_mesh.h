#pragma once
// A detailed surface to embed and deform: its vertex positions, in file order, with optional
// normals and texture coordinates kept as the file had them, and polygonal faces whose corners
// index those three arrays separately (as OBJ does; glTF files use the same index in all three).
// Deformation changes positions and normals and nothing else, so a surface written back has the
// input's vertex count, order, faces and texture coordinates.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "mesh/cell_complex.h"
#include "util/compressed_rows.h"

namespace sculpt {

/// #T by 2 texture coordinates.
using TexCoords = Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor>;

/// One face corner: indices into positions, texcoords and normals; kNoIndex where absent.
struct SurfaceCorner {
  static constexpr uint32_t kNoIndex = 0xffffffffu;
  uint32_t position = kNoIndex;
  uint32_t texcoord = kNoIndex;
  uint32_t normal = kNoIndex;
};

struct SurfaceMesh {
  Points positions;                       ///< #V by 3
  Points normals;                         ///< #VN by 3 (may be 0 rows)
  TexCoords texcoords;                    ///< #VT by 2 (may be 0 rows)
  CompressedRows<SurfaceCorner> faces;    ///< polygon corners, counter-clockwise from outside

  uint32_t numVertices() const { return static_cast<uint32_t>(positions.rows()); }
  uint32_t numFaces() const { return faces.numRows(); }
};

/// For each normal, the position it belongs to: the position of the first face corner that uses
/// it (deformation moves a normal with the surface at that point). kNoIndex for unused normals.
std::vector<uint32_t> normalAnchors(const SurfaceMesh& surface);

}  // namespace sculpt
