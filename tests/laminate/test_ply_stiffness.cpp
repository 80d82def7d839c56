// Ply stiffness: Q from (1.3), Q̄ from (1.12) with the SPEC §2 corrections.
#include "plyimpact/laminate/ply_stiffness.hpp"
#include "support/decks.hpp"

#include <Eigen/LU>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace plyimpact::ply_stiffness_tests {
namespace {

TEST(PlyStiffness, ReducedStiffnessMatchesHandCalculation) {
  const Material m = test::t300_976();
  const Eigen::Matrix3d Q = reduced_stiffness(m);
  const double nu21 = 0.30 * 9.65 / 144.8; // 0.019993
  const double d = 1.0 - 0.30 * nu21;
  EXPECT_NEAR(Q(0, 0), 144.8e9 / d, 1.0);
  EXPECT_NEAR(Q(1, 1), 9.65e9 / d, 1.0);
  EXPECT_NEAR(Q(0, 1), 0.30 * 9.65e9 / d, 1.0);
  EXPECT_EQ(Q(2, 2), 7.10e9);
  EXPECT_EQ(Q(0, 2), 0.0);
}

TEST(PlyStiffness, ZeroDegreeRotationIsIdentity) {
  const Eigen::Matrix3d Q = reduced_stiffness(test::t300_976());
  EXPECT_LT((rotate_in_plane(Q, 0.0) - Q).norm(), 1e-6 * Q.norm());
  const Eigen::Matrix2d G = transverse_shear_stiffness(test::t300_976());
  EXPECT_LT((rotate_transverse_shear(G, 0.0) - G).norm(), 1e-6 * G.norm());
}

TEST(PlyStiffness, NinetyDegreesSwapsFibreAndTransverseDirections) {
  const Eigen::Matrix3d Q = reduced_stiffness(test::t300_976());
  const Eigen::Matrix3d Qb = rotate_in_plane(Q, 90.0);
  const double tol = 1e-9 * Q(0, 0);
  EXPECT_NEAR(Qb(0, 0), Q(1, 1), tol);
  EXPECT_NEAR(Qb(1, 1), Q(0, 0), tol);
  EXPECT_NEAR(Qb(0, 1), Q(0, 1), tol);
  EXPECT_NEAR(Qb(2, 2), Q(2, 2), tol);
  EXPECT_NEAR(Qb(0, 2), 0.0, tol);
  EXPECT_NEAR(Qb(1, 2), 0.0, tol);
  const Eigen::Matrix2d G = transverse_shear_stiffness(test::t300_976());
  const Eigen::Matrix2d Gb = rotate_transverse_shear(G, 90.0);
  EXPECT_NEAR(Gb(0, 0), G(1, 1), 1e-6); // Q̄44(90°) = Q55
  EXPECT_NEAR(Gb(1, 1), G(0, 0), 1e-6); // Q̄55(90°) = Q44
  EXPECT_NEAR(Gb(0, 1), 0.0, 1e-6);
}

TEST(PlyStiffness, RotationInvariantsAreAngleIndependent) {
  // Q̄11 + Q̄22 + 2Q̄12 and Q̄66 − Q̄12 are invariants of the plane-stress stiffness (Tsai–Pagano);
  // Q̄44 + Q̄55 and det Q̄s are invariants of the transverse shear stiffness.
  const Eigen::Matrix3d Q = reduced_stiffness(test::t300_976());
  const Eigen::Matrix2d G = transverse_shear_stiffness(test::t300_976());
  const double I1 = Q(0, 0) + Q(1, 1) + 2 * Q(0, 1);
  const double I2 = Q(2, 2) - Q(0, 1);
  for (double deg = -180.0; deg <= 180.0; deg += 7.5) {
    const Eigen::Matrix3d Qb = rotate_in_plane(Q, deg);
    EXPECT_NEAR(Qb(0, 0) + Qb(1, 1) + 2 * Qb(0, 1), I1, 1e-12 * I1) << deg;
    EXPECT_NEAR(Qb(2, 2) - Qb(0, 1), I2, 1e-9 * I1) << deg;
    const Eigen::Matrix2d Gb = rotate_transverse_shear(G, deg);
    EXPECT_NEAR(Gb.trace(), G.trace(), 1e-12 * G.trace()) << deg;
    EXPECT_NEAR(Gb.determinant(), G.determinant(), 1e-12 * G.determinant()) << deg;
  }
}

TEST(PlyStiffness, RotatedStiffnessEqualsTensorTransformation) {
  // Independent check of (1.12): Q̄ = T⁻¹ Q T⁻ᵀ with engineering-strain Reuter matrix (strain energy
  // invariance: εᵀ Q̄ ε in plate axes equals ε'ᵀ Q ε' in material axes).
  const Eigen::Matrix3d Q = reduced_stiffness(test::t300_976());
  for (const double deg : {15.0, 30.0, 45.0, 60.0, -45.0, 110.0}) {
    const double c = std::cos(deg * std::numbers::pi / 180.0), s = std::sin(deg * std::numbers::pi / 180.0);
    Eigen::Matrix3d Te; // engineering strains plate → material axes
    Te << c * c, s * s, c * s, s * s, c * c, -c * s, -2 * c * s, 2 * c * s, c * c - s * s;
    const Eigen::Matrix3d expected = Te.transpose() * Q * Te;
    EXPECT_LT((rotate_in_plane(Q, deg) - expected).norm(), 1e-12 * Q.norm()) << deg;
  }
}

TEST(PlyStiffness, QuarterTurnsAreExact) {
  EXPECT_EQ(cos_sin_degrees(90.0).c, 0.0);
  EXPECT_EQ(cos_sin_degrees(-90.0).s, -1.0);
  EXPECT_EQ(cos_sin_degrees(270.0).s, -1.0);
  EXPECT_EQ(cos_sin_degrees(180.0).c, -1.0);
  EXPECT_NEAR(cos_sin_degrees(30.0).s, 0.5, 1e-16);
}

TEST(PlyStiffness, PoissonFreeModelIsWhatTheThesisProgramUsed) {
  const Eigen::Matrix3d Q = reduced_stiffness(test::t300_976(), ReducedStiffnessModel::poisson_free);
  EXPECT_EQ(Q(0, 0), 144.8e9);
  EXPECT_EQ(Q(1, 1), 9.65e9);
  EXPECT_EQ(Q(0, 1), 0.0);
}

} // namespace
} // namespace plyimpact::ply_stiffness_tests
