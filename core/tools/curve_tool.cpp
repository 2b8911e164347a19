#include "tools/curve_tool.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace sculpt {

const char* curveProfileName(CurveProfile profile) {
  return profile == CurveProfile::Smooth ? "smooth" : "rigid";
}

std::optional<CurveProfile> parseCurveProfile(std::string_view name) {
  if (name == "rigid") return CurveProfile::Rigid;
  if (name == "smooth") return CurveProfile::Smooth;
  return std::nullopt;
}

double curveProfileWeight(CurveProfile profile, double s) {
  if (profile == CurveProfile::Rigid) return 1.0;
  return std::sin(std::numbers::pi * std::clamp(s, 0.0, 1.0));
}

double polylineLength(const std::vector<Eigen::Vector3d>& polyline) {
  double length = 0.0;
  for (size_t i = 1; i < polyline.size(); ++i) length += (polyline[i] - polyline[i - 1]).norm();
  return length;
}

size_t defaultCurveSamples(const FemModel& model, double length) {
  if (!(length > 0)) return 1;
  const double samples = std::ceil(length / (0.5 * typicalCellSize(model))) + 1.0;
  return static_cast<size_t>(std::clamp(samples, 2.0, 256.0));
}

namespace {

// The point at arc length `at` along the polyline (of total length > 0).
Eigen::Vector3d pointAtLength(const std::vector<Eigen::Vector3d>& polyline, double at) {
  for (size_t i = 1; i < polyline.size(); ++i) {
    const double segment = (polyline[i] - polyline[i - 1]).norm();
    if (at <= segment && segment > 0)
      return polyline[i - 1] + (at / segment) * (polyline[i] - polyline[i - 1]);
    at -= segment;
  }
  return polyline.back();
}

}  // namespace

std::vector<CurveSample> sampleCurve(const FemModel& model, const MaterialPointLocator& locator,
                                     const std::vector<Eigen::Vector3d>& polyline, size_t count) {
  if (polyline.empty()) throw std::invalid_argument("curve: the curve has no points.");
  for (const Eigen::Vector3d& p : polyline)
    if (!p.allFinite()) throw std::invalid_argument("curve: a point of the curve is not finite.");
  if (count > kMaxCurveSamples)
    throw std::invalid_argument("curve: " + std::to_string(count) + " samples is more than " +
                                std::to_string(kMaxCurveSamples) + ".");
  const double length = polylineLength(polyline);
  if (count == 0) count = defaultCurveSamples(model, length);
  if (!(length > 0)) count = 1;
  std::vector<CurveSample> samples(count);
  for (size_t i = 0; i < count; ++i) {
    CurveSample& sample = samples[i];
    sample.s = count == 1 ? 0.5 : static_cast<double>(i) / static_cast<double>(count - 1);
    sample.rest = length > 0 ? pointAtLength(polyline, sample.s * length) : polyline.front();
    const std::optional<MaterialPoint> point = locator.locate(sample.rest);
    if (!point) throw std::invalid_argument("curve: the curve cannot be located in the solid.");
    sample.point = *point;
  }
  return samples;
}

void CurveTool::grab(std::vector<CurveSample> samples, CurveProfile profile, double stiffness) {
  if (samples.empty()) throw std::invalid_argument("curve: the curve has no samples.");
  const double total = toolStiffness(springs_.simulator().model(), stiffness, "curve");
  release(ReleaseMode::LetGo);
  samples_ = std::move(samples);
  profile_ = profile;
  offset_.setZero();
  springStiffness_ = total / static_cast<double>(samples_.size());
  std::vector<MaterialPoint> points;
  weights_.clear();
  for (const CurveSample& sample : samples_) {
    points.push_back(sample.point);
    weights_.push_back(curveProfileWeight(profile, sample.s));
  }
  anchors_ = currentPositions(springs_.simulator(), points);
  for (size_t i = 0; i < samples_.size(); ++i)
    springs_.add(samples_[i].point, anchors_[i], springStiffness_);
}

void CurveTool::grab(const std::vector<Eigen::Vector3d>& polyline, CurveProfile profile,
                     double stiffness, size_t count) {
  const FemModel& model = springs_.simulator().model();
  grab(sampleCurve(model, MaterialPointLocator(model.mesh()), polyline, count), profile, stiffness);
}

void CurveTool::drag(const Eigen::Vector3d& offset) {
  if (!offset.allFinite()) throw std::invalid_argument("curve: the drag offset is not finite.");
  if (!active()) return;
  offset_ = offset;
  const std::vector<Eigen::Vector3d> goals = targets();
  for (size_t i = 0; i < goals.size(); ++i) springs_.held()[i]->setTarget(goals[i]);
}

void CurveTool::release(ReleaseMode mode) { springs_.release(mode); }

void CurveTool::clearKept() { springs_.clearKept(); }

std::vector<Eigen::Vector3d> CurveTool::pointPositions() const {
  std::vector<MaterialPoint> points;
  for (const CurveSample& sample : samples_) points.push_back(sample.point);
  return currentPositions(springs_.simulator(), points);
}

std::vector<Eigen::Vector3d> CurveTool::targets() const {
  std::vector<Eigen::Vector3d> result;
  for (size_t i = 0; i < anchors_.size(); ++i)
    result.push_back(anchors_[i] + weights_[i] * offset_);
  return result;
}

}  // namespace sculpt
