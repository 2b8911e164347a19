#include "tools/pull_tool.h"

#include <stdexcept>

namespace sculpt {

void PullTool::grab(const MaterialPoint& point, const Eigen::Vector3d& cursor, double stiffness,
                    bool push) {
  if (!cursor.allFinite()) throw std::invalid_argument("pull: the target is not finite.");
  const double k = toolStiffness(springs_.simulator().model(), stiffness, "pull");
  release(ReleaseMode::LetGo);
  push_ = push;
  anchor_ = currentPositions(springs_.simulator(), {point}).front();
  springs_.add(point, push ? Eigen::Vector3d(2.0 * anchor_ - cursor) : cursor, k);
}

void PullTool::moveTarget(const Eigen::Vector3d& cursor) {
  if (PenaltySpringForm* s = spring())
    s->setTarget(push_ ? Eigen::Vector3d(2.0 * anchor_ - cursor) : cursor);
}

void PullTool::release(ReleaseMode mode) { springs_.release(mode); }

void PullTool::clearKept() { springs_.clearKept(); }

Eigen::Vector3d PullTool::pointPosition() const {
  const PenaltySpringForm* s = spring();
  return s ? s->position(springs_.simulator().positions()) : anchor_;
}

Eigen::Vector3d PullTool::pointVelocity() const {
  const PenaltySpringForm* s = spring();
  return s ? s->position(springs_.simulator().velocities()) : Eigen::Vector3d::Zero();
}

double PullTool::stiffness() const {
  const PenaltySpringForm* s = spring();
  return s ? s->stiffness() : 0.0;
}

Eigen::Vector3d PullTool::target() const {
  const PenaltySpringForm* s = spring();
  return s ? s->target() : anchor_;
}

double PullTool::springForce() const {
  const PenaltySpringForm* s = spring();
  if (!s) return 0.0;
  return s->stiffness() * (s->position(springs_.simulator().positions()) - s->target()).norm();
}

ToolSpring PullTool::heldSpring() const {
  ToolSpring spring;
  spring.point = pointPosition();
  spring.velocity = pointVelocity();
  spring.target = target();
  spring.stiffness = stiffness();
  spring.force = springForce();
  return spring;
}

}  // namespace sculpt
