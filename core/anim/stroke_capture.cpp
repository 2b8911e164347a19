#include "anim/stroke_capture.h"

#include <algorithm>

namespace sculpt {

void StrokeCapture::clear() {
  script_ = SessionScript{};
  grab_.reset();
}

void StrokeCapture::beginGrab(double t, const Eigen::Vector3d& rest, const Eigen::Vector3d& world,
                              bool keep) {
  endGrab(t);
  GrabEvent grab;
  grab.point = rest;
  grab.path.push_back({0.0, world});
  grab.keep = keep;
  ScriptEvent event;
  event.index = script_.events.size();
  event.time = std::max(0.0, t);
  event.action = grab;
  grab_ = script_.events.size();
  script_.events.push_back(std::move(event));
}

void StrokeCapture::moveGrab(double t, const Eigen::Vector3d& world) {
  if (!grab_) return;
  ScriptEvent& event = script_.events[*grab_];
  GrabEvent& grab = std::get<GrabEvent>(event.action);
  const double at = t - event.time;
  if (at < grab.path.back().time) return;
  if (at == grab.path.back().time)
    grab.path.back().target = world;
  else
    grab.path.push_back({at, world});
}

void StrokeCapture::endGrab(double t) {
  if (!grab_) return;
  ScriptEvent& event = script_.events[*grab_];
  std::get<GrabEvent>(event.action).release = std::max(0.0, t - event.time);
  grab_.reset();
}

}  // namespace sculpt
