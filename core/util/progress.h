#pragma once
// Progress reporting and cancellation for long operations (refinement, embedding, export).

#include <functional>
#include <string_view>
#include <utility>

namespace sculpt {

/// Called with a fraction in [0, 1] and a short stage name; returns false to cancel the work.
using ProgressCallback = std::function<bool(double fraction, std::string_view stage)>;

/// Wraps an optional callback; a default-constructed reporter never cancels.
class ProgressReporter {
 public:
  ProgressReporter() = default;
  explicit ProgressReporter(ProgressCallback callback) : callback_(std::move(callback)) {}
  /// Reports progress; returns false once the user has asked to cancel (and stays false).
  bool report(double fraction, std::string_view stage) {
    if (cancelled_) return false;
    if (callback_ && !callback_(fraction, stage)) cancelled_ = true;
    return !cancelled_;
  }
  bool cancelled() const { return cancelled_; }

 private:
  ProgressCallback callback_;
  bool cancelled_ = false;
};

}  // namespace sculpt
