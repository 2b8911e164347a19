#pragma once
// A sparse linear map from source points to destination points (d = A p), stored in compressed
// rows like OpenSubdiv's Far::StencilTable: "refine once, evaluate every frame".

#include <cstdint>
#include <vector>

#include "mesh/cell_complex.h"

namespace sculpt {

class StencilTable {
 public:
  StencilTable() = default;
  StencilTable(uint32_t numColumns, std::vector<uint32_t> offsets, std::vector<uint32_t> indices,
               std::vector<double> weights);
  /// The identity on n points.
  static StencilTable identity(uint32_t n);

  uint32_t numRows() const { return static_cast<uint32_t>(offsets_.size() - 1); }
  uint32_t numColumns() const { return numColumns_; }
  size_t numEntries() const { return indices_.size(); }
  const std::vector<uint32_t>& offsets() const { return offsets_; }  ///< #rows+1
  const std::vector<uint32_t>& indices() const { return indices_; }  ///< source point ids
  const std::vector<double>& weights() const { return weights_; }    ///< parallel to indices

  /// dst (#rows by 3) = A src (#columns by 3); dst is resized. Multi-threaded over rows.
  void apply(const Points& src, Points& dst) const;
  /// dst (#columns by 3) = A^T src (#rows by 3), resized; projects node forces onto control
  /// points.
  void applyTranspose(const Points& src, Points& dst) const;
  /// Sum of each row's weights (1 for an affine-invariant scheme).
  std::vector<double> rowSums() const;

  /// The product outer * inner (apply inner first), with rows merged and sorted by column.
  static StencilTable compose(const StencilTable& outer, const StencilTable& inner);

 private:
  uint32_t numColumns_ = 0;
  std::vector<uint32_t> offsets_{0};
  std::vector<uint32_t> indices_;
  std::vector<double> weights_;
};

/// A = S_K ... S_1 kept in factored form: applying the K small per-level tables in turn is
/// several times cheaper than the composed table, so this is the per-frame path.
class StencilChain {
 public:
  StencilChain() = default;
  explicit StencilChain(std::vector<StencilTable> levels);
  const std::vector<StencilTable>& levels() const { return levels_; }
  uint32_t numRows() const;
  uint32_t numColumns() const;
  /// dst = S_K ... S_1 src (intermediate levels in per-thread scratch buffers).
  void apply(const Points& src, Points& dst) const;
  /// dst = S_1^T ... S_K^T src: the transpose, e.g. node forces onto control points.
  void applyTranspose(const Points& src, Points& dst) const;

 private:
  void applyLevels(const Points& src, Points& dst, bool transpose) const;

  std::vector<StencilTable> levels_;
};

}  // namespace sculpt
