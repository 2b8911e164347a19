#include "scene/scene_surface_map.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace sculpt {

SceneSurfaceMap::SceneSurfaceMap(std::shared_ptr<const SceneGeometry> geometry,
                                 std::shared_ptr<const SceneSolid> solid, StencilChain chain)
    : geometry_(std::move(geometry)), solid_(std::move(solid)), chain_(std::move(chain)) {
  if (chain_.numColumns() != geometry_->restControl.rows() ||
      chain_.numRows() < solid_->centres.numVertices)
    throw std::logic_error("the subdivision does not match the scene's control mesh");
}

void SceneSurfaceMap::vertexDisplacement(const Points& control, Points& displacement) const {
  if (control.rows() != geometry_->restControl.rows())
    throw std::invalid_argument("expected " + std::to_string(geometry_->restControl.rows()) +
                                " control points, got " + std::to_string(control.rows()));
  chain_.apply(control - geometry_->restControl, displacement);
}

void SceneSurfaceMap::cellNodesFromDisplacement(const Points& vertexDisplacement,
                                                Points& nodes) const {
  const uint32_t vertices = solid_->centres.numVertices;
  nodes = geometry_->cellMesh.positions +
          solid_->centres.nodePositions(vertexDisplacement.topRows(vertices));
}

void SceneSurfaceMap::cellNodes(const Points& control, Points& nodes) const {
  Points displacement;
  vertexDisplacement(control, displacement);
  cellNodesFromDisplacement(displacement, nodes);
}

}  // namespace sculpt
