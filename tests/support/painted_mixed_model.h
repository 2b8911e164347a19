#pragma once
// A model whose materials vary between the Gauss points of its elements, on every element kind:
// for checks of matrices assembled from painted materials.

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "support/fem_builders.h"
#include "support/mesh_builders.h"

namespace sculpt::test {

/// The jittered mixed mesh at K = 2 (tricubic, trilinear and pyramid elements, none of them
/// affine), with `painted` in a ball of radius 0.6 at its centre.
inline std::unique_ptr<FemModel> paintedMixedModel(const Material& painted) {
  auto model = buildModel(jittered(mixedMesh(), 0.05, 8), 2, false);
  if (!model) return nullptr;
  const Eigen::Vector3d centre = model->restControl().colwise().mean().transpose();
  EXPECT_GT(model->paintMaterial(centre, 0.6, painted), 0);
  const FemMesh& mesh = model->mesh();
  EXPECT_GT(mesh.numTricubic(), 0u);
  EXPECT_GT(std::count(mesh.elementType.begin(), mesh.elementType.end(), ElementType::Pyramid), 0);
  return model;
}

}  // namespace sculpt::test
