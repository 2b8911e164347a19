#include "tools/contact_stroke.h"

#include <cmath>

#include "tools/material_brush.h"
#include "tools/tool_springs.h"

namespace sculpt {

void ContactStroke::begin(ToolContext& context, const ToolInput& input) {
  if (!input.position.allFinite())
    throw std::invalid_argument("probe: the position is not finite.");
  if (settings_.surfaceVertices && settings_.surfaceTriangles)
    boundary_ = std::make_unique<DeformedBoundary>(context.model(), context.locator(),
                                                   *settings_.surfaceVertices,
                                                   *settings_.surfaceTriangles);
  else
    boundary_ = std::make_unique<DeformedBoundary>(context.model());
  pull_ = std::make_unique<PullTool>(context.simulator());
  update(context, input);
}

void ContactStroke::update(ToolContext& context, const ToolInput& input) {
  if (!boundary_ || !input.position.allFinite()) return;
  Simulator& simulator = context.simulator();
  Points nodes;
  simulator.model().nodesFromControl(simulator.positions(), nodes);
  const std::optional<BoundaryHit> hit = boundary_->nearest(nodes, input.position);
  const bool touching = hit && hit->signedDistance < 0;
  if (!touching) {
    if (pull_->active()) pull_->release(ReleaseMode::LetGo);
    youngs_ = 0.0;
    normal_.setZero();
    painting_ = false;
    return;
  }
  const Eigen::Vector3d rest = boundary_->restPoint(*hit);
  const std::optional<MaterialPoint> point = context.locator().locate(rest);
  if (!point) return;
  youngs_ = pickMaterial(context.model(), rest).youngs;
  double stiffness = settings_.stiffnessForYoungs ? settings_.stiffnessForYoungs(youngs_) : 0.0;
  if (!(std::isfinite(stiffness) && stiffness > 0))
    stiffness = defaultPullStiffness(context.model());
  pull_->grab(*point, input.position, stiffness);  // lets the previous contact point go
  normal_ = hit->normal;

  if (!settings_.paint || !(input.buttons & 1u)) {
    painting_ = false;
    return;
  }
  ToolInput at = input;
  at.restPoint = rest;
  if (!painting_) {
    if (!paint_) paint_ = std::make_unique<PaintStroke>(*settings_.paint);
    paint_->begin(context, at);
    painting_ = true;
  } else {
    paint_->update(context, at);
  }
}

void ContactStroke::end(ToolContext&, const ToolInput&) { clear(); }

void ContactStroke::clear() {
  if (pull_ && pull_->active()) pull_->release(ReleaseMode::LetGo);
  painting_ = false;
  youngs_ = 0.0;
}

void ContactStroke::springs(const Simulator&, std::vector<ToolSpring>& out) const {
  if (!holdsLoads()) return;
  ToolSpring spring = pull_->heldSpring();
  spring.normal = normal_;
  out.push_back(spring);
}

}  // namespace sculpt
