// SculptApp: the tools in the 3D view (tool_state.h): picking on the deformed surface and on the
// control mesh, the strokes of each tool and F / Shift+F brush dragging. What is drawn over the
// view for them is tool_overlay.cpp.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "edit/project_edit.h"
#include "edit/topology_operation.h"
#include "sculpt/point_conversions.h"
#include "sculpt/sculpt_app.h"

namespace sculpt::app {
namespace {

// Ray (origin, direction) against a triangle; the distance along the ray or nullopt.
std::optional<float> rayTriangle(const glm::vec3& origin, const glm::vec3& direction,
                                 const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::vec3 e1 = b - a, e2 = c - a, p = glm::cross(direction, e2);
  const float det = glm::dot(e1, p);
  if (std::abs(det) < 1e-12f) return std::nullopt;
  const glm::vec3 s = origin - a;
  const float u = glm::dot(s, p) / det;
  if (u < 0.0f || u > 1.0f) return std::nullopt;
  const glm::vec3 q = glm::cross(s, e1);
  const float v = glm::dot(direction, q) / det;
  if (v < 0.0f || u + v > 1.0f) return std::nullopt;
  const float t = glm::dot(e2, q) / det;
  return t > 0.0f ? std::optional<float>(t) : std::nullopt;
}

std::string paintLabel(PaintField field) {
  switch (field) {
    case PaintField::Youngs: return "Paint Young's modulus";
    case PaintField::Density: return "Paint density";
    case PaintField::Damping: return "Paint damping";
  }
  return "Paint";
}

}  // namespace

std::optional<SculptApp::SurfaceHit> SculptApp::surfaceHit(float x, float y, float depth, int width,
                                                           int height) {
  if (!view_.hasGeometry() || depth >= 1.0f) return std::nullopt;
  const std::optional<glm::vec3> hit = camera_.unproject(x, y, depth, width, height);
  if (!hit) return std::nullopt;
  // The material under the hit, found on the CPU in the deformed cells of the frame drawn.
  const SceneGeometry& geometry = *view_.geometry();
  const SceneFrame& frame = view_.frame();
  if (frame.nodes.rows() != geometry.cellMesh.positions.rows()) return std::nullopt;
  if (!picker_ || pickerFrame_ != frame.version || pickerScene_ != geometry.sceneId) {
    picker_ = std::make_unique<MaterialPicker>(geometry.cellMesh, frame.nodes);
    pickerFrame_ = frame.version;
    pickerScene_ = geometry.sceneId;
  }
  const Eigen::Vector3d world(hit->x, hit->y, hit->z);
  const Eigen::Vector3d extent =
      geometry.restControl.colwise().maxCoeff() - geometry.restControl.colwise().minCoeff();
  const std::optional<Eigen::Vector3d> rest = picker_->restPoint(world, 0.1 * extent.norm());
  if (!rest) return std::nullopt;
  return SurfaceHit{*hit, *rest};
}

double SculptApp::brushWorldRadius(float x, float y, float depth, int width, int height) const {
  const std::optional<glm::vec3> a = camera_.unproject(x, y, depth, width, height);
  const std::optional<glm::vec3> b =
      camera_.unproject(x + model_.tools.brush(strokeTool_).radiusPixels, y, depth, width, height);
  return a && b ? glm::distance(*a, *b) : 0.0;
}

Eigen::Vector3d SculptApp::mirrorCentre() const {
  const Points& control = view_.geometry()->restControl;
  return 0.5 * (control.colwise().minCoeff() + control.colwise().maxCoeff()).transpose();
}

void SculptApp::toolStroke(const PointerResult& stroke, float x, float y, int width, int height) {
  takeEyedropperResult();
  if (stroke.strokeBegan) {
    strokeTool_ = model_.tools.tool;
    strokeInverted_ = ImGui::GetIO().KeyCtrl;
  }
  if (stylus_.active()) {  // simulated device: the mouse moves the stylus' hand
    stylusStroke(stroke, x, y, width, height);
    return;
  }
  if (!stroke.strokeBegan && !stroke.strokeActive && !stroke.strokeEnded) return;
  switch (strokeTool_) {
    case ToolKind::Pull: pullStroke(stroke, x, y, width, height); break;
    case ToolKind::Inflate:
    case ToolKind::Paint:
    case ToolKind::Pin: brushStroke(stroke, x, y, width, height); break;
    case ToolKind::Curve: curveStroke(stroke, x, y, width, height); break;
    case ToolKind::Topology: topologyClick(stroke, x, y, width, height); break;
  }
}

ToolInput SculptApp::toolInput(const glm::vec3& world,
                               const std::optional<Eigen::Vector3d>& rest) const {
  ToolInput input;
  input.position = toEigen(world);
  input.restPoint = rest;
  if (strokeInverted_) input.modifiers |= kToolInvert;
  return input;
}

void SculptApp::endToolStroke() {
  if (stroke_ == 0) return;
  if (StrokeCapture* capture = recording_->capturing()) capture->end(recording_->takeTime());
  controller_->loop().endStroke(stroke_, ToolInput{});
  stroke_ = 0;
}

std::optional<SculptApp::CursorRay> SculptApp::cursorRay(float x, float y, int width,
                                                         int height) const {
  const std::optional<glm::vec3> near = camera_.unproject(x, y, 0.0f, width, height);
  const std::optional<glm::vec3> far = camera_.unproject(x, y, 0.999f, width, height);
  if (!near || !far) return std::nullopt;
  return CursorRay{*near, glm::normalize(*far - *near)};
}

void SculptApp::pullStroke(const PointerResult& stroke, float x, float y, int width, int height) {
  // A stroke that starts on the surface grabs the material point under the cursor with a spring;
  // the target then follows the cursor in the view plane at the grabbed depth (with Ctrl it is
  // reflected through the grabbed point: push).
  // The wheel moves the target along the ray through the cursor (depth by wheel).
  const std::optional<CursorRay> ray = cursorRay(x, y, width, height);
  if (!ray) return;
  const glm::vec3 &origin = ray->origin, &direction = ray->direction;
  if (stroke.strokeBegan) {
    if (const std::optional<SurfaceHit> hit = surfaceHit(x, y, cursorDepth_, width, height)) {
      PullStroke::Settings settings;
      settings.keep = model_.tools.keepOnRelease;
      stroke_ = controller_->loop().beginStroke(std::make_unique<PullStroke>(settings),
                                                toolInput(hit->world, hit->rest));
      grabDistance_ = glm::dot(hit->world - origin, direction);
      if (StrokeCapture* capture = recording_->capturing())
        capture->beginGrab(recording_->takeTime(), hit->rest, toEigen(hit->world), settings.keep);
    }
  } else if (stroke.strokeActive && stroke_ != 0) {
    const glm::vec3 target = origin + grabDistance_ * direction;
    controller_->loop().updateStroke(stroke_, toolInput(target, std::nullopt));
    if (StrokeCapture* capture = recording_->capturing())
      capture->move(recording_->takeTime(), toEigen(target), std::nullopt);
  }
  if (stroke.strokeEnded) endToolStroke();
}

void SculptApp::stylusStroke(const PointerResult& stroke, float x, float y, int width, int height) {
  // A press on the surface puts the hand there (a probe a little inside, so it touches); a drag
  // moves it in the view plane at that depth, as a pull drags; release lifts the button.
  const std::optional<CursorRay> ray = cursorRay(x, y, width, height);
  if (!ray) return;
  const glm::vec3 &origin = ray->origin, &direction = ray->direction;
  if (stroke.strokeBegan) {
    const std::optional<SurfaceHit> hit = surfaceHit(x, y, cursorDepth_, width, height);
    if (!hit) return;
    const float inside =
        stylus_.tool() == haptics::HapticTool::Pull ? 0.0f : 0.03f * view_.radius();
    grabDistance_ = glm::dot(hit->world - origin, direction) + inside;
    stylusHeld_ = true;
  }
  if (!stylusHeld_) return;
  const glm::vec3 at = origin + grabDistance_ * direction;
  stylus_.moveHand(toEigen(at), !stroke.strokeEnded);
  if (stroke.strokeEnded) stylusHeld_ = false;
}

void SculptApp::brushStroke(const PointerResult& stroke, float x, float y, int width, int height) {
  const ToolState& t = model_.tools;
  if (stroke.strokeBegan && strokeTool_ == ToolKind::Paint && strokeInverted_) {
    // Ctrl+click with the paint brush: the eyedropper reads the painted value under the cursor.
    strokeTool_ = ToolKind::Topology;  // the rest of this stroke does nothing
    const std::optional<SurfaceHit> hit = surfaceHit(x, y, cursorDepth_, width, height);
    if (!hit) return;
    eyedropper_ = std::make_shared<Eyedropper::Result>();
    const uint64_t id = controller_->loop().beginStroke(std::make_unique<Eyedropper>(eyedropper_),
                                                        toolInput(hit->world, hit->rest));
    controller_->loop().endStroke(id, ToolInput{});
    return;
  }
  const std::optional<SurfaceHit> hit =
      stroke.strokeBegan || stroke.strokeActive ? surfaceHit(x, y, cursorDepth_, width, height)
                                                : std::nullopt;
  if (hit) lastDabX_ = x, lastDabY_ = y;
  if (hit && stroke_ == 0 && (stroke.strokeBegan || stroke.strokeActive)) {
    // The stroke starts where the cursor first touches the surface.
    const double radius = brushWorldRadius(x, y, cursorDepth_, width, height);
    if (!(radius > 0.0)) return;
    std::unique_ptr<Tool> tool;
    StrokeCapture* capture = recording_->capturing();
    const double now = recording_->takeTime();
    if (strokeTool_ == ToolKind::Inflate) {
      const double pressure = t.pressureFraction * model_.settings.material.youngs;
      const InflateStroke::Settings settings{radius,
                                             pressure * t.brush(ToolKind::Inflate).strength};
      tool = std::make_unique<InflateStroke>(settings);
      if (capture)
        capture->beginInflate(now, hit->rest, settings,
                              (strokeInverted_ ? -1.0 : 1.0) * settings.pressure);
    } else if (strokeTool_ == ToolKind::Paint) {
      const PaintStroke::Settings settings{paintBrush(t, radius, mirrorCentre()), mirrorCentre()};
      tool = std::make_unique<PaintStroke>(settings);
      if (capture) capture->beginPaint(now, hit->rest, settings);
      pendingCapture_ = Capture::Materials;  // set now: undo waits for the stroke's entry
      pendingLabel_ = paintLabel(t.field);
    } else {
      tool = std::make_unique<PinStroke>(PinStroke::Settings{radius, std::nullopt});
      if (capture) capture->beginPin(now, hit->rest, radius, strokeInverted_);
      pendingCapture_ = Capture::Pins;
      pendingLabel_ = strokeInverted_ ? "Unpin" : "Pin";
    }
    stroke_ = controller_->loop().beginStroke(std::move(tool), toolInput(hit->world, hit->rest));
  } else if (hit && stroke_ != 0 && stroke.strokeActive) {
    controller_->loop().updateStroke(stroke_, toolInput(hit->world, hit->rest));
    if (StrokeCapture* capture = recording_->capturing())
      capture->move(recording_->takeTime(), toEigen(hit->world), hit->rest);
  }
  if (stroke.strokeEnded) {
    const bool began = stroke_ != 0;
    endToolStroke();
    if (began && (strokeTool_ == ToolKind::Paint || strokeTool_ == ToolKind::Pin) &&
        pendingCapture_ != Capture::None)
      controller_->loop().requestEdits();  // the stroke's undo entry is made when the state arrives
  }
}

void SculptApp::takeEyedropperResult() {
  if (!eyedropper_) return;
  const std::optional<Material> picked = eyedropper_->take();
  if (!picked) return;
  eyedropper_.reset();
  ToolState& tools = model_.tools;
  if (tools.field == PaintField::Youngs) tools.paint.youngs = picked->youngs;
  if (tools.field == PaintField::Density) tools.paint.density = picked->density;
  if (tools.field == PaintField::Damping) tools.paint.damping = picked->damping;
  char text[96];
  std::snprintf(text, sizeof text, "picked E %.3g Pa, density %.4g kg/m^3, damping %.3g",
                picked->youngs, picked->density, picked->damping);
  model_.toast(text);
}

void SculptApp::curveStroke(const PointerResult& stroke, float x, float y, int width, int height) {
  // Draw: a stroke on the surface records the curve. Shift+drag: drag the curve.
  if (stroke.strokeBegan) {
    if (ImGui::GetIO().KeyShift && !curveRest_.empty()) {
      curveDepth_ = cursorDepth_ < 1.0f
                        ? cursorDepth_
                        : camera_.project(curveWorld_[curveWorld_.size() / 2], width, height).z;
      const std::optional<glm::vec3> start = camera_.unproject(x, y, curveDepth_, width, height);
      if (!start) return;
      CurveStroke::Settings settings;
      settings.polyline = curveRest_;
      settings.profile = model_.tools.smoothCurve ? CurveProfile::Smooth : CurveProfile::Rigid;
      if (StrokeCapture* capture = recording_->capturing())
        capture->beginCurve(recording_->takeTime(), curveRest_, settings.profile, toEigen(*start));
      stroke_ = controller_->loop().beginStroke(std::make_unique<CurveStroke>(std::move(settings)),
                                                toolInput(*start, std::nullopt));
      curveGrabbed_ = true;
      return;
    }
    curveRest_.clear();
    curveWorld_.clear();
  }
  if (curveGrabbed_) {
    if (stroke.strokeActive && stroke_ != 0)
      if (const std::optional<glm::vec3> at = camera_.unproject(x, y, curveDepth_, width, height)) {
        controller_->loop().updateStroke(stroke_, toolInput(*at, std::nullopt));
        if (StrokeCapture* capture = recording_->capturing())
          capture->move(recording_->takeTime(), toEigen(*at), std::nullopt);
      }
    if (stroke.strokeEnded) {
      endToolStroke();
      curveGrabbed_ = false;
    }
    return;
  }
  if (stroke.strokeActive &&
      (curveWorld_.empty() || std::hypot(x - lastDabX_, y - lastDabY_) >= 6.0f))
    if (const std::optional<SurfaceHit> hit = surfaceHit(x, y, cursorDepth_, width, height)) {
      curveRest_.push_back(hit->rest);
      curveWorld_.push_back(hit->world);
      lastDabX_ = x, lastDabY_ = y;
    }
}

std::optional<SculptApp::PickedFace> SculptApp::pickFace(float x, float y, int width,
                                                         int height) const {
  if (!view_.hasGeometry() || !view_.geometry()->controlMesh) return std::nullopt;
  const std::optional<glm::vec3> near = camera_.unproject(x, y, 0.0f, width, height);
  const std::optional<glm::vec3> far = camera_.unproject(x, y, 0.999f, width, height);
  if (!near || !far) return std::nullopt;
  const glm::vec3 direction = glm::normalize(*far - *near);
  const CellComplex& mesh = *view_.geometry()->controlMesh;
  const Points& control = view_.frame().control.rows() == mesh.positions.rows()
                              ? view_.frame().control
                              : mesh.positions;
  std::optional<PickedFace> best;
  float bestT = std::numeric_limits<float>::max();
  for (const FaceRef& face : boundaryFacesOfScene_) {
    const std::span<const uint32_t> loop = mesh.cellFace(face.cell, face.face);
    for (size_t k = 1; k + 1 < loop.size(); ++k) {
      const std::optional<float> t =
          rayTriangle(*near, direction, pointRow(control, loop[0]), pointRow(control, loop[k]),
                      pointRow(control, loop[k + 1]));
      if (t && *t < bestT) {
        bestT = *t;
        best = PickedFace{face, std::vector<uint32_t>(loop.begin(), loop.end())};
      }
    }
  }
  return best;
}

void SculptApp::topologyClick(const PointerResult& stroke, float x, float y, int width,
                              int height) {
  if (!stroke.strokeBegan) return;
  const std::optional<PickedFace> picked = pickFace(x, y, width, height);
  if (!picked) {
    firstFace_.reset();
    return;
  }
  if (needsTwoFaces(model_.tools.operation)) {
    if (!firstFace_) {
      firstFace_ = picked;
      return;
    }
    const std::vector<FaceRef> faces{firstFace_->face, picked->face};
    firstFace_.reset();
    applyTopology(faces);
    return;
  }
  applyTopology({picked->face});
}

std::vector<FaceRef> SculptApp::withMirroredFaces(const std::vector<FaceRef>& faces) const {
  // docs/design/ux.md: symmetry applies to topology tools too, inside one undo step. The image of a
  // face is the boundary face whose centroid is the reflection of its centroid (when there is one).
  const ToolState& t = model_.tools;
  const CellComplex& mesh = document_.project().controlMesh;
  const auto centroid = [&mesh](const FaceRef& f) {
    const auto loop = mesh.cellFace(f.cell, f.face);
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (const uint32_t v : loop) c += mesh.positions.row(v).transpose();
    return Eigen::Vector3d(c / static_cast<double>(loop.size()));
  };
  const Eigen::Vector3d lo = mesh.positions.colwise().minCoeff(),
                        hi = mesh.positions.colwise().maxCoeff();
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  const double tolerance = 1e-6 * (hi - lo).norm();
  std::vector<FaceRef> result = faces;
  const bool axes[3] = {t.mirrorX, t.mirrorY, t.mirrorZ};
  for (int axis = 0; axis < 3; ++axis) {
    if (!axes[axis]) continue;
    const std::vector<FaceRef> current = result;
    for (const FaceRef& f : current) {
      Eigen::Vector3d image = centroid(f);
      image[axis] = 2.0 * centre[axis] - image[axis];
      for (const FaceRef& g : boundaryFacesOfScene_)
        if ((centroid(g) - image).norm() <= tolerance &&
            std::find(result.begin(), result.end(), g) == result.end()) {
          result.push_back(g);
          break;
        }
    }
  }
  return result;
}

void SculptApp::applyTopology(const std::vector<FaceRef>& picked) {
  const Project& project = document_.project();
  const CellComplex& mesh = project.controlMesh;
  const std::vector<FaceRef> faces =
      needsTwoFaces(model_.tools.operation) ? picked : withMirroredFaces(picked);
  TopologyOperation operation;
  operation.faces = faces;
  const std::span<const uint32_t> loop = mesh.cellFace(faces[0].cell, faces[0].face);
  double edge = 0.0;
  for (size_t k = 0; k < loop.size(); ++k)
    edge += (mesh.positions.row(loop[k]) - mesh.positions.row(loop[(k + 1) % loop.size()])).norm();
  edge /= static_cast<double>(loop.size());
  switch (model_.tools.operation) {
    case TopologyTool::Extrude:
      operation.op = TopologyOp::Extrude;
      operation.distanceM = model_.tools.extrudeCells * edge;
      break;
    case TopologyTool::Delete:
    case TopologyTool::Subdivide:
      operation.op = model_.tools.operation == TopologyTool::Delete ? TopologyOp::Delete
                                                                     : TopologyOp::Subdivide;
      for (const FaceRef& f : faces)
        if (std::find(operation.cells.begin(), operation.cells.end(), f.cell) ==
            operation.cells.end())
          operation.cells.push_back(f.cell);
      break;
    case TopologyTool::Bridge: operation.op = TopologyOp::Bridge; break;
    case TopologyTool::Weld:
      operation.op = TopologyOp::Weld;
      operation.toleranceM = 1e-3 * edge;
      break;
    case TopologyTool::Crease: {
      operation.op = TopologyOp::Crease;
      bool all = true;
      for (const FaceRef& f : faces) {
        const std::span<const uint32_t> edges = mesh.cellFace(f.cell, f.face);
        for (size_t k = 0; k < edges.size(); ++k) {
          std::array<uint32_t, 2> e{edges[k], edges[(k + 1) % edges.size()]};
          if (e[0] > e[1]) std::swap(e[0], e[1]);
          operation.edges.push_back(e);
          all = all && std::find(mesh.creases.begin(), mesh.creases.end(), e) != mesh.creases.end();
        }
      }
      operation.untag = all;  // a second click on a creased face removes the creases
      break;
    }
    case TopologyTool::Corner: {
      operation.op = TopologyOp::Corner;
      bool all = true;
      for (const FaceRef& f : faces)
        for (const uint32_t v : mesh.cellFace(f.cell, f.face)) {
          operation.vertices.push_back(v);
          all = all && std::find(mesh.corners.begin(), mesh.corners.end(), v) != mesh.corners.end();
        }
      operation.untag = all;
      break;
    }
  }
  try {
    const TopologyEdit edit = applyTopologyOperation(mesh, operation);
    Project after = project;
    applyTopologyEdit(after, edit);
    if (!document_.commit(edit.label, std::move(after))) return;
    model_.toast(edit.label);
  } catch (const std::exception& error) {
    model_.toast(error.what(), true, 8.0);
    return;
  }
  hoverFace_.reset();
  loadDocumentScene();
}

bool SculptApp::brushKeys(const ImGuiIO& io, float dx) {
  // F + drag sets the radius and Shift+F + drag the strength (docs/design/ux.md); F alone still
  // frames.
  ToolState& t = model_.tools;
  if (brushKey_ < 0) {
    if (!isBrushTool(t.tool) || !viewHasKeys_ || !ImGui::IsKeyPressed(GLFW_KEY_F, false) ||
        io.KeyCtrl || io.KeyAlt)
      return false;
    brushKey_ = GLFW_KEY_F;
    brushKeyDragged_ = false;
    brushKeyStrength_ = io.KeyShift;
    return true;
  }
  if (!ImGui::IsKeyDown(brushKey_)) {
    if (!brushKeyDragged_ && !brushKeyStrength_) runAction(Action::FrameModel);
    brushKey_ = -1;
    return false;
  }
  if (dx != 0.0f) {
    brushKeyDragged_ = true;
    const BrushRef brush = t.brush();
    if (brushKeyStrength_)
      brush.strength = std::clamp(brush.strength + dx / 300.0f, 0.0f, 1.0f);
    else
      brush.radiusPixels =
          std::clamp(brush.radiusPixels + dx, kMinBrushRadiusPixels, kMaxBrushRadiusPixels);
  }
  return true;
}

}  // namespace sculpt::app
