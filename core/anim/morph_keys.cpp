#include "anim/morph_keys.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <stdexcept>

namespace sculpt {
namespace {

// The largest vertex distance of the frames strictly between window[0] and window.back() from
// the interpolation of those two; stops early (returning a value over `tolerance`) once one
// vertex is too far.
double interpolationError(const std::deque<SurfaceFrameData>& window, double tolerance) {
  const size_t span = window.size() - 1;
  const std::vector<float>& a = window.front().positions;
  const std::vector<float>& b = window.back().positions;
  const double limit = tolerance * tolerance;
  double worst = 0.0;
  for (size_t i = 1; i < span; ++i) {
    const double s = static_cast<double>(i) / static_cast<double>(span);
    const std::vector<float>& p = window[i].positions;
    for (size_t k = 0; k + 2 < p.size(); k += 3) {
      double squared = 0.0;
      for (size_t c = k; c < k + 3; ++c) {
        const double lerp = (1.0 - s) * double(a[c]) + s * double(b[c]);
        const double d = double(p[c]) - lerp;
        squared += d * d;
      }
      worst = std::max(worst, squared);
      if (worst > limit) return std::sqrt(worst);
    }
  }
  return std::sqrt(worst);
}

}  // namespace

double morphKeyTolerance(const SurfaceMesh& rest, double relative) {
  if (rest.positions.rows() == 0) return 0.0;
  const Eigen::RowVector3d low = rest.positions.colwise().minCoeff();
  const Eigen::RowVector3d high = rest.positions.colwise().maxCoeff();
  return relative * (high - low).norm();
}

MorphKeys chooseMorphKeys(const AnimatedSurface& take, uint32_t segment,
                          const MorphKeyOptions& options, const MorphFrameCallback& onFrame,
                          const MorphKeyCallback& onKey) {
  if (options.maxSpan < 1) throw std::invalid_argument("chooseMorphKeys: maxSpan must be >= 1");
  MorphKeys keys;
  const FrameRange range = take.segment(segment);
  if (range.count == 0) return keys;
  const auto addKey = [&](uint32_t frame, const SurfaceFrameData& surface) {
    keys.frames.push_back(frame);
    if (onKey) onKey(frame, surface);
  };

  // window[i] is frame a + i, where a is the last key.
  // Keys are chosen (and their position bounds taken) from positions alone.
  std::deque<SurfaceFrameData> window(1);
  window.front().withNormals = false;
  take.evaluateSurface(range.first, window.front());
  addKey(range.first, window.front());
  if (onFrame && !onFrame(range.first)) return keys;
  uint32_t a = range.first;
  double acceptedError = 0.0;           // of the frames between a and the newest frame but one
  std::vector<SurfaceFrameData> spare;  // buffers of dropped frames, reused to spare allocations
  for (uint32_t b = range.first + 1; b < range.first + range.count; ++b) {
    SurfaceFrameData next;
    if (!spare.empty()) {
      next = std::move(spare.back());
      spare.pop_back();
    }
    next.withNormals = false;
    take.evaluateSurface(b, next);
    window.push_back(std::move(next));
    const double error =
        b - a <= options.maxSpan ? interpolationError(window, options.tolerance) : HUGE_VAL;
    if (error > options.tolerance) {
      // b - 1 is the last frame that a reaches: it becomes the key; b follows it.
      keys.maxError = std::max(keys.maxError, acceptedError);
      a = b - 1;
      while (window.size() > 2) {
        spare.push_back(std::move(window.front()));
        window.pop_front();
      }
      addKey(a, window.front());
      acceptedError = 0.0;
    } else {
      acceptedError = error;
    }
    if (onFrame && !onFrame(b)) return keys;
  }
  const uint32_t last = range.first + range.count - 1;
  if (last != a) {
    keys.maxError = std::max(keys.maxError, acceptedError);
    addKey(last, window.back());
  }
  return keys;
}

}  // namespace sculpt
