#include "tools/tool.h"

#include <limits>
#include <stdexcept>
#include <string>

#include "tools/tool_springs.h"

namespace sculpt {

Eigen::Vector3d ToolContext::symmetryCentre() {
  const Points& rest = model().restControl();
  return 0.5 * (rest.colwise().minCoeff() + rest.colwise().maxCoeff()).transpose();
}

Eigen::Vector3d restPointOf(ToolContext& context, const ToolInput& input, const char* tool) {
  if (input.restPoint) {
    if (!input.restPoint->allFinite())
      throw std::invalid_argument(std::string(tool) + ": the position is not finite.");
    return *input.restPoint;
  }
  if (!input.position.allFinite())
    throw std::invalid_argument(std::string(tool) + ": the position is not finite.");
  if (const std::optional<Eigen::Vector3d> rest = context.restPointAt(input.position)) return *rest;
  throw std::invalid_argument(std::string(tool) + ": there is no material there.");
}

const MaterialPointLocator& SimulatorToolContext::locator() {
  if (!locator_) locator_.emplace(simulator_.model().mesh());
  return *locator_;
}

std::optional<Eigen::Vector3d> SimulatorToolContext::restPointAt(const Eigen::Vector3d& world) {
  // The FEM node nearest to `world` in the current state names the material: exact at nodes,
  // within half a node spacing elsewhere, which is what a brush centre needs.
  if (!world.allFinite()) return std::nullopt;
  FemModel& model = simulator_.model();
  Points nodes;
  model.nodesFromControl(simulator_.positions(), nodes);
  if (nodes.rows() == 0) return std::nullopt;
  Eigen::Index nearest = 0;
  const double distanceSquared =
      (nodes.rowwise() - world.transpose()).rowwise().squaredNorm().minCoeff(&nearest);
  const double reach = typicalCellSize(model);
  if (distanceSquared > reach * reach) return std::nullopt;
  return model.mesh().restNodes.row(nearest).transpose();
}

}  // namespace sculpt
