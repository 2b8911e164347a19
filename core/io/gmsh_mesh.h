#pragma once
// Gmsh meshes (.msh), ASCII format versions 2.2 (also 2.0 and 2.1, the same layout) and 4.1, as
// volume meshes. Node tags may be sparse; they are renumbered 0..N-1 in file order. Linear
// tetrahedra (type 4) and hexahedra (5) are read, prisms (6) and pyramids (7) are split into
// tetrahedra; points, lines and surface elements are skipped; other 3D elements (second order
// and higher) are rejected. Binary files and other versions are rejected with a message that
// says how to re-save the mesh. Sections other than $MeshFormat, $Nodes and $Elements are
// skipped.

#include <filesystem>
#include <string_view>

#include "mesh/volume_mesh.h"

namespace sculpt {

/// Parses the text of a .msh file and validates the mesh (findVolumeMeshProblem).
/// `sourceName` starts every error message. Throws FileError.
VolumeMesh parseGmshMesh(std::string_view text, std::string_view sourceName,
                         CellShapeCheck shapes = CellShapeCheck::Required);

/// Reads and parses a .msh file. Throws FileError.
VolumeMesh readGmshMesh(const std::filesystem::path& path,
                        CellShapeCheck shapes = CellShapeCheck::Required);

}  // namespace sculpt
