#pragma once
// A volumetric cell complex as the user (or a file) describes it: vertex positions and cells,
// each cell a list of face loops wound counter-clockwise when seen from outside the cell.
// This is the input to validation, topology building and MacCracken–Joy refinement.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

namespace sculpt {

/// #V by 3 matrix of positions, one row per vertex (row-major so a row is one xyz triple).
using Points = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// Cells stored in compressed rows: cell c owns the face loops cellFaceBegin[c] ..
/// cellFaceBegin[c+1]-1, and face loop i owns loopVertices[loopBegin[i] .. loopBegin[i+1]-1].
struct CellComplex {
  Points positions;                          ///< #V by 3 (metres)
  std::vector<uint32_t> cellFaceBegin{0};    ///< #C+1 offsets into the face-loop list
  std::vector<uint32_t> loopBegin{0};        ///< #loops+1 offsets into loopVertices
  std::vector<uint32_t> loopVertices;        ///< vertex ids, CCW seen from outside the owning cell
  std::vector<std::array<uint32_t, 2>> creases;  ///< tagged boundary edges (vertex pairs)
  std::vector<uint32_t> corners;                 ///< tagged boundary vertices

  uint32_t numVertices() const { return static_cast<uint32_t>(positions.rows()); }
  uint32_t numCells() const { return static_cast<uint32_t>(cellFaceBegin.size() - 1); }
  uint32_t numFacesOfCell(uint32_t c) const { return cellFaceBegin[c + 1] - cellFaceBegin[c]; }
  /// The vertex loop of the j-th face of cell c.
  std::span<const uint32_t> cellFace(uint32_t c, uint32_t j) const {
    const uint32_t loop = cellFaceBegin[c] + j;
    return {loopVertices.data() + loopBegin[loop], loopBegin[loop + 1] - loopBegin[loop]};
  }
  /// Appends a cell given as face loops (each CCW from outside).
  void addCell(const std::vector<std::vector<uint32_t>>& faceLoops);
  /// Appends a face loop to the cell being built; finishCell() closes it. For bulk builders.
  void addLoop(std::span<const uint32_t> loop) {
    loopVertices.insert(loopVertices.end(), loop.begin(), loop.end());
    loopBegin.push_back(static_cast<uint32_t>(loopVertices.size()));
  }
  void finishCell() { cellFaceBegin.push_back(static_cast<uint32_t>(loopBegin.size() - 1)); }
};

}  // namespace sculpt
