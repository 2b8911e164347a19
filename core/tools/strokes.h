#pragma once
// The product's tools on the Tool interface (tools/tool.h): each wraps the physical tool of its
// own header (pull_tool.h, inflate_tool.h, material_brush.h, pin_tool.h, curve_tool.h) and maps
// begin / update / end of a stroke onto it. Settings are fixed when the stroke is made.

#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "fem/material.h"
#include "tools/curve_tool.h"
#include "tools/inflate_tool.h"
#include "tools/material_brush.h"
#include "tools/pull_tool.h"
#include "tools/tool.h"

namespace sculpt {

/// Whether a brush that last acted at rest point `last` acts again with the input over `now`:
/// once it has moved `spacing` of its `radius` (paint dabs, inflate re-presses).
inline bool brushMoved(const Eigen::Vector3d& last, const Eigen::Vector3d& now, double spacing,
                       double radius) {
  return (now - last).norm() >= spacing * radius;
}

/// Pull (push with kToolInvert): a spring from the material point under the input at begin to
/// the input's position.
class PullStroke : public Tool {
 public:
  struct Settings {
    double stiffness = 0.0;  ///< N/m; <= 0: defaultPullStiffness
    bool keep = false;       ///< release keeps the spring where the point is (ReleaseMode::Keep)
    /// The material point, when the caller located it already (scripts do, to fail early).
    std::optional<MaterialPoint> point;
  };
  explicit PullStroke(Settings settings) : settings_(std::move(settings)) {}
  const char* name() const override { return "pull"; }
  void begin(ToolContext& context, const ToolInput& input) override;
  void update(ToolContext& context, const ToolInput& input) override;
  void end(ToolContext& context, const ToolInput& input) override;
  void clear() override;
  bool holdsLoads() const override;
  void springs(const Simulator& simulator, std::vector<ToolSpring>& out) const override;
  const PullTool* pull() const { return pull_.get(); }

 private:
  Settings settings_;
  std::unique_ptr<PullTool> pull_;
};

/// Inflate (deflate with kToolInvert): pressure on the boundary inside a rest sphere around the
/// material under the input while the stroke lasts; stylus pressure scales it.
class InflateStroke : public Tool {
 public:
  struct Settings {
    double radius = std::numeric_limits<double>::infinity();  ///< m (rest); infinity: all
    double pressure = 0.0;  ///< Pa at input pressure 1; negative deflates
    /// The pressed faces follow the input once it has moved this fraction of the radius.
    double respacing = 0.25;
  };
  explicit InflateStroke(Settings settings) : settings_(settings) {}
  const char* name() const override { return "inflate"; }
  void begin(ToolContext& context, const ToolInput& input) override;
  void update(ToolContext& context, const ToolInput& input) override;
  void end(ToolContext& context, const ToolInput& input) override;
  void clear() override;
  bool holdsLoads() const override { return inflate_ && inflate_->active(); }
  const InflateTool* inflate() const { return inflate_.get(); }

 private:
  double pressureOf(const ToolInput& input) const;
  Settings settings_;
  std::unique_ptr<InflateTool> inflate_;
  Eigen::Vector3d centre_ = Eigen::Vector3d::Zero();
  double pressure_ = 0.0;
};

/// Material paint: a dab of the brush at begin and every time the input has moved a quarter of
/// the radius. An edit of the user's work.
class PaintStroke : public Tool {
 public:
  struct Settings {
    MaterialBrushSettings brush;  ///< radius in rest metres
    /// Mirror planes through this point; none: the scene's symmetry centre.
    std::optional<Eigen::Vector3d> mirrorCentre;
    double spacing = 0.25;  ///< of the radius, between dabs
  };
  explicit PaintStroke(Settings settings) : settings_(std::move(settings)) {}
  const char* name() const override { return "paint"; }
  void begin(ToolContext& context, const ToolInput& input) override;
  void update(ToolContext& context, const ToolInput& input) override;
  ToolEdit edits() const override { return ToolEdit::Materials; }
  long samplesPainted() const { return painted_; }

 private:
  void dab(ToolContext& context, const Eigen::Vector3d& rest);
  Settings settings_;
  Eigen::Vector3d last_ = Eigen::Vector3d::Zero();
  long painted_ = 0;
};

/// Pin (unpin with kToolInvert) the control points in a rest sphere around the material under
/// the input, at begin and as it moves; or, with a box, the points in it once. An edit.
class PinStroke : public Tool {
 public:
  struct Settings {
    double radius = 0.0;                     ///< m (rest)
    std::optional<Eigen::AlignedBox3d> box;  ///< instead of the sphere (scripts)
  };
  explicit PinStroke(Settings settings) : settings_(settings) {}
  const char* name() const override { return "pin"; }
  void begin(ToolContext& context, const ToolInput& input) override;
  void update(ToolContext& context, const ToolInput& input) override;
  ToolEdit edits() const override { return ToolEdit::Pins; }
  uint32_t pointsTouched() const { return touched_; }

 private:
  Settings settings_;
  uint32_t touched_ = 0;
};

/// Curve: grabs the material points along a rest polyline (curve_tool.h) at begin and drags
/// them by the input's travel since begin.
class CurveStroke : public Tool {
 public:
  struct Settings {
    std::vector<Eigen::Vector3d> polyline;  ///< rest positions
    CurveProfile profile = CurveProfile::Rigid;
    double stiffness = 0.0;  ///< N/m for the whole curve; <= 0: defaultPullStiffness
    size_t samples = 0;      ///< 0: defaultCurveSamples
    bool keep = false;
    /// Already sampled (scripts sample when they are loaded, to fail early); else the polyline.
    std::vector<CurveSample> sampled;
    /// The drag offset is input position minus this; none: minus the position at begin.
    std::optional<Eigen::Vector3d> dragOrigin;
  };
  explicit CurveStroke(Settings settings) : settings_(std::move(settings)) {}
  const char* name() const override { return "curve"; }
  void begin(ToolContext& context, const ToolInput& input) override;
  void update(ToolContext& context, const ToolInput& input) override;
  void end(ToolContext& context, const ToolInput& input) override;
  void clear() override;
  bool holdsLoads() const override;
  void springs(const Simulator& simulator, std::vector<ToolSpring>& out) const override;
  const CurveTool* curve() const { return curve_.get(); }

 private:
  Settings settings_;
  std::unique_ptr<CurveTool> curve_;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
};

/// The eyedropper: reads the material of the sample nearest the material under the input. The
/// result is read on another thread (the window's), hence the shared, locked slot.
class Eyedropper : public Tool {
 public:
  class Result {
   public:
    std::optional<Material> take();
    void set(const Material& material);

   private:
    std::mutex mutex_;
    std::optional<Material> material_;
  };
  explicit Eyedropper(std::shared_ptr<Result> result) : result_(std::move(result)) {}
  const char* name() const override { return "eyedropper"; }
  void begin(ToolContext& context, const ToolInput& input) override;

 private:
  std::shared_ptr<Result> result_;
};

}  // namespace sculpt
