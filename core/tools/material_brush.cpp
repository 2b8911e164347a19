#include "tools/material_brush.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace sculpt {

const char* falloffName(Falloff falloff) {
  switch (falloff) {
    case Falloff::Smooth: return "smooth";
    case Falloff::Sphere: return "sphere";
    case Falloff::Linear: return "linear";
    case Falloff::Sharp: return "sharp";
    case Falloff::Constant: return "constant";
  }
  return "smooth";
}

std::optional<Falloff> parseFalloff(const std::string& name) {
  for (Falloff f : {Falloff::Smooth, Falloff::Sphere, Falloff::Linear, Falloff::Sharp,
                    Falloff::Constant})
    if (name == falloffName(f)) return f;
  return std::nullopt;
}

double falloffWeight(Falloff falloff, double r, double radius) {
  if (!(radius > 0) || !(r <= radius)) return 0.0;
  const double p = 1.0 - std::max(r, 0.0) / radius;
  switch (falloff) {
    case Falloff::Smooth: return 3 * p * p - 2 * p * p * p;
    case Falloff::Sphere: return std::sqrt(std::max(0.0, 2 * p - p * p));
    case Falloff::Linear: return p;
    case Falloff::Sharp: return p * p;
    case Falloff::Constant: return 1.0;
  }
  return 0.0;
}

std::string brushProblem(const MaterialBrushSettings& settings) {
  if (!std::isfinite(settings.radius) || settings.radius <= 0)
    return "the brush radius must be a positive finite number of metres.";
  if (!(settings.strength >= 0 && settings.strength <= 1))
    return "the brush strength must lie in [0, 1].";
  if (const std::string problem = materialProblem(settings.target); !problem.empty())
    return "invalid brush material: " + problem;
  if (!settings.mirror.centre.allFinite()) return "the symmetry centre is not finite.";
  return {};
}

long paintDab(FemModel& model, const Eigen::Vector3d& centre,
              const MaterialBrushSettings& settings) {
  if (const std::string problem = brushProblem(settings); !problem.empty())
    throw std::invalid_argument("paint: " + problem);
  if (!centre.allFinite()) throw std::invalid_argument("paint: the brush centre is not finite.");
  // The centre and its reflections, one per subset of the enabled planes.
  const std::array<bool, 3> axes{settings.mirror.x, settings.mirror.y, settings.mirror.z};
  std::vector<Eigen::Vector3d> images{centre};
  for (int axis = 0; axis < 3; ++axis) {
    if (!axes[size_t(axis)]) continue;
    const size_t n = images.size();
    for (size_t i = 0; i < n; ++i) {
      Eigen::Vector3d m = images[i];
      m[axis] = 2.0 * settings.mirror.centre[axis] - m[axis];
      images.push_back(m);
    }
  }
  const auto weight = [&](const Eigen::Vector3d& x) {
    double w = 0.0;
    for (const Eigen::Vector3d& c : images)
      w = std::max(w, falloffWeight(settings.falloff, (x - c).norm(), settings.radius));
    return settings.strength * w;
  };
  std::string error;
  const long touched = model.paintMaterial(weight, settings.target, settings.fields, &error);
  if (touched < 0) throw std::invalid_argument("paint: " + error);
  return touched;
}

Material pickMaterial(const FemModel& model, const Eigen::Vector3d& rest) {
  if (!rest.allFinite()) throw std::invalid_argument("eyedropper: the position is not finite.");
  const FemMesh& mesh = model.mesh();
  if (mesh.gaussRestPosition.empty())
    throw std::invalid_argument("eyedropper: the model has no material samples.");
  size_t best = 0;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (size_t q = 0; q < mesh.gaussRestPosition.size(); ++q) {
    const double d = (mesh.gaussRestPosition[q] - rest).squaredNorm();
    if (d < bestDistance) {
      bestDistance = d;
      best = q;
    }
  }
  return mesh.gaussMaterial[best];
}

}  // namespace sculpt
