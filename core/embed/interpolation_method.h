#pragma once
// The four ways of moving an embedded point with its cell mesh, all on the same data.

#include <optional>
#include <string_view>

namespace sculpt {

enum class InterpolationMethod {
  Linear,     ///< f_C: barycentric (tetrahedra) or trilinear (hexahedra) interpolation of nodes
  Vertex,     ///< f_V: interpolated per-node linear models x_i + F_i (X - X_i)
  Phong,      ///< Phong Deformation: the same with half-gradients, (f_C + f_V) / 2
  Attribute,  ///< metaball-weighted node displacements within a radius (Houdini's Point Deform)
};

/// The weight alpha of the node gradients in sum_i beta_i (x_i + alpha F_i (X - X_i)):
/// 0 for linear, 1/2 for Phong, 1 for the vertex model. Not defined for Attribute (returns 0).
inline double gradientBlend(InterpolationMethod method) {
  switch (method) {
    case InterpolationMethod::Phong: return 0.5;
    case InterpolationMethod::Vertex: return 1.0;
    default: return 0.0;
  }
}

inline std::string_view methodName(InterpolationMethod method) {
  switch (method) {
    case InterpolationMethod::Linear: return "linear";
    case InterpolationMethod::Vertex: return "vertex";
    case InterpolationMethod::Phong: return "phong";
    case InterpolationMethod::Attribute: return "attribute";
  }
  return "?";
}

inline std::optional<InterpolationMethod> parseInterpolationMethod(std::string_view name) {
  for (auto method : {InterpolationMethod::Linear, InterpolationMethod::Vertex,
                      InterpolationMethod::Phong, InterpolationMethod::Attribute})
    if (methodName(method) == name) return method;
  return std::nullopt;
}

}  // namespace sculpt
