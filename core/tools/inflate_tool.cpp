#include "tools/inflate_tool.h"

#include <memory>

namespace sculpt {

InflateTool::InflateTool(Simulator& simulator) : simulator_(simulator) {}

InflateTool::~InflateTool() { release(); }

void InflateTool::press(const Eigen::Vector3d& centre, double radius, double pressure) {
  // Built first, so that a rejected input leaves the previous brush in place.
  auto form = std::make_unique<PressureForm>(simulator_.model(), pressure,
                                             SphereRegion{centre, radius});
  release();
  form_ = static_cast<PressureForm*>(simulator_.addLoad(std::move(form)));
}

void InflateTool::setPressure(double pressure) {
  if (form_) form_->setPressure(pressure);
}

void InflateTool::release() {
  if (form_) simulator_.removeLoad(form_);
  form_ = nullptr;
}

}  // namespace sculpt
