#include "haptics/servo/force_scale.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sculpt::haptics {

double ForceScale::contactDeviceStiffness(double youngs) const {
  if (!(deviceStableStiffness > 0)) return 0.0;
  double u = 0.5;
  if (youngs > 0 && referenceYoungs > 0)
    u = std::clamp(0.5 + 0.5 * std::log10(youngs / referenceYoungs), 0.0, 1.0);
  return deviceStableStiffness * (0.2 + 0.6 * u);
}

std::string ForceScale::describe() const {
  char line[160];
  std::snprintf(line, sizeof line, "1 N on the hand = %.3g N in the scene; 1 mm = %.3g mm",
                sceneNewtonsPerDeviceNewton, workspaceScale);
  return line;
}

ForceScale chooseForceScale(const DeviceInfo& device, double workspaceScale, double youngs,
                            double sceneRadius, double userFactor) {
  ForceScale scale;
  scale.workspaceScale = workspaceScale > 0 && std::isfinite(workspaceScale) ? workspaceScale : 1.0;
  scale.referenceYoungs = youngs > 0 && std::isfinite(youngs) ? youngs : 0.0;
  const double factor = userFactor > 0 && std::isfinite(userFactor) ? userFactor : 1.0;
  const double r = device.workspaceRadius, fmax = device.maxForce, kStable = device.stableStiffness;
  if (!device.hasForce() || !(r > 0) || !(kStable > 0) || !(scale.referenceYoungs > 0) ||
      !(sceneRadius > 0) || !std::isfinite(sceneRadius))
    return scale;
  const double kSolid = scale.referenceYoungs * sceneRadius;
  // r / (0.8 Fmax) > 2 / k_stable holds for every PHANTOM-class arm (the coupling alone would
  // reach 0.8 Fmax well inside the workspace); keep a floor for odd descriptions.
  const double compliance = std::max(r / (0.8 * fmax) - 2.0 / kStable, 0.1 * r / fmax);
  scale.deviceStableStiffness = kStable;
  scale.sceneNewtonsPerDeviceNewton = factor * kSolid * scale.workspaceScale * compliance;
  scale.pullStiffness = scale.sceneStiffness(0.5 * kStable);
  return scale;
}

}  // namespace sculpt::haptics
