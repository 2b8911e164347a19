#include "tools/pin_tool.h"

namespace sculpt {

namespace {

template <typename Inside>
uint32_t pinWhere(Simulator& simulator, bool pin, const Inside& inside) {
  const Points& rest = simulator.model().restControl();
  uint32_t count = 0;
  for (Eigen::Index i = 0; i < rest.rows(); ++i) {
    if (!inside(Eigen::Vector3d(rest.row(i).transpose()))) continue;
    simulator.setFixed(static_cast<uint32_t>(i), pin);
    ++count;
  }
  return count;
}

}  // namespace

uint32_t pinInBox(Simulator& simulator, const Eigen::AlignedBox3d& box, bool pin) {
  return pinWhere(simulator, pin, [&](const Eigen::Vector3d& x) { return box.contains(x); });
}

uint32_t pinInSphere(Simulator& simulator, const Eigen::Vector3d& centre, double radius,
                     bool pin) {
  return pinWhere(simulator, pin,
                  [&](const Eigen::Vector3d& x) { return (x - centre).norm() <= radius; });
}

}  // namespace sculpt
