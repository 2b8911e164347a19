#pragma once
// Between the scene and the hand. Scenes are in SI units: pulling a rubber bunny 10 cm takes
// kilonewtons or more, while a Touch renders 3.3 N. The force scale S (scene newtons per device
// newton) and the coupling stiffness are chosen together from the scene's stiffness and size so
//  - a rigid grab feels like a spring of half the device's stable stiffness (the coupling alone,
//    k_c W / S = k_stable / 2 with W the workspace scale, scene m per device m), so the loop is
//    stable whatever the solid does (docs/design/haptics.md "Force scale"); and
//  - a full pull (the stylus moved one workspace radius r from the grab) is felt at 80% of the
//    device's maximum force, with the solid modelled as a spring k_solid = E R (E the scene's
//    Young's modulus, R its radius) in series with the coupling:
//      (k_c k_solid / (k_c + k_solid)) r W / S = 0.8 F_max
//    which gives S = k_solid W (r / (0.8 F_max) - 2 / k_stable) and k_c = k_stable S / (2 W).
// A user factor multiplies S (larger: the scene feels lighter); the window shows and adjusts it.
//
// Contact (probe, stiffness paint): the felt stiffness of the surface is the Young's modulus at
// the contact mapped into [0.2, 0.8] k_stable, logarithmically over [E0 / 10, 10 E0] (E0 the
// scene's material), so a region painted 10x stiffer is felt clearly stiffer and never past the
// device's stable range.

#include <string>

#include "haptics/device/haptic_device.h"

namespace sculpt::haptics {

struct ForceScale {
  double sceneNewtonsPerDeviceNewton = 1.0;  ///< S
  double workspaceScale = 1.0;               ///< W, scene m per device m
  double pullStiffness = 0.0;                ///< k_c, the pull spring in the scene (N/m)
  double deviceStableStiffness = 0.0;        ///< k_stable of the device (N/m)
  double referenceYoungs = 0.0;              ///< E0 (Pa)

  /// The scene spring (N/m) whose rigid-grab feel is `deviceStiffness` (N/m on the hand).
  double sceneStiffness(double deviceStiffness) const {
    return deviceStiffness * sceneNewtonsPerDeviceNewton / workspaceScale;
  }
  /// The felt contact stiffness on the hand (N/m) for Young's modulus `youngs` (Pa).
  double contactDeviceStiffness(double youngs) const;
  /// One line for the device panel and the CLI: "1 N on the hand = 2.4e+04 N in the scene".
  std::string describe() const;
};

/// The scale for `device` mapped with `workspaceScale` onto a scene of Young's modulus `youngs`
/// (Pa) and bounding radius `sceneRadius` (m), times `userFactor` (> 0). A device without force
/// (or bad inputs) gets S = 1 and the default coupling of the window (pullStiffness 0).
ForceScale chooseForceScale(const DeviceInfo& device, double workspaceScale, double youngs,
                            double sceneRadius, double userFactor = 1.0);

}  // namespace sculpt::haptics
