#include "render/camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>
#include <string>

namespace sculpt::render {
namespace {

constexpr float kHalfPi = glm::half_pi<float>();
constexpr float kMinDistanceRadii = 1e-3f, kMaxDistanceRadii = 1e3f;
// A framed sphere spans this fraction of the view's shorter side: the model stands clear of the
// panels and the view's edges, as Blender's View Selected leaves it.
constexpr double kFrameFill = 0.8;
constexpr double kClipMargin = 1.05;   // near/far keep the scene sphere grown by 5 %

bool finite(float v) { return std::isfinite(v); }

// View and projection are composed in double so that project/unproject round-trip to ~1e-7 even
// with a wide near/far range; OpenGL gets the float copies.
glm::dmat4 viewMatrix(const glm::dvec3& pivot, double yaw, double pitch, double distance) {
  // world -> eye: translate the pivot to the origin, undo yaw about y, undo pitch about x, then
  // push the scene `distance` in front of the eye.
  glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -distance));
  m = glm::rotate(m, pitch, glm::dvec3(1.0, 0.0, 0.0));
  m = glm::rotate(m, -yaw, glm::dvec3(0.0, 1.0, 0.0));
  return glm::translate(m, -pivot);
}

}  // namespace

glm::vec3 Camera::backward() const {
  return {std::cos(pitch_) * std::sin(yaw_), std::sin(pitch_), std::cos(pitch_) * std::cos(yaw_)};
}
glm::vec3 Camera::right() const { return {std::cos(yaw_), 0.0f, -std::sin(yaw_)}; }
glm::vec3 Camera::up() const {
  return {-std::sin(pitch_) * std::sin(yaw_), std::cos(pitch_), -std::sin(pitch_) * std::cos(yaw_)};
}
glm::vec3 Camera::eye() const { return pivot_ + distance_ * backward(); }

void Camera::clipPlanes(float& nearDistance, float& farDistance) const {
  // Depth along the view direction of the scene sphere's nearest and farthest points, and of
  // the pivot (which may have been panned away from the scene).
  const double d = glm::dot(glm::dvec3(sceneCentre_ - eye()), -glm::dvec3(backward()));
  const double r = kClipMargin * sceneRadius_;
  double farD = std::max(d + r, 1.05 * distance_);
  double nearD = std::min(d - r, 0.5 * static_cast<double>(distance_));
  // Perspective needs a positive near plane. With the eye inside the scene sphere it sits at 1 %
  // of the far distance (depth read back from a 24-bit buffer then stays good to ~1e-5 of the
  // scene), or closer when zoomed in further, so that what is around the pivot stays in front.
  if (!orthographic_) nearD = std::max(nearD, std::min(1e-2 * farD, 0.5 * distance_));
  if (farD <= nearD) farD = nearD + r;
  nearDistance = static_cast<float>(nearD);
  farDistance = static_cast<float>(farD);
}

glm::mat4 Camera::view() const {
  return glm::mat4(viewMatrix(glm::dvec3(pivot_), yaw_, pitch_, distance_));
}

namespace {
glm::dmat4 projectionMatrix(bool orthographic, double fovY, double distance, double aspect,
                            double nearD, double farD) {
  if (orthographic) {
    const double halfHeight = distance * std::tan(0.5 * fovY);
    const double halfWidth = halfHeight * aspect;
    return glm::ortho(-halfWidth, halfWidth, -halfHeight, halfHeight, nearD, farD);
  }
  return glm::perspective(fovY, aspect, nearD, farD);
}
}  // namespace

glm::mat4 Camera::projection(float aspect) const {
  if (!(aspect > 0.0f) || !finite(aspect))
    throw std::invalid_argument("Camera::projection needs a positive finite aspect ratio");
  float nearD = 0.0f, farD = 0.0f;
  clipPlanes(nearD, farD);
  return glm::mat4(projectionMatrix(orthographic_, fovY_, distance_, aspect, nearD, farD));
}

void Camera::orbit(float dxPixels, float dyPixels) {
  orbitBy(-kOrbitRadiansPerPixel * dxPixels, kOrbitRadiansPerPixel * dyPixels);
}

void Camera::orbitBy(float yawRadians, float pitchRadians) {
  if (!finite(yawRadians) || !finite(pitchRadians)) return;  // a bad event must not poison the view
  setOrientation(yaw_ + yawRadians, pitch_ + pitchRadians);
}

void Camera::setOrientation(float yaw, float pitch) {
  if (!finite(yaw) || !finite(pitch))
    throw std::invalid_argument("Camera::setOrientation needs finite angles");
  // Keep yaw in (-pi, pi] so that it does not lose precision after many turns.
  yaw_ = std::remainder(yaw, glm::two_pi<float>());
  pitch_ = std::clamp(pitch, -kHalfPi, kHalfPi);
}

float Camera::pixelSizeAtPivot(int viewportHeight) const {
  if (viewportHeight <= 0)
    throw std::invalid_argument("the viewport height must be positive, got " +
                                std::to_string(viewportHeight));
  return 2.0f * distance_ * std::tan(0.5f * fovY_) / static_cast<float>(viewportHeight);
}

void Camera::pan(float dxPixels, float dyPixels, int viewportHeight) {
  if (!finite(dxPixels) || !finite(dyPixels)) return;
  const float pixel = pixelSizeAtPivot(viewportHeight);
  // The scene follows the cursor, so the camera moves the other way (screen y points down).
  pivot_ += pixel * (-dxPixels * right() + dyPixels * up());
}

