#pragma once
// Compressed rows (CSR adjacency): row i holds values[offsets[i] .. offsets[i+1]-1].

#include <cstdint>
#include <span>
#include <vector>

namespace sculpt {

template <typename T>
struct CompressedRows {
  std::vector<uint32_t> offsets{0};  ///< #rows+1
  std::vector<T> values;

  uint32_t numRows() const { return static_cast<uint32_t>(offsets.size() - 1); }
  std::span<const T> row(uint32_t i) const {
    return {values.data() + offsets[i], offsets[i + 1] - offsets[i]};
  }
  uint32_t rowSize(uint32_t i) const { return offsets[i + 1] - offsets[i]; }
  void closeRow() { offsets.push_back(static_cast<uint32_t>(values.size())); }
};

/// Inverts an incidence relation: given rows over [0, numTargets), returns for each target the
/// rows that mention it (in increasing row order, each row once per mention).
template <typename T>
CompressedRows<uint32_t> invertIncidence(const CompressedRows<T>& rows, uint32_t numTargets) {
  CompressedRows<uint32_t> inverse;
  inverse.offsets.assign(numTargets + 1, 0);
  for (const T& t : rows.values) ++inverse.offsets[static_cast<uint32_t>(t) + 1];
  for (uint32_t i = 0; i < numTargets; ++i) inverse.offsets[i + 1] += inverse.offsets[i];
  inverse.values.resize(rows.values.size());
  std::vector<uint32_t> cursor(inverse.offsets.begin(), inverse.offsets.end() - 1);
  for (uint32_t r = 0; r < rows.numRows(); ++r)
    for (const T& t : rows.row(r)) inverse.values[cursor[static_cast<uint32_t>(t)]++] = r;
  return inverse;
}

}  // namespace sculpt
