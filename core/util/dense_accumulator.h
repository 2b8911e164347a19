#pragma once
// A dense accumulator over the rows of one sparse column at a time, and the rows it touched: the
// sparse products that assemble the mass and stand-in stiffness matrices sum into it. A row
// counts as touched when its stamp is the current column's, so nothing is cleared between
// columns but the touched sums (and no byte-sized flags, whose stores the compiler must assume
// may change the vectors' own pointers, which it then reloads at every add).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace sculpt {

template <typename Value>
class DenseAccumulator {
 public:
  DenseAccumulator(size_t rows, const Value& zero)
      : zero_(zero), sum_(rows, zero), stamp_(rows, 0), touched_(rows) {}

  void add(uint32_t row, const Value& value) {
    if (stamp_[row] != current_) {
      stamp_[row] = current_;
      touched_[count_++] = row;
    }
    sum_[row] += value;
  }
  /// The touched rows in increasing order (drain's order).
  void sortTouched() { std::sort(touched_.begin(), touched_.begin() + std::ptrdiff_t(count_)); }
  /// Calls f(row, sum) for every touched row, in the order touched (or sorted), and starts the
  /// next column.
  template <typename F>
  void drain(const F& f) {
    for (size_t k = 0; k < count_; ++k) {
      const uint32_t row = touched_[k];
      f(row, std::exchange(sum_[row], zero_));
    }
    count_ = 0;
    if (++current_ == 0) {  // the stamps wrapped around: start them again
      std::fill(stamp_.begin(), stamp_.end(), 0u);
      current_ = 1;
    }
  }

 private:
  Value zero_;
  std::vector<Value> sum_;
  std::vector<uint32_t> stamp_;
  std::vector<uint32_t> touched_;
  size_t count_ = 0;
  uint32_t current_ = 1;
};

}  // namespace sculpt
