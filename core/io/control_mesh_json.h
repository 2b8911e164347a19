#pragma once
// The control-mesh file format (docs/file-formats.md):
//   {"format": "sculpt-control-mesh", "version": 1, "vertices": [[x,y,z], ...],
//    "cells": [[[v0,v1,v2,...], [face 2], ...], ...], "creases": [[a,b], ...], "corners": [v, ...]}
// A cell may also be written {"type": "hex"|"tet"|"prism"|"pyramid", "vertices": [...]} in VTK
// vertex order.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

#include "io/file_error.h"
#include "mesh/cell_complex.h"

namespace sculpt {

/// Parses the JSON text; `sourceName` prefixes error messages. Throws FileError. Vertex indices
/// are not range-checked here (validate() reports them with the cell index).
CellComplex parseControlMeshJson(std::string_view text, std::string_view sourceName);
/// Reads and parses a file. Throws FileError.
CellComplex loadControlMeshJson(const std::filesystem::path& path);
/// Serialises in the same format (cells as face loops; positions with 17 significant digits).
std::string controlMeshToJson(const CellComplex& mesh);
/// Writes atomically (temporary file, flush, rename). Throws FileError.
void saveControlMeshJson(const CellComplex& mesh, const std::filesystem::path& path);

}  // namespace sculpt
