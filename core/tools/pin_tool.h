#pragma once
// Pin / unpin: fixes or frees the control points whose rest position lies in a box or
// a sphere (Simulator::setFixed; a pinned point keeps its current position and loses its
// velocity). The window paints with the sphere; scripts and the CLI use boxes.

#include <Eigen/Geometry>
#include <cstdint>

#include "sim/simulator.h"

namespace sculpt {

/// Pins (pin = true) or unpins the control points with rest position in `box` (closed);
/// returns how many lie in it.
uint32_t pinInBox(Simulator& simulator, const Eigen::AlignedBox3d& box, bool pin = true);
/// The same for rest positions within `radius` of `centre`.
uint32_t pinInSphere(Simulator& simulator, const Eigen::Vector3d& centre, double radius,
                     bool pin = true);

}  // namespace sculpt
