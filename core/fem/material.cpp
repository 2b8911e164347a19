#include "fem/material.h"

#include <cmath>

namespace sculpt {

LameParameters lameParameters(const Material& m) {
  const double E = m.youngs, nu = m.poisson;
  return {E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), E / (2.0 * (1.0 + nu))};
}

std::string materialProblem(const Material& m) {
  auto bad = [](const char* what, double value, const char* expected) {
    return std::string(what) + " = " + std::to_string(value) + " (expected " + expected + ")";
  };
  if (!std::isfinite(m.density) || m.density <= 0) return bad("density", m.density, "> 0 kg/m^3");
  if (!std::isfinite(m.damping) || m.damping < 0) return bad("damping", m.damping, ">= 0");
  if (!std::isfinite(m.youngs) || m.youngs <= 0) return bad("Young's modulus", m.youngs, "> 0 Pa");
  if (!std::isfinite(m.poisson) || m.poisson <= -1.0 || m.poisson >= 0.5)
    return bad("Poisson ratio", m.poisson, "in (-1, 0.5)");
  return {};
}

}  // namespace sculpt
