#pragma once
// Curve-based manipulation (McDonnell-Qin section 4.1, Fig. 9a): the user draws a curve on the
// solid (a polyline of rest positions); the tool resamples it at points evenly spaced by arc
// length, locates each as a material point (MaterialPointLocator, as a grab does) and attaches
// a zero-length spring per point (tools/tool_springs.h, the pull tool's springs). Dragging moves
// every target by the drag translation d weighted by a profile along the curve:
//
//   target_i = anchor_i + w(s_i) d,   s_i = i / (n - 1) the arc-length fraction of sample i
//                                     (s = 0.5 for a single sample),
//   rigid:  w(s) = 1                  (the curve moves as a whole),
//   smooth: w(s) = sin(pi s)          (the middle moves fully, the ends stay where they were),
//
// anchor_i being where point i was at grab time. The total stiffness (default
// defaultPullStiffness, as one pull spring) is split evenly over the n springs, so a rigid drag
// pulls about as hard as one pull spring dragged by the same amount. Release lets go of every
// spring or keeps them (ReleaseMode), as PullTool does. The tool keeps a reference to its
// simulator, which must outlive it.

#include <Eigen/Core>
#include <optional>
#include <string_view>
#include <vector>

#include "sim/material_point.h"
#include "sim/simulator.h"
#include "tools/tool_springs.h"

namespace sculpt {

enum class CurveProfile { Rigid, Smooth };

/// "rigid", "smooth".
const char* curveProfileName(CurveProfile profile);
/// The profile named `name` (as curveProfileName writes it), nullopt otherwise.
std::optional<CurveProfile> parseCurveProfile(std::string_view name);
/// The drag weight at arc-length fraction s in [0, 1]: rigid 1, smooth sin(pi s).
double curveProfileWeight(CurveProfile profile, double s);

/// Most samples on one curve.
constexpr size_t kMaxCurveSamples = 1024;

/// Length of the polyline (m).
double polylineLength(const std::vector<Eigen::Vector3d>& polyline);

/// Default number of samples for a curve of `length` metres: one per half typical cell
/// (typicalCellSize) plus one, clamped to [2, 256]; 1 for a curve of length 0.
size_t defaultCurveSamples(const FemModel& model, double length);

/// A point of the resampled curve.
struct CurveSample {
  MaterialPoint point;
  Eigen::Vector3d rest = Eigen::Vector3d::Zero();  ///< resampled rest position on the polyline
  double s = 0.5;                                  ///< arc-length fraction in [0, 1]
};

/// Resamples the rest polyline at `count` points evenly spaced by arc length (count 0:
/// defaultCurveSamples; a curve of length 0 gives one sample) and locates each. Throws
/// std::invalid_argument for an empty or non-finite polyline, a count above kMaxCurveSamples or
/// a point that cannot be located (a model without elements).
std::vector<CurveSample> sampleCurve(const FemModel& model, const MaterialPointLocator& locator,
                                     const std::vector<Eigen::Vector3d>& polyline,
                                     size_t count = 0);

class CurveTool {
 public:
  explicit CurveTool(Simulator& simulator) : springs_(simulator) {}
  CurveTool(const CurveTool&) = delete;
  CurveTool& operator=(const CurveTool&) = delete;

  /// Grabs the curve's samples (a previous grab is let go), the drag offset at zero. `stiffness`
  /// is the curve's total in N/m (<= 0: defaultPullStiffness), split evenly. Throws
  /// std::invalid_argument for no samples or a non-finite stiffness.
  void grab(std::vector<CurveSample> samples, CurveProfile profile = CurveProfile::Rigid,
            double stiffness = 0.0);
  /// sampleCurve with a one-off locator, then grab.
  void grab(const std::vector<Eigen::Vector3d>& polyline,
            CurveProfile profile = CurveProfile::Rigid, double stiffness = 0.0, size_t count = 0);
  /// Sets the drag translation (m): target_i = anchor_i + w(s_i) offset. Nothing when not
  /// grabbing. Throws std::invalid_argument for a non-finite offset.
  void drag(const Eigen::Vector3d& offset);
  void release(ReleaseMode mode = ReleaseMode::LetGo);
  /// Removes the springs kept by release(Keep).
  void clearKept();

  bool active() const { return !springs_.held().empty(); }
  size_t numKept() const { return springs_.numKept(); }
  CurveProfile profile() const { return profile_; }
  /// The samples of the last grab, their weights w(s_i) and positions at grab time.
  const std::vector<CurveSample>& samples() const { return samples_; }
  const std::vector<double>& weights() const { return weights_; }
  const std::vector<Eigen::Vector3d>& anchors() const { return anchors_; }
  const Eigen::Vector3d& offset() const { return offset_; }
  /// Stiffness of each spring (total / n; N/m).
  double springStiffness() const { return springStiffness_; }
  /// Current positions of the samples (of the last grab).
  std::vector<Eigen::Vector3d> pointPositions() const;
  /// anchor_i + w(s_i) offset.
  std::vector<Eigen::Vector3d> targets() const;

 private:
  ToolSprings springs_;
  CurveProfile profile_ = CurveProfile::Rigid;
  std::vector<CurveSample> samples_;
  std::vector<double> weights_;
  std::vector<Eigen::Vector3d> anchors_;
  Eigen::Vector3d offset_ = Eigen::Vector3d::Zero();
  double springStiffness_ = 0.0;
};

}  // namespace sculpt
