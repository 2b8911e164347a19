#include "sculpt/scene_view.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "embed/attribute_transfer.h"
#include "embed/embedded_deformer.h"
#include "embed/node_field.h"
#include "mesh/plane_slice.h"
#include "render/overlay_geometry.h"

namespace sculpt::app {
namespace {

std::vector<float> floats(const Points& points) {
  std::vector<float> out;
  out.reserve(static_cast<size_t>(points.size()));
  for (Eigen::Index r = 0; r < points.rows(); ++r)
    for (int d = 0; d < 3; ++d) out.push_back(static_cast<float>(points(r, d)));
  return out;
}

const std::vector<float>* cellField(const SceneFrame& frame, FieldKind field) {
  switch (field) {
    case FieldKind::YoungsModulus: return &frame.cellYoungs;
    case FieldKind::Density: return &frame.cellDensity;
    case FieldKind::StrainEnergy: return &frame.cellStrainEnergy;
    case FieldKind::Damping: return &frame.cellDamping;
    default: return nullptr;
  }
}

// How far the deformed surface may reach out of its cells' nodes' box, as a fraction of the
// box's diagonal (Phong deformation bends it between the nodes).
constexpr float kSurfaceBulge = 0.05f;
const glm::vec3 kControlColour(0.95f, 0.85f, 0.30f);
const glm::vec3 kPinnedColour(0.90f, 0.25f, 0.25f);
const glm::vec3 kSpringColour(1.00f, 0.35f, 0.20f);

}  // namespace

void SceneView::setGeometry(std::shared_ptr<const SceneGeometry> geometry) {
  geometry_ = std::move(geometry);
  const SceneGeometry& g = *geometry_;
  std::vector<float> local;
  local.reserve(3 * static_cast<size_t>(g.embedding.numPoints()));
  for (uint32_t p = 0; p < g.embedding.numPoints(); ++p)
    for (int d = 0; d < 3; ++d) local.push_back(static_cast<float>(g.embedding.local(p, d)));
  deformer_ = std::make_unique<render::PhongGpuDeformer>(g.cellMesh, g.embedding.cells, local,
                                                         floats(g.restNormals));
  deformer_->setTriangles(g.triangles);
  nodeFieldWeights_ = nodeFieldWeights(g.cellMesh);
  nodeFieldCurrent_ = false;

  const Eigen::Vector3d lo = g.restPositions.colwise().minCoeff().transpose();
  const Eigen::Vector3d hi = g.restPositions.colwise().maxCoeff().transpose();
  boxLow_ = glm::vec3(lo.x(), lo.y(), lo.z());
  boxHigh_ = glm::vec3(hi.x(), hi.y(), hi.z());
  centre_ = 0.5f * (boxLow_ + boxHigh_);
  radius_ = std::max(0.5f * glm::length(boxHigh_ - boxLow_), 1e-6f);

  // The ground grid under the model and the axes at its lowest back corner.
  const float spacing = std::pow(10.0f, std::floor(std::log10(radius_ * 0.5f)));
  const render::LineList grid =
      render::groundGrid(glm::vec3(centre_.x, boxLow_.y, centre_.z), 2.0f * radius_, spacing);
  grid_.setLines(grid.xyz, grid.rgb);
  const render::LineList axes = render::axes(boxLow_, 0.4f * radius_);
  axes_.setLines(axes.xyz, axes.rgb);

  cellEdges_ = render::distinctCellEdges(g.cellMesh, g.cellKind);

  // Until the first simulated state: the rest shape.
  setFrame(restFrame(g, defaultSceneMaterial()), DisplaySettings{});
}

void SceneView::uploadDeformation(const DisplaySettings& display) {
  const auto start = std::chrono::steady_clock::now();
  InterpolationMethod method = display.method;
  if (method == InterpolationMethod::Attribute && !deformer_->hasAttributeNeighbours()) {
    const SceneGeometry& g = *geometry_;
    deformer_->setAttributeNeighbours(attributeTransferWeights(
        g.cellMesh.positions, g.restPositions, defaultAttributeRadius(meanEdgeLength(g.cellMesh))));
  }
  // The frame carries gradients by the default scheme; another one is applied here, O(nodes).
  const std::vector<Eigen::Matrix3d>* gradients = &frame_.gradients;
  if (display.gradients != kDefaultGradientScheme &&
      frame_.nodes.rows() == geometry_->cellMesh.positions.rows()) {
    applyNodeGradientStencil(geometry_->gradientStencil(display.gradients), frame_.nodes,
                             schemeGradients_);
    gradients = &schemeGradients_;
  }
  deformer_->setFrame(frame_.nodes, *gradients, method);
  uploadedMethod_ = method;
  uploadedGradients_ = display.gradients;
  lastUploadMs_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void SceneView::setFrame(const SceneFrame& frame, const DisplaySettings& display) {
  if (!geometry_) return;
  frame_ = frame;
  // Node displacements serve the colour range and the slice: once per frame.
  displacements_.clear();
  if (frame_.nodes.rows() == geometry_->cellMesh.positions.rows()) {
    displacements_.resize(static_cast<size_t>(frame_.nodes.rows()));
    for (Eigen::Index i = 0; i < frame_.nodes.rows(); ++i)
      displacements_[static_cast<size_t>(i)] =
          (frame_.nodes.row(i) - geometry_->cellMesh.positions.row(i)).norm();
  }
  upload(display);
}

void SceneView::upload(const DisplaySettings& display) {
  uploadDeformation(display);
  uploadField(display);
}

void SceneView::uploadField(const DisplaySettings& display) {
  uploadedField_ = display.field;
  uploadedSmooth_ = display.smoothField;
  showsNodeField_ = false;
  const std::vector<float>* values = cellField(frame_, display.field);
  if (!values || values->size() != geometry_->cellMesh.numCells()) return;
  if (!display.smoothField) {
    deformer_->setCellField(*values);
    return;
  }
  showsNodeField_ = true;
  // Node values again only when the cell values changed: painted materials stay the same for
  // many frames, the strain energy changes with every step (O(cells) either way).
  if (nodeFieldCurrent_ && *values == nodeFieldSource_) return;
  const auto start = std::chrono::steady_clock::now();
  nodeFieldFromCells(nodeFieldWeights_, *values, nodeField_);
  lastNodeFieldMs_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  nodeFieldSource_ = *values;
  nodeFieldCurrent_ = true;
  ++nodeFieldReconstructions_;
  deformer_->setNodeField(nodeField_);
}

FieldRange SceneView::fieldRange(FieldKind field) const {
  FieldRange range;
  if (field == FieldKind::Displacement) {
    const std::vector<double>& d = displacements_;
    range.low = 0.0f;
    range.high = d.empty() ? 0.0f : static_cast<float>(*std::max_element(d.begin(), d.end()));
  } else if (const std::vector<float>* values = cellField(frame_, field);
             values && !values->empty()) {
    const auto [lo, hi] = std::minmax_element(values->begin(), values->end());
    range.low = *lo, range.high = *hi;
  }
  if (!(range.high > range.low)) {  // a uniform field: centre it in the map
    const float pad = std::max(std::abs(range.low) * 0.05f, 1e-12f);
    range.low -= pad, range.high += pad;
  }
  return range;
}

std::vector<double> SceneView::cellValues(FieldKind field) const {
  const std::vector<float>* values = cellField(frame_, field);
  if (!values || values->size() != geometry_->cellMesh.numCells()) return {};
  return std::vector<double>(values->begin(), values->end());
}

glm::vec4 SceneView::clipPlane(const DisplaySettings& display) const {
  glm::vec3 normal(0.0f);
  normal[display.clipAxis] = 1.0f;
  const float offset =
      boxLow_[display.clipAxis] +
      display.clipPosition * (boxHigh_[display.clipAxis] - boxLow_[display.clipAxis]);
  return glm::vec4(normal, offset);
}

bool cullsBackFaces(bool closedOutward, std::span<const Eigen::Matrix3d> nodeGradients,
                    const DisplaySettings& display, const glm::mat4& viewProjection,
                    const glm::vec3& low, const glm::vec3& high) {
  if (!closedOutward || display.clip) return false;
  for (const Eigen::Matrix3d& gradient : nodeGradients)
    if (!(gradient.determinant() > 0.0)) return false;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec4 clip = viewProjection * glm::vec4(corner & 1 ? high.x : low.x,
                                                      corner & 2 ? high.y : low.y,
                                                      corner & 4 ? high.z : low.z, 1.0f);
    if (!(clip.w > 0.0f && clip.z > -clip.w)) return false;  // behind the eye or the near plane
  }
  return true;
}

void SceneView::draw(const glm::mat4& view, const glm::mat4& projection,
                     const DisplaySettings& display, FieldRange range) {
  if (!geometry_) return;
  const SceneGeometry& g = *geometry_;
  if (display.method != uploadedMethod_ || display.gradients != uploadedGradients_ ||
      display.field != uploadedField_ || display.smoothField != uploadedSmooth_)
    upload(display);
  if (display.showGrid) grid_.draw(view, projection, 1.0f);
  if (display.showAxes) axes_.draw(view, projection, 1.0f);

  const glm::vec4 plane = clipPlane(display);
  if (display.showSurface) {
    render::SurfaceStyle style;
    style.flatShading = display.flatShading;
    style.wireframe = display.wireframe;
    style.field = display.field == FieldKind::None           ? render::SurfaceField::None
                  : display.field == FieldKind::Displacement ? render::SurfaceField::Displacement
                  : showsNodeField_                          ? render::SurfaceField::PerNode
                                                             : render::SurfaceField::PerCell;
    style.fieldLow = range.low, style.fieldHigh = range.high;
    style.clip = display.clip;
    style.clipPlane = plane;
    if (frame_.nodes.rows() > 0) {
      // Around the deformed surface: the cells' nodes, with room for the surface to bulge out
      // of their hull between them.
      const Eigen::RowVector3d lo = frame_.nodes.colwise().minCoeff();
      const Eigen::RowVector3d hi = frame_.nodes.colwise().maxCoeff();
      const glm::vec3 low(lo.x(), lo.y(), lo.z()), high(hi.x(), hi.y(), hi.z());
      const glm::vec3 room(kSurfaceBulge * glm::length(high - low));
      style.cullBackFaces = cullsBackFaces(g.closedOutward, frame_.gradients, display,
                                           projection * view, low - room, high + room);
    }
    deformer_->draw(view, projection, style);
  }
  if (display.clip) {
    // The cut through the deformed level-K cells, coloured by the field: smooth from the node
    // values as the surface is, or flat per cell.
    const Eigen::Vector3d normal(plane.x, plane.y, plane.z);
    const bool smooth = showsNodeField_;
    const std::vector<double> nodeValues =
        display.field == FieldKind::Displacement ? displacements_
        : smooth ? std::vector<double>(nodeField_.begin(), nodeField_.end())
                 : std::vector<double>{};
    const std::vector<double> perCell = smooth ? std::vector<double>{} : cellValues(display.field);
    const PlaneSlice slice =
        slicePlane(g.cellMesh, frame_.nodes, normal, plane.w, nodeValues, perCell);
    slice_.setSlice(slice);
    slice_.draw(view, projection, range.low, range.high);
  }
  if (display.showCells) {
    const render::LineList edges = render::edgeLines(cellEdges_, frame_.nodes);
    cells_.setLines(edges.xyz, edges.rgb);
    cells_.draw(view, projection, 1.0f);
  }
  if (!frame_.springs.empty()) {  // pull springs: from the material point to its target
    render::LineList springs;
    std::vector<float> ends, endColours;
    for (const ToolSpring& spring : frame_.springs) {
      const Eigen::Vector3d& point = spring.point;
      const Eigen::Vector3d& target = spring.target;
      const glm::vec3 a(point.x(), point.y(), point.z()), b(target.x(), target.y(), target.z());
      springs.addSegment(a, b, kSpringColour);
      ends.insert(ends.end(), {a.x, a.y, a.z, b.x, b.y, b.z});
      endColours.insert(endColours.end(), {kSpringColour.x, kSpringColour.y, kSpringColour.z,
                                           kSpringColour.x, kSpringColour.y, kSpringColour.z});
    }
    springs_.setLines(springs.xyz, springs.rgb);
    springs_.setPoints(ends, endColours);
    glDisable(GL_DEPTH_TEST);  // the spring is a handle: always visible
    springs_.draw(view, projection, 8.0f);
    glEnable(GL_DEPTH_TEST);
  }
  if (display.showControlMesh && frame_.control.rows() == g.restControl.rows()) {
    const render::LineList edges = render::controlEdges(g.controlEdges, floats(frame_.control),
                                                        kControlColour);
    std::vector<float> pointColours;
    for (Eigen::Index i = 0; i < frame_.control.rows(); ++i) {
      const bool pinned =
          static_cast<size_t>(i) < g.pinned.size() && g.pinned[static_cast<size_t>(i)];
      const glm::vec3 c = pinned ? kPinnedColour : kControlColour;
      pointColours.insert(pointColours.end(), {c.x, c.y, c.z});
    }
    controlMesh_.setLines(edges.xyz, edges.rgb);
    controlMesh_.setPoints(floats(frame_.control), pointColours);
    glDisable(GL_DEPTH_TEST);  // the cage is mostly outside or around the surface: always show it
    controlMesh_.draw(view, projection, 6.0f);
    glEnable(GL_DEPTH_TEST);
  }
}

}  // namespace sculpt::app
