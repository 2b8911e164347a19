// The convergence experiment of James 2020 (Fig. 10) with this program's deformer: fitted error
// slopes against the mean edge length, for interior, surface and corner test cells, tets and hexes,
// with the paper's averaged node gradients and with the quadratic fit.

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
      runConvergenceStudy(StudyCells::Tetrahedra, StudyPlacement::Interior, kSpacings,
                          GradientScheme::Average);
  print(series);
  EXPECT_GE(series.slopes[2], 2.7);                       // phong
  EXPECT_GE(series.slopes[0], 1.9);                       // linear
  EXPECT_LE(series.slopes[0], 2.1);
  EXPECT_LE(series.slopes[3], 1.3);                       // attribute
}

TEST(PhongConvergence, InteriorHexahedra) {
  const ConvergenceSeries series =
      runConvergenceStudy(StudyCells::Hexahedra, StudyPlacement::Interior, kSpacings,
                          GradientScheme::Average);
  print(series);
  EXPECT_GE(series.slopes[2], 2.7);
  EXPECT_GE(series.slopes[0], 1.9);
  EXPECT_LE(series.slopes[0], 2.1);
  EXPECT_LE(series.slopes[3], 1.3);
}

TEST(PhongConvergence, SurfaceCells) {
  for (StudyCells cells : {StudyCells::Tetrahedra, StudyCells::Hexahedra}) {
    const ConvergenceSeries series =
        runConvergenceStudy(cells, StudyPlacement::Surface, kSpacings, GradientScheme::Average);
    print(series);
    // Missing neighbours above degrade the averaged node gradients: second order, still below
    // linear.
    EXPECT_GE(series.slopes[2], 1.8);
    for (const ConvergenceRow& row : series.rows) EXPECT_LT(row.errors.max[2], row.errors.max[0]);
  }
}

TEST(PhongConvergence, QuadraticFitGradientsKeepThirdOrderInSurfaceAndCornerCells) {
  for (StudyCells cells : {StudyCells::Tetrahedra, StudyCells::Hexahedra}) {
    for (StudyPlacement placement :
         {StudyPlacement::Interior, StudyPlacement::Surface, StudyPlacement::Corner}) {
      const ConvergenceSeries fit =
          runConvergenceStudy(cells, placement, kSpacings, GradientScheme::Fit);
      const ConvergenceSeries average =
          runConvergenceStudy(cells, placement, kSpacings, GradientScheme::Average);
      print(fit);
      const double finestFit = fit.rows.back().errors.max[2];
      const double finestAverage = average.rows.back().errors.max[2];
      std::printf("[ measured ] %s %d: phong slope fit %.2f average %.2f; finest h error fit "
                  "%.2e average %.2e (%.1fx)\n",
                  cells == StudyCells::Tetrahedra ? "tets" : "hexes", static_cast<int>(placement),
                  fit.slopes[2], average.slopes[2], finestFit, finestAverage,
                  finestAverage / finestFit);
      EXPECT_GE(fit.slopes[2], 2.7);
      if (placement != StudyPlacement::Interior) {
        EXPECT_GE(finestAverage, 10.0 * finestFit);
      }
      // The linear column does not depend on the node gradients.
      EXPECT_EQ(fit.rows.back().errors.max[0], average.rows.back().errors.max[0]);
    }
  }
}

}  // namespace
}  // namespace sculpt
