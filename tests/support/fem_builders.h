#pragma once
// Helpers shared by the FEM and simulation tests: building a model (failing the test with the
// reason when that is impossible), the bundled 3x3x3 block, random point sets.

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <random>
#include <string>

#include "fem/fem_model.h"
#include "io/control_mesh_json.h"

namespace sculpt::test {

/// The model of `control`, or nullptr after a failed expectation naming the reason.
inline std::unique_ptr<FemModel> buildModel(const CellComplex& control, const FemSetup& setup) {
  std::string error;
  auto model = FemModel::create(control, setup, &error);
  EXPECT_TRUE(model.has_value()) << error;
  if (!model) return nullptr;
  return std::make_unique<FemModel>(std::move(*model));
}

inline std::unique_ptr<FemModel> buildModel(const CellComplex& control, int level,
                                            bool trilinear) {
  FemSetup setup;
  setup.level = level;
  setup.trilinear = trilinear;
  return buildModel(control, setup);
}

/// assets/block3.json: 3x3x3 unit control cells.
inline CellComplex block3() {
  return loadControlMeshJson(std::filesystem::path(SCULPT_SOURCE_DIR) / "assets" / "block3.json");
}

/// rows x 3 values uniform in [-amplitude, amplitude].
/// The elastic kernel's gradient at x, and its Hessian applied to v, on their own.
inline Points kernelGradient(const ElasticKernel& kernel, const Points& x) {
  Points g = Points::Zero(x.rows(), 3);
  kernel.addGradient(x, g);
  return g;
}
inline Points kernelHessianProduct(const ElasticKernel& kernel, const Points& v) {
  Points h = Points::Zero(v.rows(), 3);
  kernel.addHessianProduct(v, h);
  return h;
}
/// The sum of the entrywise products (the dot product of the flattened arrays).
inline double dot(const Points& a, const Points& b) { return (a.array() * b.array()).sum(); }

inline Points randomPoints(Eigen::Index rows, double amplitude, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> uni(-amplitude, amplitude);
  Points p(rows, 3);
  for (Eigen::Index i = 0; i < rows; ++i)
    for (int d = 0; d < 3; ++d) p(i, d) = uni(rng);
  return p;
}

}  // namespace sculpt::test
