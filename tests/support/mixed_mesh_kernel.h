#pragma once
// The fixture of the elastic-kernel tests: a level-2 model of the jittered mixed mesh (all three
// element types), its typical element size L_, a configuration x0_ for the derived test to set,
// and the kernel's gradient and Hessian products on their own.

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "fem/fem_model.h"
#include "support/fem_builders.h"
#include "support/mesh_builders.h"

namespace sculpt::test {

class MixedMeshKernelTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string error;
    model_ =
        FemModel::create(jittered(mixedMesh(), 0.05, 8), FemSetup{2, false, Material{}}, &error);
    ASSERT_TRUE(model_) << error;
    const ElementCounts c = model_->mesh().counts();
    ASSERT_GT(c.tricubic, 0u);
    ASSERT_GT(c.trilinear, 0u);
    ASSERT_GT(c.pyramid, 0u);
    L_ = std::cbrt(model_->mesh().restVolume() / model_->mesh().numElements());
  }
  Points gradient(const Points& x) const { return kernelGradient(model_->elastic(), x); }
  Points hessianProduct(const Points& v) const {
    return kernelHessianProduct(model_->elastic(), v);
  }
  std::optional<FemModel> model_;
  Points x0_;
  double L_ = 0;
};

}  // namespace sculpt::test
