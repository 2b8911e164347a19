#pragma once
// Legacy ASCII VTK unstructured grids (version 4.2, readable by ParaView): hexahedra as
// VTK_HEXAHEDRON, every other cell as VTK_POLYHEDRON with its outward face stream, and the cell
// shape as an integer cell field.

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

#include "mesh/cell_complex.h"
#include "mesh/hexahedron.h"  // vtkHexahedronOrder: the VTK_HEXAHEDRON vertex order
#include "mesh/topology.h"

namespace sculpt {

inline constexpr int kVtkHexahedron = 12;
inline constexpr int kVtkPolyhedron = 42;

/// A named per-vertex vector field, written as POINT_DATA VECTORS (e.g. a displacement).
struct VtkPointVectors {
  std::string name;                ///< field name (spaces are replaced by '_')
  const Points* values = nullptr;  ///< #V by 3, one row per vertex of the complex
};

/// The whole file as text. `complex` supplies positions, `topology` (built from it) the cells.
/// Throws std::invalid_argument when a field has the wrong number of rows.
std::string vtkUnstructuredGrid(const CellComplex& complex, const Topology& topology,
                                std::span<const VtkPointVectors> pointVectors = {});

/// Writes vtkUnstructuredGrid(...) atomically. Throws FileError.
void writeVtk(const CellComplex& complex, const Topology& topology,
              const std::filesystem::path& path,
              std::span<const VtkPointVectors> pointVectors = {});

}  // namespace sculpt
