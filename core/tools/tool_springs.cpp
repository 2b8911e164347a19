#include "tools/tool_springs.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>

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
  return kPullStiffnessPerCell * youngs * typicalCellSize(model);
}

double toolStiffness(const FemModel& model, double stiffness, const char* tool) {
  if (!std::isfinite(stiffness))
    throw std::invalid_argument(std::string(tool) + ": the spring stiffness is not finite.");
  return stiffness > 0 ? stiffness : defaultPullStiffness(model);
}

std::vector<Eigen::Vector3d> currentPositions(Simulator& simulator,
                                              const std::vector<MaterialPoint>& points) {
  Points nodes;
  simulator.model().nodesFromControl(simulator.positions(), nodes);
  std::vector<Eigen::Vector3d> result;
  result.reserve(points.size());
  for (const MaterialPoint& p : points)
    result.push_back(materialPointPosition(simulator.model().mesh(), nodes, p));
  return result;
}

ToolSprings::~ToolSprings() {
  release(ReleaseMode::LetGo);
  clearKept();
}

PenaltySpringForm& ToolSprings::add(const MaterialPoint& point, const Eigen::Vector3d& target,
                                    double stiffness) {
  auto spring = std::make_unique<PenaltySpringForm>(simulator_.model(), point, target, stiffness);
  held_.push_back(static_cast<PenaltySpringForm*>(simulator_.addLoad(std::move(spring))));
  return *held_.back();
}

void ToolSprings::release(ReleaseMode mode) {
  for (PenaltySpringForm* spring : held_) {
    if (mode == ReleaseMode::Keep) {
      spring->setTarget(spring->position(simulator_.positions()));
      kept_.push_back(spring);
    } else {
      simulator_.removeLoad(spring);
    }
  }
  held_.clear();
}

void ToolSprings::clearKept() {
  for (const Form* form : kept_) simulator_.removeLoad(form);
  kept_.clear();
}

}  // namespace sculpt
