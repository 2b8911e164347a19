#include "anim/stroke_capture.h"

#include <algorithm>
#include <utility>

namespace sculpt {
namespace {

// Appends a key `at` s after the event's start (the same time replaces the last key's value).
void appendKey(std::vector<PathKey>& path, double at, const Eigen::Vector3d& value) {
  if (at < path.back().time) return;
  if (at == path.back().time)
    path.back().target = value;
  else
    path.push_back({at, value});
}

}  // namespace

void StrokeCapture::clear() {
  script_ = SessionScript{};
  stroke_.reset();
}

void StrokeCapture::add(double t, ScriptEvent::Action action) {
  ScriptEvent event;
  event.index = script_.events.size();
  event.time = std::max(0.0, t);
  event.action = std::move(action);
  script_.events.push_back(std::move(event));
}

void StrokeCapture::startStroke(Kind kind, size_t event, double t) {
  stroke_.emplace();
  stroke_->kind = kind;
  stroke_->event = event;
  stroke_->time = t;
}

void StrokeCapture::beginGrab(double t, const Eigen::Vector3d& rest, const Eigen::Vector3d& world,
                              bool keep) {
  end(t);
  GrabEvent grab;
  grab.point = rest;
  grab.path.push_back({0.0, world});
  grab.keep = keep;
  add(t, std::move(grab));
  startStroke(Kind::Grab, script_.events.size() - 1, t);
}

void StrokeCapture::beginCurve(double t, std::vector<Eigen::Vector3d> points, CurveProfile profile,
                               const Eigen::Vector3d& world) {
  end(t);
  CurveEvent curve;
  curve.points = std::move(points);
  curve.path.push_back({0.0, Eigen::Vector3d::Zero()});
  curve.profile = profile;
  add(t, std::move(curve));
  startStroke(Kind::Curve, script_.events.size() - 1, t);
  stroke_->origin = world;
}

void StrokeCapture::beginBrush(double t, Kind kind, const Eigen::Vector3d& rest, double spacing,
                               double radius, ScriptEvent::Action action) {
  end(t);
  startStroke(kind, kNoEvent, t);
  stroke_->spacing = spacing;
  stroke_->radius = radius;
  stroke_->repeated = std::move(action);
  actAt(t, rest);
}

void StrokeCapture::beginInflate(double t, const Eigen::Vector3d& rest,
                                 const InflateStroke::Settings& settings, double pressure) {
  InflateEvent inflate;
  inflate.radius = settings.radius;
  inflate.pressure = pressure;
  beginBrush(t, Kind::Inflate, rest, settings.respacing, settings.radius, inflate);
}

void StrokeCapture::beginPaint(double t, const Eigen::Vector3d& rest,
                               const PaintStroke::Settings& settings) {
  PaintEvent paint;
  paint.brush = settings.brush;
  paint.mirrorCentre = settings.mirrorCentre;
  beginBrush(t, Kind::Paint, rest, settings.spacing, settings.brush.radius, paint);
}

void StrokeCapture::beginPin(double t, const Eigen::Vector3d& rest, double radius, bool unpin) {
  PinEvent pin;
  pin.radius = radius;
  pin.unpin = unpin;
  beginBrush(t, Kind::Pin, rest, 0.0, radius, pin);
}

void StrokeCapture::actAt(double t, const Eigen::Vector3d& rest) {
  // The brush acts here as its tool would: a new press, dab or pin centred on `rest`.
  if (stroke_->kind == Kind::Inflate && stroke_->event != kNoEvent)
    std::get<InflateEvent>(script_.events[stroke_->event].action).duration =
        std::max(0.0, t - script_.events[stroke_->event].time);
  ScriptEvent::Action action = stroke_->repeated;
  std::visit(
      [&rest](auto& event) {
        if constexpr (requires { event.centre; }) event.centre = rest;
      },
      action);
  add(t, std::move(action));
  stroke_->event = script_.events.size() - 1;
  stroke_->last = rest;
}

void StrokeCapture::move(double t, const Eigen::Vector3d& world,
                         const std::optional<Eigen::Vector3d>& rest) {
  if (!stroke_ || t < stroke_->time) return;
  stroke_->time = t;
  ScriptEvent& event = script_.events[stroke_->event];
  const double at = t - event.time;
  switch (stroke_->kind) {
    case Kind::Grab: appendKey(std::get<GrabEvent>(event.action).path, at, world); return;
    case Kind::Curve:
      appendKey(std::get<CurveEvent>(event.action).path, at, world - stroke_->origin);
      return;
    case Kind::Inflate: std::get<InflateEvent>(event.action).duration = at; break;
    case Kind::Paint:
    case Kind::Pin: break;
  }
  if (!rest) return;
  // A pin brush pins wherever it passes; inflate and paint act again once moved far enough.
  const bool acts = stroke_->kind == Kind::Pin
                        ? *rest != stroke_->last
                        : brushMoved(stroke_->last, *rest, stroke_->spacing, stroke_->radius);
  if (acts) actAt(t, *rest);
}

void StrokeCapture::end(double t) {
  if (!stroke_) return;
  ScriptEvent& event = script_.events[stroke_->event];
  const double held = std::max(0.0, t - event.time);
  switch (stroke_->kind) {
    case Kind::Grab: std::get<GrabEvent>(event.action).release = held; break;
    case Kind::Curve: std::get<CurveEvent>(event.action).release = held; break;
    case Kind::Inflate: std::get<InflateEvent>(event.action).duration = held; break;
    case Kind::Paint:
    case Kind::Pin: break;
  }
  stroke_.reset();
}

}  // namespace sculpt
