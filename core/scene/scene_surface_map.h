#pragma once
// How a scene's drawn state follows from its control points, held apart from the running physics
// so that it can be used on any thread and outlive a rebuild: the level-K cell-mesh nodes (what
// SceneFrame::nodes holds and the Phong deformer takes) are the rest nodes plus the level-K
// vertex displacements S_K ... S_1 (p - p_rest), with the split cells' centre nodes as the mean
// of their vertices (embed/solid_cell_mesh.h). The running scene and the recorder both use it,
// so a recorded frame gives the nodes the window drew, bit for bit.

#include <cstdint>
#include <memory>

#include "scene/scene_builder.h"
#include "subdiv/stencil_table.h"

namespace sculpt {

class SceneSurfaceMap {
 public:
  /// `chain` is S_1 .. S_K of the scene's control mesh (Subdivision::chain).
  SceneSurfaceMap(std::shared_ptr<const SceneGeometry> geometry,
                  std::shared_ptr<const SceneSolid> solid, StencilChain chain);

  const SceneGeometry& geometry() const { return *geometry_; }
  const std::shared_ptr<const SceneGeometry>& sharedGeometry() const { return geometry_; }
  const SceneSolid& solid() const { return *solid_; }
  uint32_t numControlPoints() const { return static_cast<uint32_t>(geometry_->restControl.rows()); }

  /// The level-K vertex displacements for control points `control` (#control by 3).
  void vertexDisplacement(const Points& control, Points& displacement) const;
  /// Cell-mesh nodes from the level-K vertex displacements (the first rows are used).
  void cellNodesFromDisplacement(const Points& vertexDisplacement, Points& nodes) const;
  /// Both steps: the nodes for control points.
  void cellNodes(const Points& control, Points& nodes) const;

 private:
  std::shared_ptr<const SceneGeometry> geometry_;
  std::shared_ptr<const SceneSolid> solid_;
  StencilChain chain_;
};

}  // namespace sculpt
