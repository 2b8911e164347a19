#pragma once
// Detailed surfaces as Wavefront OBJ text. The reader keeps every list (v, vt, vn, f) in file
// order and every corner's own v/vt/vn indices, so a surface written back after deformation
// matches the input line for line except for the moved positions and normals.
//
// Read: `v x y z [w] [r g b]` (xyz kept), `vt u [v [w]]` (uv kept), `vn x y z`, `f` with corners
// `v`, `v/vt`, `v//vn` or `v/vt/vn`, 1-based or negative (relative to the end of each list so
// far), at least 3 corners. Comments (`#`) and the lines o, g, s, usemtl, mtllib, l, p and any
// other keyword are skipped. An index must refer to an element defined above its face line.

#include <filesystem>
#include <string>
#include <string_view>

#include "io/obj_text.h"
#include "mesh/surface_mesh.h"

namespace sculpt {

/// Parses OBJ text; `sourceName` starts every error message. Throws FileError
/// ("<source>: line <n>: <problem>") for malformed or non-finite numbers, zero or out-of-range
/// indices, faces with fewer than 3 corners, or text without faces.
SurfaceMesh parseObjSurface(std::string_view text, std::string_view sourceName);

/// Reads and parses a file. Throws FileError.
SurfaceMesh readObjSurface(const std::filesystem::path& path);

/// The OBJ text: a header comment with the counts, then v, vt, vn and f lines in the surface's
/// order. Corners are written as v, v/vt, v//vn or v/vt/vn, whichever indices they have.
std::string objSurfaceText(const SurfaceMesh& surface,
                           NumberPrecision precision = NumberPrecision::kDouble);

/// Writes objSurfaceText(...) atomically. Throws FileError for non-finite coordinates or
/// write failures.
void writeObjSurface(const std::filesystem::path& path, const SurfaceMesh& surface,
                     NumberPrecision precision = NumberPrecision::kDouble);

}  // namespace sculpt
