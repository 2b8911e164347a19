#pragma once
// How node deformation gradients F_i are reconstructed from the deformed nodes.

#include <optional>
#include <string_view>

#include "embed/deformation_gradients.h"
#include "mesh/volume_mesh.h"

namespace sculpt {

enum class GradientScheme {
  Average,  ///< James 2020 eq. 12: weighted average of the cell gradients around the node
  Fit,      ///< gradient of a quadratic least-squares fit of the nodes around it (docs/phong.md)
};

/// The scheme used where none is chosen: the fit, which is third-order accurate in surface cells
/// as well as inside (docs/phong-study/phong-study.md).
inline constexpr GradientScheme kDefaultGradientScheme = GradientScheme::Fit;

std::string_view gradientSchemeName(GradientScheme scheme);  ///< "average", "fit"
std::optional<GradientScheme> parseGradientScheme(std::string_view name);

/// The node-gradient stencil of `scheme` for `rest`; `eps` regularises the averaging weights
/// (the fit's fallback included).
NodeGradientStencil nodeGradientStencil(const VolumeMesh& rest, GradientScheme scheme,
                                        double eps = 1.0);

}  // namespace sculpt
