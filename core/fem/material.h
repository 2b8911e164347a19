#pragma once
// Material samples painted through the volume (paper section 3.2.1): density, damping, Young's
// modulus and Poisson ratio at each Gauss point of each element.

#include <string>

namespace sculpt {

struct Material {
  double density = 1000.0;  ///< kg/m^3 (mu of the paper)
  double damping = 0.0;     ///< kg/(m^3 s): damping density gamma, D = integral gamma N^T N
  double youngs = 1.0e5;    ///< Pa
  double poisson = 0.3;     ///< in (-1, 0.5)
  bool operator==(const Material&) const = default;  ///< by value (0.0 == -0.0)
};

struct LameParameters {
  double lambda = 0.0;  ///< Pa
  double mu = 0.0;      ///< Pa (shear modulus)
};

/// Isotropic Lame parameters of eq. 6's C(E, nu).
LameParameters lameParameters(const Material& material);

/// Empty when usable; otherwise a sentence naming the bad field and value (negative density,
/// E <= 0, nu outside (-1, 0.5), anything not finite).
std::string materialProblem(const Material& material);

}  // namespace sculpt
