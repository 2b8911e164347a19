#pragma once
// Arrays filled item by item (the columns of a sparse matrix, the rows of node blocks) whose
// final size is not known beforehand: reserved from the mean size of the items so far, instead
// of growing by doubling. A doubling holds the old and the new array at once and leaves up to
// half of the new one unused; in a first step every page of that is touched for the first time,
// which is dear on a VM (docs/memory.md).

#include <algorithm>
#include <cstddef>

namespace sculpt {

/// After item `done` of `total` has been appended to `first` and `rest` (arrays of the same
/// length): once 64 items (or all of them) are in, and whenever fewer than two items of the mean
/// size still fit, reserves the mean size for every item to come, an eighth more, and one more
/// item. An item over twice the mean can still make a vector grow by itself.
template <class First, class... Rest>
void reserveFromMean(size_t done, size_t total, First& first, Rest&... rest) {
  constexpr size_t kProbeItems = 64;
  if (done == 0 || done < std::min(kProbeItems, total)) return;
  const size_t entries = first.size(), mean = entries / done;
  if (first.capacity() - entries > 2 * mean) return;
  const size_t expected = entries + mean * (total - done) * 9 / 8 + mean;
  first.reserve(expected);
  (rest.reserve(expected), ...);
}

}  // namespace sculpt
