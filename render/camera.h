#pragma once
// The 3D view's camera: a turntable orbit around a pivot point (Y up), as in Blender.
//
// The eye sits at pivot + distance * (cos(pitch) sin(yaw), sin(pitch), cos(pitch) cos(yaw)), so
// yaw = pitch = 0 looks from +z towards -z (the front view). The view matrix is built from the two
// rotations rather than lookAt, so looking straight down or up (pitch = ±pi/2) is not singular.
// The orthographic view shows the pivot plane at the same scale as the perspective one
// (half-height = distance * tan(fovY / 2)), so toggling the projection keeps the apparent size of
// what is at the pivot. Near and far planes follow a scene sphere (set by frame() or
// setSceneBounds()) so that nothing in it is clipped at any zoom.
//
// Window coordinates here are pixels with y down (GLFW's cursor convention), in the same units as
// the viewport size passed with them (use framebuffer pixels when reading the depth buffer).

#include <glm/glm.hpp>
#include <optional>

namespace sculpt::render {

/// The six axis views of the numpad (Blender's 1/3/7 and Ctrl+1/3/7), in our Y-up world.
enum class StandardView {
  Front,   ///< from +z looking towards -z
  Back,    ///< from -z looking towards +z
  Right,   ///< from +x looking towards -x
  Left,    ///< from -x looking towards +x
  Top,     ///< from +y looking down, -z up on the screen
  Bottom,  ///< from -y looking up, +z up on the screen
};

class Camera {
 public:
  /// Radians of orbit per pixel of mouse motion.
  static constexpr float kOrbitRadiansPerPixel = 0.008f;

  Camera() = default;

  /// Column-major view matrix (world -> eye coordinates, the eye looks along -z).
  glm::mat4 view() const;
  /// Perspective or orthographic projection (OpenGL clip space, z in [-1, 1]) for a viewport of
  /// this width / height. Throws std::invalid_argument for a non-positive or non-finite aspect.
  glm::mat4 projection(float aspect) const;

  /// Turntable orbit by a mouse motion in pixels: dragging right turns the scene right (yaw
  /// decreases), dragging down shows more of its top (pitch increases, clamped to ±pi/2).
  void orbit(float dxPixels, float dyPixels);
  /// Orbit by angles in radians (numpad 4/6/8/2 steps): the eye moves by +yaw around world up and
  /// up by +pitch.
  void orbitBy(float yawRadians, float pitchRadians);
  /// Moves the pivot (and the eye with it) in the view plane so that a point at the pivot's depth
  /// follows the cursor exactly: the scene moves by (dx, dy) pixels of a viewport this high.
  void pan(float dxPixels, float dyPixels, int viewportHeight);
  /// distance *= factor, clamped to [1e-3, 1e3] scene radii. factor < 1 zooms in.
  /// Throws std::invalid_argument unless factor is positive and finite.
  void zoom(float factor);
  /// Pivot = centre and the distance at which a sphere of this radius spans 80 % of the view's
  /// shorter side (of a view of this aspect), in the current projection. Also sets the scene
  /// sphere. Orientation and projection mode are kept. Throws std::invalid_argument for a
  /// non-positive radius or aspect.
  void frame(const glm::vec3& centre, float radius, float aspect);
  /// The sphere that near/far planes must keep visible (e.g. the model's bounds as it deforms).
  void setSceneBounds(const glm::vec3& centre, float radius);
  /// Looks along one of the axes (keeps pivot, distance and projection mode).
  void setStandardView(StandardView view);
  /// Perspective <-> orthographic (numpad 5), keeping the scale at the pivot.
  void toggleOrthographic() { orthographic_ = !orthographic_; }
  void setOrthographic(bool orthographic) { orthographic_ = orthographic; }
  /// Makes `pivot` the orbit centre while the eye stays where it is: the view turns to look at
  /// the new pivot and orbits around it from then on. A pivot at the eye keeps the orientation.
  void setPivot(const glm::vec3& pivot);
  /// Sets yaw and pitch (radians; pitch clamped to ±pi/2).
  void setOrientation(float yaw, float pitch);
  /// Sets the eye-pivot distance (clamped like zoom()).
  void setDistance(float distance);
  /// Vertical field of view in radians, in (0, pi). Throws std::invalid_argument otherwise.
  void setFieldOfView(float fovYRadians);

  /// Projects a world point to window coordinates: x, y in pixels (y down) and z the depth-buffer
  /// value in [0, 1] (for the default glDepthRange).
  glm::vec3 project(const glm::vec3& world, int width, int height) const;
  /// The world point at window position (x, y) (pixels, y down) and depth-buffer value depth01
  /// (as read with glReadPixels(GL_DEPTH_COMPONENT)). Depth 1 is the cleared background: nullopt.
  /// Throws std::invalid_argument for a non-positive viewport or a depth outside [0, 1].
  std::optional<glm::vec3> unproject(float x, float y, float depth01, int width, int height) const;

  glm::vec3 eye() const;
  /// Unit vector from the pivot towards the eye.
  glm::vec3 backward() const;
  /// Unit vectors of the screen's right and up directions in world coordinates.
  glm::vec3 right() const;
  glm::vec3 up() const;

  const glm::vec3& pivot() const { return pivot_; }
  float yaw() const { return yaw_; }
  float pitch() const { return pitch_; }
  float distance() const { return distance_; }
  float fieldOfView() const { return fovY_; }
  bool orthographic() const { return orthographic_; }
  const glm::vec3& sceneCentre() const { return sceneCentre_; }
  float sceneRadius() const { return sceneRadius_; }
  /// World units per pixel in the plane through the pivot for a viewport this high.
  float pixelSizeAtPivot(int viewportHeight) const;

 private:
  /// Near and far distances covering the scene sphere and the pivot.
  void clipPlanes(float& nearDistance, float& farDistance) const;
  /// projection * view in double precision (project/unproject round-trip to ~1e-7).
  glm::dmat4 viewProjectionD(double aspect) const;

  glm::vec3 pivot_{0.0f};
  float yaw_ = 0.5f, pitch_ = 0.3f;
  float distance_ = 3.0f;
  float fovY_ = glm::radians(35.0f);
  bool orthographic_ = false;
  glm::vec3 sceneCentre_{0.0f};
  float sceneRadius_ = 1.0f;
};

}  // namespace sculpt::render
