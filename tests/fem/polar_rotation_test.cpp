// polarRotation (core/fem/polar_rotation.h): F = R S with R a proper rotation, for ordinary,
// inverted and degenerate deformation gradients.

#include "fem/polar_rotation.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>

#include "support/mesh_builders.h"

namespace sculpt {
namespace {

using test::randomRotation;

double orthonormalityError(const Eigen::Matrix3d& R) {
  return (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
}

Eigen::Matrix3d randomSpd(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> uni(lo, hi);
  const Eigen::Matrix3d Q = randomRotation(rng);
  return Q * Eigen::Vector3d(uni(rng), uni(rng), uni(rng)).asDiagonal() * Q.transpose();
}

TEST(PolarRotation, RandomPositiveDeterminantGivesRotationAndSpdStretch) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n01;
  double worstOrtho = 0, worstSym = 0, minEig = 1e300;
  int tried = 0;
  while (tried < 1000) {
    Eigen::Matrix3d F;
    for (int i = 0; i < 9; ++i) F(i / 3, i % 3) = n01(rng);
    if (F.determinant() <= 1e-3) continue;
    ++tried;
    const Eigen::Matrix3d R = polarRotation(F);
    ASSERT_TRUE(R.allFinite());
    worstOrtho = std::max(worstOrtho, orthonormalityError(R));
    EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
    const Eigen::Matrix3d S = R.transpose() * F;
    worstSym = std::max(worstSym, (S - S.transpose()).cwiseAbs().maxCoeff() / S.norm());
    const Eigen::Vector3d eig =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(0.5 * (S + S.transpose())).eigenvalues();
    minEig = std::min(minEig, eig.minCoeff());
    EXPECT_GT(eig.minCoeff(), 0.0);
  }
  EXPECT_LT(worstOrtho, 1e-13);
  EXPECT_LT(worstSym, 1e-13);
  std::printf(
      "1000 random F (det > 0): max |R^T R - I| = %.3g, max asym(R^T F)/|F| = %.3g, "
      "min eigenvalue of S = %.3g\n",
      worstOrtho, worstSym, minEig);
}

TEST(PolarRotation, RecoversTheRotationOfRotationTimesStretch) {
  std::mt19937_64 rng(11);
  double worst = 0;
  for (int t = 0; t < 500; ++t) {
    const Eigen::Matrix3d Q = randomRotation(rng);
    // Stretches from strongly compressed to strongly stretched (condition number up to 1e3).
    const Eigen::Matrix3d S = randomSpd(rng, 0.01, 10.0);
    const Eigen::Matrix3d R = polarRotation(Q * S);
    worst = std::max(worst, (R - Q).cwiseAbs().maxCoeff());
  }
  // Large angles about coordinate axes (180 degrees included) with identity stretch.
  for (int axis = 0; axis < 3; ++axis)
    for (double angle :
         {0.5 * std::numbers::pi, std::numbers::pi, 1.5 * std::numbers::pi, -std::numbers::pi}) {
      const Eigen::Matrix3d Q =
          Eigen::AngleAxisd(angle, Eigen::Vector3d::Unit(axis)).toRotationMatrix();
      worst = std::max(worst, (polarRotation(Q) - Q).cwiseAbs().maxCoeff());
      const Eigen::Matrix3d S = Eigen::Vector3d(2.0, 0.5, 1.3).asDiagonal();
      worst = std::max(worst, (polarRotation(Q * S) - Q).cwiseAbs().maxCoeff());
    }
  EXPECT_LT(worst, 1e-12);
  std::printf("rotation * SPD: max |R - Q| = %.3g\n", worst);
}

TEST(PolarRotation, InvertedGradientGivesClosestProperRotation) {
  std::mt19937_64 rng(13);
  std::normal_distribution<double> n01;
  double worstOrtho = 0, worstSym = 0, worstLocal = 0;
  for (int t = 0; t < 500; ++t) {
    Eigen::Matrix3d F;
    for (int i = 0; i < 9; ++i) F(i / 3, i % 3) = n01(rng);
    if (F.determinant() > 0) F.col(0) = -F.col(0);  // make it inverted
    ASSERT_LT(F.determinant(), 0.0);
    const Eigen::Matrix3d R = polarRotation(F);
    ASSERT_TRUE(R.allFinite());
    EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
    worstOrtho = std::max(worstOrtho, orthonormalityError(R));
    const Eigen::Matrix3d S = R.transpose() * F;
    worstSym = std::max(worstSym, (S - S.transpose()).cwiseAbs().maxCoeff() / S.norm());
    // S = R^T F has exactly one negative eigenvalue, the one of smallest magnitude.
    const Eigen::Vector3d eig =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(0.5 * (S + S.transpose())).eigenvalues();
    EXPECT_LT(eig[0], 0.0);
    EXPECT_GT(eig[1], 0.0);
    EXPECT_LE(-eig[0], eig[1] * (1 + 1e-12));
    // Local optimality: R minimises |F - R|_F over SO(3) (no nearby rotation is closer).
    const double d0 = (F - R).norm();
    for (int k = 0; k < 20; ++k) {
      const Eigen::Vector3d w(1e-3 * n01(rng), 1e-3 * n01(rng), 1e-3 * n01(rng));
      const Eigen::Matrix3d Rk = R * Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix();
      worstLocal = std::max(worstLocal, d0 - (F - Rk).norm());
    }
  }
  EXPECT_LT(worstOrtho, 1e-13);
  EXPECT_LT(worstSym, 1e-13);
  EXPECT_LE(worstLocal, 1e-14);
  // A pure reflection: the singular values are all 1, any proper rotation with symmetric R^T F
  // is acceptable.
  const Eigen::Matrix3d mirror = Eigen::Vector3d(1, 1, -1).asDiagonal();
  const Eigen::Matrix3d Rm = polarRotation(mirror);
  EXPECT_NEAR(Rm.determinant(), 1.0, 1e-14);
  EXPECT_LT(orthonormalityError(Rm), 1e-14);
  const Eigen::Matrix3d Sm = Rm.transpose() * mirror;
  EXPECT_LT((Sm - Sm.transpose()).cwiseAbs().maxCoeff(), 1e-14);
  // A rotated, squashed-through element: F = Q diag(2, 1, -0.1) -> R = Q.
  const Eigen::Matrix3d Q = randomRotation(rng);
  const Eigen::Matrix3d Rq = polarRotation(Q * Eigen::Vector3d(2, 1, -0.1).asDiagonal());
  EXPECT_LT((Rq - Q).cwiseAbs().maxCoeff(), 1e-13);
  std::printf(
      "inverted F: max |R^T R - I| = %.3g, max asym = %.3g, best local improvement = "
      "%.3g\n",
      worstOrtho, worstSym, worstLocal);
}

TEST(PolarRotation, DegenerateAndNonFiniteInputsGiveFiniteRotations) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  Eigen::Matrix3d withNan = Eigen::Matrix3d::Identity();
  withNan(1, 2) = nan;
  Eigen::Matrix3d withInf = Eigen::Matrix3d::Identity();
  withInf(0, 0) = inf;
  Eigen::Matrix3d rankOne = Eigen::Vector3d(1, 2, 3) * Eigen::RowVector3d(0.5, -1, 2);
  Eigen::Matrix3d flat = Eigen::Vector3d(1, 1, 0).asDiagonal();
  for (const Eigen::Matrix3d& F :
       {Eigen::Matrix3d(Eigen::Matrix3d::Zero()), withNan, withInf, rankOne, flat}) {
    const Eigen::Matrix3d R = polarRotation(F);
    ASSERT_TRUE(R.allFinite()) << F;
    EXPECT_NEAR(R.determinant(), 1.0, 1e-12) << F;
    EXPECT_LT(orthonormalityError(R), 1e-12) << F;
  }
  // A flat element keeps its in-plane rotation: F = Q diag(1, 1, 0) -> R = Q.
  std::mt19937_64 rng(17);
  const Eigen::Matrix3d Q = randomRotation(rng);
  EXPECT_LT((polarRotation(Q * flat) - Q).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(PolarRotation, WarmStartFromANearbyOrFarGuessGivesTheColdResult) {
  // The per-step kernel starts from last step's rotation: near guesses (small rotations away),
  // far ones (half turns), inverted and degenerate F must all give polarRotation(F).
  std::mt19937_64 rng(2026);
  std::normal_distribution<double> small(0.0, 0.05);
  double worst = 0.0;
  for (int k = 0; k < 20000; ++k) {
    const Eigen::Matrix3d R = randomRotation(rng);
    Eigen::Matrix3d F = R * randomSpd(rng, 0.5, 2.0);
    if (k % 10 == 7) F.col(0) = -F.col(0);  // inverted
    const Eigen::Matrix3d cold = polarRotation(F);
    const Eigen::Matrix3d nearGuess =
        cold * Eigen::AngleAxisd(std::abs(small(rng)),
                                 Eigen::Vector3d(small(rng), 1.0, small(rng)).normalized())
                   .toRotationMatrix();
    const Eigen::Matrix3d farGuess =
        cold *
        Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d(1.0, small(rng), 0.0).normalized())
            .toRotationMatrix();
    for (const Eigen::Matrix3d& guess :
         {nearGuess, farGuess, Eigen::Matrix3d(Eigen::Matrix3d::Identity())}) {
      const Eigen::Matrix3d warm = polarRotation(F, guess);
      worst = std::max(worst, (warm - cold).cwiseAbs().maxCoeff());
      ASSERT_LT((warm - cold).cwiseAbs().maxCoeff(), 1e-12) << "F\n" << F << "\nguess\n" << guess;
    }
  }
  std::printf("warm-started polar rotation: max |R_warm - R_cold| = %.3g over 60000 cases\n",
              worst);
  for (const Eigen::Matrix3d& F : {Eigen::Matrix3d(Eigen::Matrix3d::Zero()),
                                   Eigen::Matrix3d(Eigen::Vector3d(1, 1, 0).asDiagonal())}) {
    const Eigen::Matrix3d warm = polarRotation(F, Eigen::Matrix3d::Identity());
    ASSERT_TRUE(warm.allFinite());
    EXPECT_LT((warm - polarRotation(F)).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(PolarRotation, FourAtOnceEqualOneAtATimeWhateverTheOtherLanesDo) {
  // The element pass solves four rotations in the lanes of a vector; a lane that leaves the
  // warm path (far guess, inverted or degenerate F, NaN) must not disturb its neighbours.
  std::mt19937_64 rng(77);
  std::normal_distribution<double> small(0.0, 0.02);
  double worst = 0.0;
  for (int k = 0; k < 5000; ++k) {
    Eigen::Matrix3d F[4], guess[4], batch[4];
    for (int l = 0; l < 4; ++l) {
      F[l] = randomRotation(rng) * randomSpd(rng, 0.5, 2.0);
      const Eigen::Matrix3d cold = polarRotation(F[l]);
      guess[l] = cold * Eigen::AngleAxisd(std::abs(small(rng)),
                                          Eigen::Vector3d(small(rng), 1.0, small(rng)).normalized())
                            .toRotationMatrix();
      switch ((k + l) % 9) {
        case 1: guess[l] = -guess[l]; break;        // far (an improper guess, half turns away)
        case 2: F[l].col(0) = -F[l].col(0); break;  // inverted
        case 3: F[l].col(2).setZero(); break;       // degenerate
        case 4: F[l](1, 1) = std::numeric_limits<double>::quiet_NaN(); break;
        case 5: guess[l] = F[l]; break;             // the guess is a stretch, not a rotation
        default: break;
      }
    }
    const int count = 1 + k % 4;
    polarRotations(F, guess, count, batch);
    for (int l = 0; l < count; ++l) {
      const Eigen::Matrix3d single = polarRotation(F[l], guess[l]);
      ASSERT_TRUE(batch[l].allFinite());
      if (!F[l].allFinite()) {
        EXPECT_EQ(batch[l], single);
        continue;
      }
      worst = std::max(worst, (batch[l] - single).cwiseAbs().maxCoeff());
      ASSERT_LT((batch[l] - single).cwiseAbs().maxCoeff(), 1e-14)
          << "case " << (k + l) % 9 << " lane " << l << " of " << count;
    }
  }
  std::printf("four polar rotations at once: max |R_batch - R_single| = %.3g\n", worst);
}

}  // namespace
}  // namespace sculpt
