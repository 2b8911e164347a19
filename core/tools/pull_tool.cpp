#include "tools/pull_tool.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <stdexcept>

namespace sculpt {

double typicalCellSize(const FemModel& model) {
  const FemMesh& mesh = model.mesh();
  const double volume = std::accumulate(mesh.gaussVolume.begin(), mesh.gaussVolume.end(), 0.0);
  if (mesh.numElements() == 0 || !(volume > 0)) return 1.0;
  return std::cbrt(volume / mesh.numElements());
}

double defaultPullStiffness(const FemModel& model) {
  double youngs = model.setup().material.youngs;
  for (const Material& m : model.mesh().gaussMaterial) youngs = std::max(youngs, m.youngs);
  return 10.0 * youngs * typicalCellSize(model);
}

PullTool::PullTool(Simulator& simulator) : simulator_(simulator) {}

PullTool::~PullTool() {
  release(ReleaseMode::LetGo);
  clearKept();
}

void PullTool::grab(const MaterialPoint& point, const Eigen::Vector3d& cursor, double stiffness,
                    bool push) {
  if (!cursor.allFinite()) throw std::invalid_argument("pull: the target is not finite.");
  if (!std::isfinite(stiffness))
    throw std::invalid_argument("pull: the spring stiffness is not finite.");
  release(ReleaseMode::LetGo);
  const double k = stiffness > 0 ? stiffness : defaultPullStiffness(simulator_.model());
  point_ = point;
  push_ = push;
  Points nodes;
  simulator_.model().nodesFromControl(simulator_.positions(), nodes);
  anchor_ = materialPointPosition(simulator_.model().mesh(), nodes, point);
  const Eigen::Vector3d goal = push ? Eigen::Vector3d(2.0 * anchor_ - cursor) : cursor;
  auto spring = std::make_unique<PenaltySpringForm>(simulator_.model(), point, goal, k);
  spring_ = static_cast<PenaltySpringForm*>(simulator_.addLoad(std::move(spring)));
}

void PullTool::moveTarget(const Eigen::Vector3d& cursor) {
  if (!spring_) return;
  spring_->setTarget(push_ ? Eigen::Vector3d(2.0 * anchor_ - cursor) : cursor);
}

void PullTool::release(ReleaseMode mode) {
  if (!spring_) return;
  if (mode == ReleaseMode::Keep) {
    spring_->setTarget(spring_->position(simulator_.positions()));
    kept_.push_back(spring_);
  } else {
    simulator_.removeLoad(spring_);
  }
  spring_ = nullptr;
}

void PullTool::clearKept() {
  for (const Form* form : kept_) simulator_.removeLoad(form);
  kept_.clear();
}

Eigen::Vector3d PullTool::pointPosition() const {
  return spring_ ? spring_->position(simulator_.positions()) : anchor_;
}

Eigen::Vector3d PullTool::target() const { return spring_ ? spring_->target() : anchor_; }

double PullTool::springForce() const {
  if (!spring_) return 0.0;
  return spring_->stiffness() * (spring_->position(simulator_.positions()) - spring_->target()).norm();
}

}  // namespace sculpt
