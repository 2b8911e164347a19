// The convergence experiment of James 2020 (Fig. 10) with this program's deformer: fitted error
// slopes against the mean edge length, for interior and surface test cells, tets and hexes.

#include <gtest/gtest.h>

#include <cstdio>

#include "embed/interpolation_study.h"

namespace sculpt {
namespace {

const double kSpacings[] = {0.1, 0.05, 0.025, 0.0125, 0.00625};

void print(const ConvergenceSeries& series) {
  for (const ConvergenceRow& row : series.rows)
    std::printf("h=%.4f edge=%.4f linear=%.3e vertex=%.3e phong=%.3e attribute=%.3e\n",
                row.spacing, row.meanEdge, row.errors.max[0], row.errors.max[1],
                row.errors.max[2], row.errors.max[3]);
  std::printf("slopes linear=%.3f vertex=%.3f phong=%.3f attribute=%.3f\n", series.slopes[0],
              series.slopes[1], series.slopes[2], series.slopes[3]);
}

TEST(PhongConvergence, InteriorTetrahedra) {
  const ConvergenceSeries series =
      runConvergenceStudy(StudyCells::Tetrahedra, StudyPlacement::Interior, kSpacings);
  print(series);
  EXPECT_GE(series.slopes[2], 2.7);                       // phong
  EXPECT_GE(series.slopes[0], 1.9);                       // linear
  EXPECT_LE(series.slopes[0], 2.1);
  EXPECT_LE(series.slopes[3], 1.3);                       // attribute
}

TEST(PhongConvergence, InteriorHexahedra) {
  const ConvergenceSeries series =
      runConvergenceStudy(StudyCells::Hexahedra, StudyPlacement::Interior, kSpacings);
  print(series);
  EXPECT_GE(series.slopes[2], 2.7);
  EXPECT_GE(series.slopes[0], 1.9);
  EXPECT_LE(series.slopes[0], 2.1);
  EXPECT_LE(series.slopes[3], 1.3);
}

TEST(PhongConvergence, SurfaceCells) {
  for (StudyCells cells : {StudyCells::Tetrahedra, StudyCells::Hexahedra}) {
    const ConvergenceSeries series = runConvergenceStudy(cells, StudyPlacement::Surface, kSpacings);
    print(series);
    // Missing neighbours above degrade the node gradients: second order, still below linear.
    EXPECT_GE(series.slopes[2], 1.8);
    for (const ConvergenceRow& row : series.rows) EXPECT_LT(row.errors.max[2], row.errors.max[0]);
  }
}

}  // namespace
}  // namespace sculpt
