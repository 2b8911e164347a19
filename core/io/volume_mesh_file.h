#pragma once
// Loading simulation volume meshes (tetrahedra and hexahedra) written by other programs: legacy
// VTK (.vtk), Gmsh (.msh) and TetGen (.node + .ele). docs/file-formats.md describes what is read.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>

#include "mesh/volume_mesh.h"

namespace sculpt {

/// Reads a volume mesh, choosing the reader by extension (case-insensitive): .vtk (legacy VTK),
/// .msh (Gmsh), .node or .ele (the TetGen pair with the same stem). The mesh is validated with
/// findVolumeMeshProblem. Throws FileError, whose message starts with the file path.
/// `shapes` = Skipped reads a deformed frame, whose cells may be inverted.
VolumeMesh readVolumeMesh(const std::filesystem::path& path,
                          CellShapeCheck shapes = CellShapeCheck::Required);

/// For the readers: throws FileError "<sourceName>: <problem>" when findVolumeMeshProblem finds
/// one. A problem with a mesh cell also names the element of the file it came from, since
/// skipped surface elements and split pyramids/wedges renumber cells:
///   "mesh.msh: cell 12 (tetrahedron, from element 57): inverted, signed volume -1.3e-05".
/// @param[in] fileElementOfCell  #cells: the file's number of the element each cell came from
/// @param[in] elementNoun        what the file calls its elements ("element", "VTK cell", ...)
void throwOnVolumeMeshProblem(const VolumeMesh& mesh, std::span<const uint64_t> fileElementOfCell,
                              std::string_view elementNoun, std::string_view sourceName,
                              CellShapeCheck shapes = CellShapeCheck::Required);

}  // namespace sculpt
