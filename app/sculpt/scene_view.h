#pragma once
// The GPU side of a scene: the embedded surface (Phong-deformed in the vertex shader), the
// control mesh, the level-K cells coloured by element type, the clipping-plane slice with its
// field, the ground grid and the axes. Fed by SceneController: setGeometry() once per build,
// setFrame() with each new simulation state (O(nodes) upload; O(cells) when a cell field shows).

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <span>

#include "embed/node_field.h"
#include "render/line_renderer.h"
#include "render/overlay_geometry.h"
#include "render/phong_gpu_deformer.h"
#include "render/slice_renderer.h"
#include "scene/scene_controller.h"
#include "sculpt/display_settings.h"

namespace sculpt::app {

struct FieldRange {
  float low = 0.0f, high = 1.0f;
};

/// Whether the surface may be drawn without its back faces (render::SurfaceStyle::cullBackFaces)
/// and look the same: it is closed and faces out at rest (SceneGeometry::closedOutward) and the
/// solid is nowhere turned inside out (every node's deformation gradient has a positive
/// determinant: where one has not, the surface there faces in, and would show as a hole), the
/// clipping plane does not open it, and the box `low`..`high` around it lies wholly beyond the
/// near plane of `viewProjection`, so that the eye is outside and the near plane does not cut it.
bool cullsBackFaces(bool closedOutward, std::span<const Eigen::Matrix3d> nodeGradients,
                    const DisplaySettings& display, const glm::mat4& viewProjection,
                    const glm::vec3& low, const glm::vec3& high);

class SceneView {
 public:
  SceneView() = default;
  /// Replaces the scene drawn (rebuilds the static GPU data). Needs a current GL context.
  void setGeometry(std::shared_ptr<const SceneGeometry> geometry);
  bool hasGeometry() const { return geometry_ != nullptr; }
  const SceneGeometry* geometry() const { return geometry_.get(); }
  const std::shared_ptr<const SceneGeometry>& sharedGeometry() const { return geometry_; }

  /// Takes a new simulation state and uploads what `display` needs of it.
  void setFrame(const SceneFrame& frame, const DisplaySettings& display);
  const SceneFrame& frame() const { return frame_; }

  /// Draws with the current frame; `range` maps the field to the colour map.
  void draw(const glm::mat4& view, const glm::mat4& projection, const DisplaySettings& display,
            FieldRange range);

  /// The field's minimum and maximum in the current frame (for the automatic colour range).
  FieldRange fieldRange(FieldKind field) const;
  /// Rest bounding sphere of the embedded surface.
  glm::vec3 centre() const { return centre_; }
  float radius() const { return radius_; }
  /// Rest bounding box (clipping plane positions are fractions of it).
  glm::vec3 boxLow() const { return boxLow_; }
  glm::vec3 boxHigh() const { return boxHigh_; }
  /// Bytes uploaded for the deformation by the last setFrame (node positions and gradients).
  size_t lastUploadBytes() const { return deformer_ ? deformer_->frameUploadBytes() : 0; }
  double lastUploadMs() const { return lastUploadMs_; }
  /// Wall time of the last reconstruction of node values from a cell field (smooth fields).
  double lastNodeFieldMs() const { return lastNodeFieldMs_; }
  /// How many times node values were reconstructed (once per change of the cell values shown).
  uint64_t nodeFieldReconstructions() const { return nodeFieldReconstructions_; }
  /// The node values of the cell field last shown smoothly (embed/node_field.h).
  const std::vector<float>& nodeField() const { return nodeField_; }
  /// Triangles of the embedded surface.
  size_t numTriangles() const { return geometry_ ? geometry_->triangles.size() / 3 : 0; }
  /// The deformer, for measurements (draw ratio) and tests.
  render::PhongGpuDeformer* deformer() { return deformer_.get(); }
  const render::PhongGpuDeformer* deformer() const { return deformer_.get(); }

 private:
  void uploadDeformation(const DisplaySettings& display);
  glm::vec4 clipPlane(const DisplaySettings& display) const;
  std::vector<double> cellValues(FieldKind field) const;
  /// Uploads what `display` needs of the current frame (method, cell field).
  void upload(const DisplaySettings& display);
  /// The field shown: per cell, or per node from the cells when `display` draws it smoothly.
  void uploadField(const DisplaySettings& display);

  std::shared_ptr<const SceneGeometry> geometry_;
  SceneFrame frame_;
  std::vector<double> displacements_;  ///< per node |x - X| of frame_
  std::unique_ptr<render::PhongGpuDeformer> deformer_;
  render::LineRenderer grid_, axes_, controlMesh_, cells_, springs_;
  render::SliceRenderer slice_;
  std::vector<render::CellEdge> cellEdges_;  ///< level-K cell edges by element kind, per geometry
  InterpolationMethod uploadedMethod_ = InterpolationMethod::Phong;
  GradientScheme uploadedGradients_ = kDefaultGradientScheme;
  /// The frame's node gradients by the displayed scheme, where it is not the frame's own.
  std::vector<Eigen::Matrix3d> schemeGradients_;
  FieldKind uploadedField_ = FieldKind::None;
  bool uploadedSmooth_ = true;
  /// Cell field -> node values (per geometry), the last values reconstructed and their source.
  CompressedRows<NodeFieldWeight> nodeFieldWeights_;
  std::vector<float> nodeField_, nodeFieldSource_;
  bool nodeFieldCurrent_ = false;  ///< the deformer holds nodeField_
  bool showsNodeField_ = false;    ///< nodeField_ is the field shown (smooth)
  double lastNodeFieldMs_ = 0.0;
  uint64_t nodeFieldReconstructions_ = 0;
  glm::vec3 centre_{0.0f}, boxLow_{0.0f}, boxHigh_{0.0f};
  float radius_ = 1.0f;
  double lastUploadMs_ = 0.0;
};

}  // namespace sculpt::app
