#pragma once
// The deformed control mesh as the command line and the headless window write it (--out F.vtk):
// the control mesh's cells at `positions`, with the POINT_DATA vector "displacement" (positions
// minus the rest positions). One function, so that both write the same bytes for the same state.

#include <filesystem>

#include "mesh/cell_complex.h"

namespace sculpt {

/// Writes `rest`'s cells at `positions` (#rest vertices by 3) atomically. Throws FileError, and
/// std::invalid_argument when the row count does not match.
void writeDeformedControlVtk(const CellComplex& rest, const Points& positions,
                             const std::filesystem::path& path);

}  // namespace sculpt
