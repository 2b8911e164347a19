// Phong vs linear interpolation of regularized Kelvinlets on regular and jittered tet lattices:
// the error ratio grows as the mesh resolves the brush (docs/design/phong-deformation.md:
// about 1.75x at h/eps = 0.5, 4x at 0.25, 12x at 0.125).

#include <gtest/gtest.h>

#include <cstdio>

#include "embed/interpolation_study.h"

namespace sculpt {
namespace {

TEST(KelvinletStudy, PhongBeatsLinearMoreAsTheMeshResolvesTheBrush) {
  const double ratios[] = {0.5, 0.25, 0.125};
  for (bool jittered : {false, true}) {
    const std::vector<KelvinletRow> rows = runKelvinletStudy(ratios, jittered);
    for (const KelvinletRow& row : rows)
      std::printf("%s %s h/eps=%.3f rms linear=%.3e phong=%.3e ratio=%.2f  max ratio=%.2f\n",
                  jittered ? "jittered" : "regular", brushName(row.brush), row.spacingOverEps,
                  row.errors.rms[0], row.errors.rms[2], row.rmsRatio, row.maxRatio);
    for (size_t i = 0; i < rows.size(); ++i) {
      EXPECT_GT(rows[i].rmsRatio, 1.2) << brushName(rows[i].brush) << ' ' << rows[i].spacingOverEps;
      if (i >= 3) {
        EXPECT_GT(rows[i].rmsRatio, rows[i - 3].rmsRatio * 1.5);  // same brush, finer mesh
      }
      if (rows[i].spacingOverEps == 0.125) {
        EXPECT_GT(rows[i].rmsRatio, 6.0);
      }
    }
  }
}

}  // namespace
}  // namespace sculpt
