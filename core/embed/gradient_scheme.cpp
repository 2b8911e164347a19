#include "embed/gradient_scheme.h"

#include "embed/gradient_fit.h"
#include "embed/gradient_weights.h"

namespace sculpt {

std::string_view gradientSchemeName(GradientScheme scheme) {
  return scheme == GradientScheme::Fit ? "fit" : "average";
}

std::optional<GradientScheme> parseGradientScheme(std::string_view name) {
  for (auto scheme : {GradientScheme::Average, GradientScheme::Fit})
    if (gradientSchemeName(scheme) == name) return scheme;
  return std::nullopt;
}

NodeGradientStencil nodeGradientStencil(const VolumeMesh& rest, GradientScheme scheme, double eps) {
  NodeGradientStencil average =
      nodeGradientStencil(rest, cellGradientOperator(rest), cellToNodeWeights(rest, eps));
  if (scheme == GradientScheme::Average) return average;
  return quadraticFitStencil(rest, average);
}

}  // namespace sculpt