void Camera::setDistance(float distance) {
  if (!(distance > 0.0f) || !finite(distance))
    throw std::invalid_argument("the camera distance must be positive and finite");
  distance_ =
      std::clamp(distance, kMinDistanceRadii * sceneRadius_, kMaxDistanceRadii * sceneRadius_);
}

void Camera::zoom(float factor) {
  if (!(factor > 0.0f) || !finite(factor))
    throw std::invalid_argument("a zoom factor must be positive and finite, got " +
                                std::to_string(factor));
  setDistance(distance_ * factor);
}

void Camera::setSceneBounds(const glm::vec3& centre, float radius) {
  if (!(radius > 0.0f) || !finite(radius) || !finite(centre.x) || !finite(centre.y) ||
      !finite(centre.z))
    throw std::invalid_argument("the scene bounds need a finite centre and a positive radius");
  sceneCentre_ = centre;
  sceneRadius_ = radius;
}

void Camera::frame(const glm::vec3& centre, float radius, float aspect) {
  if (!(aspect > 0.0f) || !finite(aspect))
    throw std::invalid_argument("Camera::frame needs a positive finite aspect ratio");
  setSceneBounds(centre, radius);
  pivot_ = centre;
  // A sphere at distance d subtends a half-angle asin(r / d); it must fit the smaller of the
  // vertical and horizontal half fields of view.
  const double halfY = 0.5 * static_cast<double>(fovY_);
  const double halfX = std::atan(static_cast<double>(aspect) * std::tan(halfY));
  // In perspective the sphere's outline subtends asin(r / d), whose tangent must be kFrameFill
  // times the tangent of the tighter half field of view; in orthographic r itself is that
  // fraction of the tighter half extent, d tan(half field).
  const double tanHalf = std::tan(std::min(halfX, halfY));
  const double d = orthographic_ ? radius / (kFrameFill * tanHalf)
                                 : radius / std::sin(std::atan(kFrameFill * tanHalf));
  setDistance(static_cast<float>(d));
}

void Camera::setStandardView(StandardView view) {
  switch (view) {
    case StandardView::Front:
      setOrientation(0.0f, 0.0f);
      break;
    case StandardView::Back:
      setOrientation(glm::pi<float>(), 0.0f);
      break;
    case StandardView::Right:
      setOrientation(kHalfPi, 0.0f);
      break;
    case StandardView::Left:
      setOrientation(-kHalfPi, 0.0f);
      break;
    case StandardView::Top:
      setOrientation(0.0f, kHalfPi);
      break;
    case StandardView::Bottom:
      setOrientation(0.0f, -kHalfPi);
      break;
  }
}

void Camera::setPivot(const glm::vec3& pivot) {
  if (!finite(pivot.x) || !finite(pivot.y) || !finite(pivot.z))
    throw std::invalid_argument("the pivot must be a finite point");
  const glm::vec3 offset = eye() - pivot;
  const float length = glm::length(offset);
  if (length < kMinDistanceRadii * sceneRadius_) {
    pivot_ = pivot;  // no direction to look along: keep the orientation
    return;
  }
  const float horizontal = std::hypot(offset.x, offset.z);
  const float yaw = horizontal > 1e-6f * length ? std::atan2(offset.x, offset.z) : yaw_;
  setOrientation(yaw, std::atan2(offset.y, horizontal));
  pivot_ = pivot;
  setDistance(length);
}

void Camera::setFieldOfView(float fovYRadians) {
  if (!(fovYRadians > 0.0f && fovYRadians < glm::pi<float>()))
    throw std::invalid_argument("the field of view must be in (0, pi) radians");
  fovY_ = fovYRadians;
}

glm::dmat4 Camera::viewProjectionD(double aspect) const {
  float nearD = 0.0f, farD = 0.0f;
  clipPlanes(nearD, farD);
  return projectionMatrix(orthographic_, fovY_, distance_, aspect, nearD, farD) *
         viewMatrix(glm::dvec3(pivot_), yaw_, pitch_, distance_);
}

glm::vec3 Camera::project(const glm::vec3& world, int width, int height) const {
  if (width <= 0 || height <= 0)
    throw std::invalid_argument("Camera::project needs a viewport of positive size");
  const glm::dmat4 viewProjection = viewProjectionD(double(width) / double(height));
  const glm::dvec4 clip = viewProjection * glm::dvec4(glm::dvec3(world), 1.0);
  const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
  return glm::vec3((ndc.x + 1.0) * 0.5 * width, (1.0 - ndc.y) * 0.5 * height, (ndc.z + 1.0) * 0.5);
}

std::optional<glm::vec3> Camera::unproject(float x, float y, float depth01, int width,
                                           int height) const {
  if (width <= 0 || height <= 0)
    throw std::invalid_argument("Camera::unproject needs a viewport of positive size");
  if (!(depth01 >= 0.0f && depth01 <= 1.0f))
    throw std::invalid_argument("a depth-buffer value must be in [0, 1], got " +
                                std::to_string(depth01));
  if (depth01 >= 1.0f || !finite(x) || !finite(y)) return std::nullopt;  // background
  const glm::dmat4 viewProjection = viewProjectionD(double(width) / double(height));
  const glm::dvec4 ndc(2.0 * x / width - 1.0, 1.0 - 2.0 * y / height, 2.0 * depth01 - 1.0, 1.0);
  const glm::dvec4 world = glm::inverse(viewProjection) * ndc;
  if (!(std::abs(world.w) > 1e-300)) return std::nullopt;
  return glm::vec3(glm::dvec3(world) / world.w);
}

}  // namespace sculpt::render
