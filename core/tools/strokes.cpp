#include "tools/strokes.h"

#include <stdexcept>

#include "tools/pin_tool.h"

namespace sculpt {

// ---------------------------------------------------------------------------------------------
// Pull

void PullStroke::begin(ToolContext& context, const ToolInput& input) {
  std::optional<MaterialPoint> point = settings_.point;
  if (!point) point = context.locator().locate(restPointOf(context, input, "pull"));
  if (!point) throw std::invalid_argument("pull: nothing to grab there.");
  if (!pull_) pull_ = std::make_unique<PullTool>(context.simulator());
  pull_->grab(*point, input.position, settings_.stiffness, input.inverted());
}

void PullStroke::update(ToolContext&, const ToolInput& input) {
  if (pull_) pull_->moveTarget(input.position);
}

void PullStroke::end(ToolContext&, const ToolInput&) {
  if (pull_ && pull_->active())
    pull_->release(settings_.keep ? ReleaseMode::Keep : ReleaseMode::LetGo);
}

void PullStroke::clear() {
  if (!pull_) return;
  pull_->release(ReleaseMode::LetGo);
  pull_->clearKept();
}

bool PullStroke::holdsLoads() const { return pull_ && (pull_->active() || pull_->numKept() > 0); }

void PullStroke::springs(const Simulator& simulator, std::vector<ToolSpring>& out) const {
  (void)simulator;
  if (pull_ && pull_->active()) out.push_back(pull_->heldSpring());
}

// ---------------------------------------------------------------------------------------------
// Inflate

double InflateStroke::pressureOf(const ToolInput& input) const {
  return (input.inverted() ? -1.0 : 1.0) * settings_.pressure * input.pressure;
}

void InflateStroke::begin(ToolContext& context, const ToolInput& input) {
  const Eigen::Vector3d rest = restPointOf(context, input, "inflate");
  if (!inflate_) inflate_ = std::make_unique<InflateTool>(context.simulator());
  centre_ = rest;
  pressure_ = pressureOf(input);
  inflate_->press(centre_, settings_.radius, pressure_);
}

void InflateStroke::update(ToolContext& context, const ToolInput& input) {
  if (!inflate_ || !inflate_->active()) return;
  const double pressure = pressureOf(input);
  const std::optional<Eigen::Vector3d> rest =
      input.restPoint ? input.restPoint : context.restPointAt(input.position);
  if (rest && brushMoved(centre_, *rest, settings_.respacing, settings_.radius)) {
    centre_ = *rest;
    pressure_ = pressure;
    inflate_->press(centre_, settings_.radius, pressure_);
  } else if (pressure != pressure_) {
    pressure_ = pressure;
    inflate_->setPressure(pressure_);
  }
}

void InflateStroke::end(ToolContext&, const ToolInput&) { clear(); }

void InflateStroke::clear() {
  if (inflate_) inflate_->release();
}

// ---------------------------------------------------------------------------------------------
// Paint

void PaintStroke::dab(ToolContext& context, const Eigen::Vector3d& rest) {
  MaterialBrushSettings brush = settings_.brush;
  brush.mirror.centre = settings_.mirrorCentre ? *settings_.mirrorCentre : context.symmetryCentre();
  const long touched = paintDab(context.model(), rest, brush);
  painted_ += touched;
  last_ = rest;
  if (touched > 0) context.materialsChanged();
}

void PaintStroke::begin(ToolContext& context, const ToolInput& input) {
  dab(context, restPointOf(context, input, "paint"));
}

void PaintStroke::update(ToolContext& context, const ToolInput& input) {
  const std::optional<Eigen::Vector3d> rest =
      input.restPoint ? input.restPoint : context.restPointAt(input.position);
  if (rest && brushMoved(last_, *rest, settings_.spacing, settings_.brush.radius))
    dab(context, *rest);
}

// ---------------------------------------------------------------------------------------------
// Pin

void PinStroke::begin(ToolContext& context, const ToolInput& input) {
  const bool pin = !input.inverted();
  if (settings_.box) {
    touched_ += pinInBox(context.simulator(), *settings_.box, pin);
    return;
  }
  touched_ +=
      pinInSphere(context.simulator(), restPointOf(context, input, "pin"), settings_.radius, pin);
}

void PinStroke::update(ToolContext& context, const ToolInput& input) {
  if (settings_.box) return;
  const std::optional<Eigen::Vector3d> rest =
      input.restPoint ? input.restPoint : context.restPointAt(input.position);
  if (rest)
    touched_ += pinInSphere(context.simulator(), *rest, settings_.radius, !input.inverted());
}

// ---------------------------------------------------------------------------------------------
// Curve

void CurveStroke::begin(ToolContext& context, const ToolInput& input) {
  std::vector<CurveSample> samples = settings_.sampled;
  if (samples.empty())
    samples =
        sampleCurve(context.model(), context.locator(), settings_.polyline, settings_.samples);
  if (!curve_) curve_ = std::make_unique<CurveTool>(context.simulator());
  curve_->grab(std::move(samples), settings_.profile, settings_.stiffness);
  origin_ = settings_.dragOrigin ? *settings_.dragOrigin : input.position;
  curve_->drag(input.position - origin_);
}

void CurveStroke::update(ToolContext&, const ToolInput& input) {
  if (curve_ && curve_->active()) curve_->drag(input.position - origin_);
}

void CurveStroke::end(ToolContext&, const ToolInput&) {
  if (curve_ && curve_->active())
    curve_->release(settings_.keep ? ReleaseMode::Keep : ReleaseMode::LetGo);
}

void CurveStroke::clear() {
  if (!curve_) return;
  curve_->release(ReleaseMode::LetGo);
  curve_->clearKept();
}

bool CurveStroke::holdsLoads() const {
  return curve_ && (curve_->active() || curve_->numKept() > 0);
}

void CurveStroke::springs(const Simulator& simulator, std::vector<ToolSpring>& out) const {
  (void)simulator;
  if (!curve_ || !curve_->active()) return;
  const std::vector<Eigen::Vector3d> points = curve_->pointPositions(), targets = curve_->targets();
  for (size_t i = 0; i < points.size() && i < targets.size(); ++i) {
    ToolSpring spring;  // drawn, not labelled
    spring.point = points[i];
    spring.target = targets[i];
    spring.stiffness = curve_->springStiffness();
    out.push_back(spring);
  }
}

// ---------------------------------------------------------------------------------------------
// Eyedropper

std::optional<Material> Eyedropper::Result::take() {
  const std::lock_guard lock(mutex_);
  return std::exchange(material_, std::nullopt);
}

void Eyedropper::Result::set(const Material& material) {
  const std::lock_guard lock(mutex_);
  material_ = material;
}

void Eyedropper::begin(ToolContext& context, const ToolInput& input) {
  result_->set(pickMaterial(context.model(), restPointOf(context, input, "eyedropper")));
}

}  // namespace sculpt
