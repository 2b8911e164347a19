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

#include "mesh/cell_complex.h"

namespace sculpt {

/// A file that cannot be read or parsed. what() is one line naming the file, the element and
/// the problem, e.g. "block.json: cell 3, face 2: vertex index -1 is negative".
class FileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

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
