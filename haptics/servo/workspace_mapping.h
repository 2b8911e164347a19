#pragma once
// Where the device's workspace sits in the scene: a similarity from device coordinates (m, the
// device's frame) to scene coordinates (m, world), x_scene = centre + scale R (x_device - clutch).
// By default the device's workspace sphere maps onto the scene's bounding sphere, axes
// unrotated (device x right, y up, z towards the user = the default view's axes); the window
// turns it with the camera so that "right" on the device is right on the screen.
//
// Clutch: while the clutch button is held, moving the device moves nothing; at release the
// offset is kept, so the hand can be re-centred without moving the tool (the same as lifting a
// mouse off its pad).

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sculpt::haptics {

struct WorkspaceMapping {
  Eigen::Vector3d sceneCentre = Eigen::Vector3d::Zero();  ///< where the device origin maps (m)
  double scale = 1.0;  ///< scene metres per device metre (> 0)
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  ///< device axes -> scene axes
  Eigen::Vector3d clutchOffset = Eigen::Vector3d::Zero();        ///< device m, from the clutch

  /// The device's workspace (radius m) onto a scene sphere (centre, radius m).
  static WorkspaceMapping fit(double workspaceRadius, const Eigen::Vector3d& centre,
                              double sceneRadius) {
    WorkspaceMapping m;
    m.sceneCentre = centre;
    m.scale = workspaceRadius > 0 && sceneRadius > 0 ? sceneRadius / workspaceRadius : 1.0;
    return m;
  }
  Eigen::Vector3d toScene(const Eigen::Vector3d& device) const {
    return sceneCentre + scale * (rotation * (device - clutchOffset));
  }
  Eigen::Vector3d toDevice(const Eigen::Vector3d& scene) const {
    return rotation.conjugate() * ((scene - sceneCentre) / scale) + clutchOffset;
  }
  /// A velocity or displacement (no translation).
  Eigen::Vector3d vectorToScene(const Eigen::Vector3d& device) const {
    return scale * (rotation * device);
  }
  /// A scene force direction into the device frame (length kept: the force scale is separate).
  Eigen::Vector3d directionToDevice(const Eigen::Vector3d& scene) const {
    return rotation.conjugate() * scene;
  }
};

}  // namespace sculpt::haptics
