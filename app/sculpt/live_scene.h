#pragma once
// The window's scene: a detailed surface embedded in a simulated solid. The default is the
// Stanford bunny (Loop-refined for display) in a hexahedral cage built around it, simulated at
// level 1 under gravity with its bottom pinned, so that it moves at once.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "embed/deformation_gradients.h"
#include "embed/embedding.h"
#include "embed/solid_cell_mesh.h"
#include "sim/fem_model.h"
#include "sim/simulator.h"

namespace sculpt::app {

class LiveScene {
 public:
  /// Builds the default scene from assets/bunny.obj (`sourceDir` is the source tree). Throws on
  /// failure (std::runtime_error with a sentence).
  static std::unique_ptr<LiveScene> buildDefault(const std::string& sourceDir);

  /// Display surface at rest: positions, area-weighted normals, triangles (3 indices each).
  const Points& restPositions() const { return restPositions_; }
  const Points& restNormals() const { return restNormals_; }
  const std::vector<uint32_t>& triangles() const { return triangles_; }
  /// The level-K cells the surface is embedded in, and the embedding.
  const VolumeMesh& cellMesh() const { return solid_.mesh; }
  const Embedding& embedding() const { return embedding_; }

  /// Advances the simulation by one frame (1/60 s) and updates nodes and node gradients.
  StepReport step();
  const Points& nodes() const { return nodes_; }
  const std::vector<Eigen::Matrix3d>& nodeGradients() const { return gradients_; }
  uint32_t numElements() const;
  double lastStepMs() const { return lastStepMs_; }

 private:
  LiveScene() = default;
  void updateNodes();

  Points restPositions_, restNormals_;
  std::vector<uint32_t> triangles_;
  std::optional<FemModel> model_;
  std::unique_ptr<Simulator> simulator_;
  SolidCellMesh solid_;
  Embedding embedding_;
  NodeGradientStencil stencil_;
  Points femNodes_, nodes_;
  std::vector<Eigen::Matrix3d> gradients_;
  double lastStepMs_ = 0.0;
};

}  // namespace sculpt::app
