#pragma once
// Legacy VTK unstructured grids (`DATASET UNSTRUCTURED_GRID`) as volume meshes, ASCII and BINARY
// (big-endian). Cells may be in the classic `CELLS n size` layout or in the VTK 5.1 layout
// (`CELLS nOffsets nConnectivity`, `OFFSETS`, `CONNECTIVITY`). Tetrahedra (10), voxels (11),
// hexahedra (12), wedges (13) and pyramids (14) are read; wedges and pyramids are split into
// tetrahedra. Cells of dimension below 3 are skipped; other 3D cells (quadratic, polyhedra) are
// rejected. Data after the cells (POINT_DATA, CELL_DATA, FIELD) is ignored.

#include <filesystem>
#include <string>
#include <string_view>

#include "mesh/volume_mesh.h"

namespace sculpt {

/// Parses a whole .vtk file (`bytes` as read from disk) and validates the mesh
/// (findVolumeMeshProblem). `sourceName` starts every error message. Throws FileError.
VolumeMesh parseVtkVolumeMesh(std::string_view bytes, std::string_view sourceName,
                              CellShapeCheck shapes = CellShapeCheck::Required);

/// Reads and parses a .vtk file. Throws FileError.
VolumeMesh readVtkVolumeMesh(const std::filesystem::path& path,
                             CellShapeCheck shapes = CellShapeCheck::Required);

/// The mesh as a legacy VTK 4.2 file (classic CELLS layout, POINTS as double, cell types 10 and
/// 12). ASCII numbers have 17 significant digits, so both encodings read back bit for bit.
/// Throws std::invalid_argument for a cell that is neither 4 nor 8 nodes, or (binary) a node id
/// beyond the int32 range of the classic layout.
std::string volumeMeshToVtk(const VolumeMesh& mesh, bool binary);
/// The same file with other node positions (#nodes by 3, e.g. a deformed state; else
/// std::invalid_argument) and `title` as its title line; it ends after CELL_TYPES, so point and
/// cell data can follow.
std::string volumeMeshToVtk(const VolumeMesh& mesh, bool binary, const Points& positions,
                            std::string_view title);

/// Writes volumeMeshToVtk(mesh, binary) atomically. Throws FileError.
void writeVtkVolumeMesh(const std::filesystem::path& path, const VolumeMesh& mesh, bool binary);

}  // namespace sculpt
