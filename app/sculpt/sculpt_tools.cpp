// SculptApp: the tools in the 3D view (tool_state.h): picking on the deformed surface and on the
// control mesh, the strokes of each tool, F / Shift+F brush dragging, and what is drawn over the
// view for them: each tool's cursor (brush circle with its falloff ring; pull's grab point and
// depth ring; curve's point), the mirror planes, the curve, the faces.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "edit/project_edit.h"
#include "edit/topology_operation.h"
#include "sculpt/overlay_label.h"
#include "sculpt/sculpt_app.h"

namespace sculpt::app {
namespace {

ImU32 colour(int r, int g, int b, int a = 255) { return IM_COL32(r, g, b, a); }

// The pull cursor in the pull spring's colour (scene_view.cpp), the curve's cursor in the curve's.
const ImU32 kPullColour = colour(255, 89, 51);
const ImU32 kCurveColour = colour(80, 220, 255);
// A faint dark edge under the cursors' strokes, so that they show on light surfaces too.
const ImU32 kCursorShadow = colour(0, 0, 0, 90);
// The pull cursor's ring: a disc of this fraction of the scene's radius in the view plane at the
// grabbed depth, so that its size on screen tells how deep the grab is.
constexpr float kPullRingFraction = 0.04f;

// Where the falloff weight is 1/2 (the inner ring), as a fraction of the radius.
float halfWeightFraction(Falloff falloff) {
  double lo = 0.0, hi = 1.0;
  for (int k = 0; k < 40; ++k) {
    const double mid = 0.5 * (lo + hi);
    (falloffWeight(falloff, mid, 1.0) > 0.5 ? lo : hi) = mid;
  }
  return static_cast<float>(lo);
}

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

Eigen::Vector3d toEigen(const glm::vec3& v) { return Eigen::Vector3d(v.x, v.y, v.z); }

glm::vec3 row(const Points& points, uint32_t i) {
  return glm::vec3(points(i, 0), points(i, 1), points(i, 2));
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
  const Eigen::Vector3d extent = geometry.restControl.colwise().maxCoeff() - geometry.restControl.colwise().minCoeff();
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

ToolInput SculptApp::toolInput(const glm::vec3& world, const std::optional<Eigen::Vector3d>& rest) const {
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
    const float inside = stylus_.tool() == haptics::HapticTool::Pull ? 0.0f : 0.03f * view_.radius();
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
  if (stroke.strokeActive && (curveWorld_.empty() || std::hypot(x - lastDabX_, y - lastDabY_) >= 6.0f))
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
      const std::optional<float> t = rayTriangle(*near, direction, row(control, loop[0]),
                                                 row(control, loop[k]), row(control, loop[k + 1]));
      if (t && *t < bestT) {
        bestT = *t;
        best = PickedFace{face, std::vector<uint32_t>(loop.begin(), loop.end())};
      }
    }
  }
  return best;
}

void SculptApp::topologyClick(const PointerResult& stroke, float x, float y, int width, int height) {
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
  // docs/design/ux.md: symmetry applies to topology tools too, inside one undo step. The image of a face is
  // the boundary face whose centroid is the reflection of its centroid (when there is one).
  const ToolState& t = model_.tools;
  const CellComplex& mesh = document_.project().controlMesh;
  const auto centroid = [&mesh](const FaceRef& f) {
    const auto loop = mesh.cellFace(f.cell, f.face);
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (const uint32_t v : loop) c += mesh.positions.row(v).transpose();
    return Eigen::Vector3d(c / static_cast<double>(loop.size()));
  };
  const Eigen::Vector3d lo = mesh.positions.colwise().minCoeff(), hi = mesh.positions.colwise().maxCoeff();
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
        if (std::find(operation.cells.begin(), operation.cells.end(), f.cell) == operation.cells.end())
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
  // F + drag sets the radius and Shift+F + drag the strength (docs/design/ux.md); F alone still frames.
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

void SculptApp::drawToolOverlay(const ViewRect& view) {
  if (!view_.hasGeometry()) return;
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  draw->PushClipRect(view.min, view.max, true);
  if (stylus_.active()) {
    stylus_.drawCursor(draw, camera_, view.min, view.max);
    draw->PopClipRect();
    return;
  }
  const int width = std::max(1, static_cast<int>(view.max.x - view.min.x));
  const int height = std::max(1, static_cast<int>(view.max.y - view.min.y));
  const auto screen = [&](const glm::vec3& world) {
    const glm::vec3 p = camera_.project(world, width, height);
    return ImVec2(view.min.x + p.x, view.min.y + p.y);
  };
  const ToolState& t = model_.tools;
  const BrushSettings brush = t.brush();
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const bool inView = mouse.x >= view.min.x && mouse.y >= view.min.y && mouse.x < view.max.x &&
                      mouse.y < view.max.y && !ImGui::GetIO().WantCaptureMouse;
  // The surface point under the cursor, from the depth read in the last frame; the ground grid
  // writes depth too, but lies outside the box of the control points (the solid lies inside
  // their hull).
  std::optional<glm::vec3> hovered =
      inView && cursorDepth_ < 1.0f ? camera_.unproject(mouse.x - view.min.x, mouse.y - view.min.y,
                                                        cursorDepth_, width, height)
                                    : std::nullopt;
  if (const Points& control = view_.frame().control; hovered && control.rows() > 0) {
    const Eigen::Vector3d slack = Eigen::Vector3d::Constant(0.01 * view_.radius());
    const Eigen::Vector3d lo = control.colwise().minCoeff().transpose() - slack;
    const Eigen::Vector3d hi = control.colwise().maxCoeff().transpose() + slack;
    const Eigen::Vector3d p = toEigen(*hovered);
    if ((p.array() < lo.array()).any() || (p.array() > hi.array()).any()) hovered.reset();
  }
  if ((t.tool == ToolKind::Paint || (t.tool == ToolKind::Topology && !needsTwoFaces(t.operation))) &&
      (t.mirrorX || t.mirrorY || t.mirrorZ)) {
    // The symmetry planes through the rest control box's centre, as the box's mid sections.
    const Points& control = view_.geometry()->restControl;
    const Eigen::Vector3d lo = control.colwise().minCoeff(), hi = control.colwise().maxCoeff();
    const Eigen::Vector3d c = mirrorCentre();
    const bool axes[3] = {t.mirrorX, t.mirrorY, t.mirrorZ};
    for (int axis = 0; axis < 3; ++axis) {
      if (!axes[axis]) continue;
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      ImVec2 corners[4];
      for (int k = 0; k < 4; ++k) {
        Eigen::Vector3d p = c;
        p[u] = (k == 1 || k == 2) ? hi[u] : lo[u];
        p[v] = k >= 2 ? hi[v] : lo[v];
        corners[k] = screen(glm::vec3(p.x(), p.y(), p.z()));
      }
      draw->AddQuadFilled(corners[0], corners[1], corners[2], corners[3], colour(230, 60, 60, 40));
      draw->AddQuad(corners[0], corners[1], corners[2], corners[3], colour(230, 60, 60, 160), 1.5f);
    }
  }
  // The cursors, over the planes.
  if (isBrushTool(t.tool) && (inView || brushKey_ >= 0)) {
    const ImVec2 centre =
        brushKey_ >= 0 ? ImVec2(lastDabX_ + view.min.x, lastDabY_ + view.min.y) : mouse;
    const ImU32 ring = t.tool == ToolKind::Pin ? colour(255, 90, 80) : colour(255, 255, 255, 220);
    draw->AddCircle(centre, brush.radiusPixels, kCursorShadow, 48,
                    3.5f);  // shows on light surfaces
    draw->AddCircle(centre, brush.radiusPixels, ring, 48, 1.5f);
    if (t.tool != ToolKind::Pin && brush.falloff != Falloff::Constant)
      draw->AddCircle(centre, brush.radiusPixels * halfWeightFraction(brush.falloff),
                      colour(255, 255, 255, 110), 48, 1.0f);
    if (brushKey_ >= 0) {
      char text[48];
      if (brushKeyStrength_)
        std::snprintf(text, sizeof text, "strength %.2f", brush.strength);
      else
        std::snprintf(text, sizeof text,
                      t.unifiedRadius ? "radius %.0f px (unified)" : "radius %.0f px",
                      brush.radiusPixels);
      drawOverlayLabel(draw, centre, brush.radiusPixels, colour(255, 255, 255), text);
    }
  }
  const bool pulling = stroke_ != 0 && strokeTool_ == ToolKind::Pull;  // its spring is drawn
  if (t.tool == ToolKind::Pull && hovered && !pulling) {
    // Where a drag grabs, and a ring of a fixed size in the plane the grabbed point will move in.
    const ImVec2 centre = screen(*hovered);
    const ImVec2 edge = screen(*hovered + kPullRingFraction * view_.radius() * camera_.right());
    const float ring = std::clamp(std::hypot(edge.x - centre.x, edge.y - centre.y), 5.0f, 80.0f);
    draw->AddCircle(centre, ring, kCursorShadow, 40, 4.0f);
    draw->AddCircle(centre, ring, kPullColour, 40, 2.0f);
    draw->AddCircleFilled(centre, 4.5f, kCursorShadow, 16);
    draw->AddCircleFilled(centre, 3.5f, kPullColour, 16);
  }
  if (t.tool == ToolKind::Curve && hovered && !curveGrabbed_) {
    // Where the curve's next point goes (or, with Shift, where a drag of the curve starts).
    const ImVec2 centre = screen(*hovered);
    draw->AddCircle(centre, 8.0f, kCursorShadow, 24, 3.5f);
    draw->AddCircle(centre, 8.0f, kCurveColour, 24, 1.5f);
    draw->AddCircleFilled(centre, 4.0f, kCursorShadow, 12);
    draw->AddCircleFilled(centre, 3.0f, kCurveColour, 12);
  }
  // The force of each pull spring, at its target.
  const SceneFrame& frame = view_.frame();
  for (const ToolSpring& spring : frame.springs) {
    if (!std::isfinite(spring.force)) continue;
    const Eigen::Vector3d& target = spring.target;
    char text[48];
    // In units of the solid's weight too: "3.7e6 N" says little about a 1,600 t bunny.
    if (frame.weight > 0)
      std::snprintf(text, sizeof text, "%.3g N (%.2gx weight)", spring.force,
                    spring.force / frame.weight);
    else
      std::snprintf(text, sizeof text, "%.3g N", spring.force);
    const ImVec2 at = screen(glm::vec3(target.x(), target.y(), target.z()));
    // Beside the spring's end dot (8 px across), on a backdrop: readable on the light model.
    drawOverlayLabel(draw, at, 5.0f, colour(255, 150, 130), text);
  }
  if (!curveWorld_.empty() && t.tool == ToolKind::Curve) {
    std::vector<ImVec2> points;
    for (const glm::vec3& p : curveWorld_) points.push_back(screen(p));
    draw->AddPolyline(points.data(), static_cast<int>(points.size()), kCurveColour, 0, 3.0f);
  }
  if (t.tool == ToolKind::Topology) {
    const Points& control = view_.frame().control;
    const auto outline = [&](const PickedFace& face, ImU32 line, ImU32 fill) {
      std::vector<ImVec2> points;
      for (const uint32_t v : face.loop)
        if (v < control.rows()) points.push_back(screen(row(control, v)));
      if (points.size() < 3) return;
      draw->AddConvexPolyFilled(points.data(), static_cast<int>(points.size()), fill);
      draw->AddPolyline(points.data(), static_cast<int>(points.size()), line, ImDrawFlags_Closed, 2.5f);
    };
    if (hoverFace_ && inView) outline(*hoverFace_, colour(80, 220, 255), colour(80, 220, 255, 70));
    if (firstFace_) outline(*firstFace_, colour(255, 120, 30), colour(255, 120, 30, 90));
  }
  draw->PopClipRect();
}

}  // namespace sculpt::app
