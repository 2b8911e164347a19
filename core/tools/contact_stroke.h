#pragma once
// Contact with the deformed surface, as a stylus feels it: while the input is inside the surface,
// a zero-length spring pushes the surface point nearest the input towards the input (a
// frictionless penalty contact: the point is found again at every update, so the contact slides
// along the surface as the stylus strokes it). Outside the solid nothing acts. The spring's
// stiffness follows the painted Young's modulus at the contact, through a mapping the caller
// chooses (a haptic device maps it into its stable range), so a stiffer region both yields less
// and pushes back harder. With a paint brush set, the held button paints where the stylus
// touches.
//
// The spring it reports (springs()) carries the surface normal, which marks it one-sided for a
// reader of the probe: it acts only while (target - point) . normal < 0.

#include <functional>
#include <memory>
#include <optional>

#include "tools/deformed_boundary.h"
#include "tools/pull_tool.h"
#include "tools/strokes.h"
#include "tools/tool.h"

namespace sculpt {

class ContactStroke : public Tool {
 public:
  struct Settings {
    /// Spring stiffness (N/m) for the Young's modulus (Pa) at the contact; empty: the default
    /// pull stiffness whatever the material.
    std::function<double(double youngs)> stiffnessForYoungs;
    /// Paints with this brush where the stylus touches while button 0 is held; none: no paint.
    std::optional<PaintStroke::Settings> paint;
    /// The surface to touch, embedded in the solid (rest vertices, three indices per triangle;
    /// the scene's detail surface); none: the solid's own boundary.
    std::shared_ptr<const Points> surfaceVertices;
    std::shared_ptr<const std::vector<uint32_t>> surfaceTriangles;
  };
  explicit ContactStroke(Settings settings) : settings_(std::move(settings)) {}
  const char* name() const override { return "probe"; }
  void begin(ToolContext& context, const ToolInput& input) override;
  void update(ToolContext& context, const ToolInput& input) override;
  void end(ToolContext& context, const ToolInput& input) override;
  void clear() override;
  bool holdsLoads() const override { return pull_ && pull_->active(); }
  void springs(const Simulator& simulator, std::vector<ToolSpring>& out) const override;
  ToolEdit edits() const override { return settings_.paint ? ToolEdit::Materials : ToolEdit::None; }

  bool inContact() const { return holdsLoads(); }
  /// Young's modulus at the contact (Pa; 0 without contact).
  double contactYoungs() const { return youngs_; }
  long samplesPainted() const { return paint_ ? paint_->samplesPainted() : 0; }

 private:
  Settings settings_;
  std::unique_ptr<DeformedBoundary> boundary_;
  std::unique_ptr<PullTool> pull_;
  std::unique_ptr<PaintStroke> paint_;
  bool painting_ = false;
  Eigen::Vector3d normal_ = Eigen::Vector3d::Zero();
  double youngs_ = 0.0;
};

}  // namespace sculpt
