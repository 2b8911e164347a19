#pragma once
// TetGen meshes: a .node file (node positions) and a .ele file (tetrahedra) with the same stem,
// as `tetgen` writes them. '#' starts a comment; node attributes, boundary markers and region
// attributes are skipped. Numbering starts at 0 or 1, as the first node of the .node file says,
// and node numbers must be consecutive from there (TetGen's own rule). A 10-node (second-order)
// .ele is read as its 4 corner nodes, which TetGen lists first.
//
// Orientation: TetGen 1.5 lists each tetrahedron with det[X1-X0, X2-X0, X3-X0] > 0, which is our
// convention (volume_mesh.h); this was checked by meshing a cube with `tetgen -pq1.4a0.01Q`
// (562 tetrahedra, all positive). So nodes are taken as written, and a tetrahedron with a
// negative determinant is reported as inverted.

#include <filesystem>
#include <string_view>

#include "mesh/volume_mesh.h"

namespace sculpt {

/// Parses the texts of a .node and a .ele file and validates the mesh (findVolumeMeshProblem).
/// The source names start the error messages about each file. Throws FileError.
VolumeMesh parseTetGenMesh(std::string_view nodeText, std::string_view eleText,
                           std::string_view nodeSourceName, std::string_view eleSourceName,
                           CellShapeCheck shapes = CellShapeCheck::Required);

/// Reads `path` (a .node or a .ele file) and the other file of the pair (same stem). Throws
/// FileError.
VolumeMesh readTetGenMesh(const std::filesystem::path& path,
                          CellShapeCheck shapes = CellShapeCheck::Required);

}  // namespace sculpt
