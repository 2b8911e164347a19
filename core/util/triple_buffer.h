#pragma once
// A value handed from one writer thread to one reader thread through three fixed slots:
// publish() fills the writer's slot and swaps it with the middle one, read() swaps the middle
// one with the reader's when it is newer. Both are wait-free and O(1) (one atomic exchange; no
// lock, no allocation), so neither side ever waits for the other, and the reader always sees a
// whole value, the newest one published when it looked (or the default before the first).
//
// T should be a small, trivially copyable value: publish copies it once.

#include <array>
#include <atomic>

namespace sculpt {

template <typename T>
class TripleBuffer {
 public:
  /// Writer thread: makes `value` the newest.
  void publish(const T& value) {
    slots_[writer_] = value;
    writer_ = middle_.exchange(writer_ | kFresh, std::memory_order_acq_rel) & kIndex;
  }
  /// Reader thread: the newest value published (T{} before the first).
  const T& read() {
    if (middle_.load(std::memory_order_relaxed) & kFresh)
      reader_ = middle_.exchange(reader_, std::memory_order_acq_rel) & kIndex;
    return slots_[reader_];
  }

 private:
  static constexpr unsigned kIndex = 3, kFresh = 4;
  std::array<T, 3> slots_{};
  unsigned writer_ = 0, reader_ = 1;  // each touched by its own thread only
  std::atomic<unsigned> middle_{2};
};

}  // namespace sculpt
