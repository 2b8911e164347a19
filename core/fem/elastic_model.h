#pragma once
// Which elastic energy the elements use (docs/fem.md, "The inversion barrier").
//
// Corotated is the paper's co-rotated linear elasticity (section 3.3): quadratic in the rotated
// strain, so a large enough load can push a Gauss point through zero volume (det F <= 0) and the
// element then tangles. Barrier adds, at every Gauss point, an energy that is zero while the
// point keeps at least `threshold` of its rest volume and grows with the cube of the shortfall
//     psi(J) = stiffness * k * max(0, threshold - J)^3 / threshold,   J = det F,
// k = V (lambda + 2 mu / 3) the point's bulk modulus times its volume. It leaves every state with
// J >= threshold unchanged (the CalculiX comparisons, the patch tests) and pushes a compressed
// or inverted point back with a force that grows as it is squeezed: in an inverted state too,
// where psi keeps rising as J falls, so an element that was turned inside out is turned back.

#include <optional>
#include <string>

namespace sculpt {

enum class ElasticModel {
  Corotated,  ///< the paper's co-rotated linear elasticity
  Barrier,    ///< the same with the inversion barrier (the default)
};
inline constexpr ElasticModel kDefaultElasticModel = ElasticModel::Barrier;

const char* elasticModelName(ElasticModel model);  ///< "corotated", "barrier"
std::optional<ElasticModel> parseElasticModel(const std::string& name);

struct InversionBarrier {
  double threshold = 0.5;  ///< J below which the barrier acts (half the rest volume)
  double stiffness = 10.0;  ///< in units of the bulk modulus, see above
  /// false (the solvers): the Hessian keeps only psi'' cof(F) (x) cof(F), which is positive
  /// semi-definite so that CG stays applicable, and drops psi' d cof(F), which is not. true: the
  /// exact second derivative (the finite-difference tests).
  bool exactHessian = false;
};

}  // namespace sculpt
