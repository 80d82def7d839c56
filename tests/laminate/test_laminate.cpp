// Laminate stiffness A, B, D, F and inertias (SPEC §2, (1.24), (1.25), (2.109)).
#include "plyimpact/laminate/laminate.hpp"
#include "plyimpact/laminate/layup.hpp"
#include "support/decks.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace plyimpact::laminate_tests {
namespace {

Laminate make(const std::string& layup, double t,
              ReducedStiffnessModel model = ReducedStiffnessModel::exact) {
  std::vector<Ply> plies;
  for (const double a : parse_layup(layup))
    plies.push_back({a, t, 0});
  return Laminate({test::t300_976()}, plies, 5.0 / 6.0, model);
}

/// x rounds to `ref` at 4 significant digits: |x − ref| ≤ half a unit of the 4th digit of ref.
::testing::AssertionResult four_digits(double x, double ref) {
  const double unit = std::pow(10.0, std::floor(std::log10(std::abs(ref))) - 3.0);
  if (std::abs(x - ref) <= 0.5 * unit) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << x << " vs " << ref;
}

TEST(Laminate, Annex2PlateHasTheSpecCheckValues) {
  const Laminate L = make("[0_2/90_4/0_2]", 0.465e-3);
  EXPECT_NEAR(L.thickness(), 3.72e-3, 1e-15);
  EXPECT_TRUE(four_digits(L.A()(0, 0), 2.8901e8));
  EXPECT_TRUE(four_digits(L.A()(1, 1), 2.8901e8));
  EXPECT_TRUE(four_digits(L.A()(0, 1), 1.0834e7));
  EXPECT_TRUE(four_digits(L.A()(2, 2), 2.6412e7));
  EXPECT_TRUE(four_digits(L.D()(0, 0), 552.02));
  EXPECT_TRUE(four_digits(L.D()(0, 1), 12.494));
  EXPECT_TRUE(four_digits(L.D()(1, 1), 114.56));
  EXPECT_TRUE(four_digits(L.D()(2, 2), 30.458));
  EXPECT_TRUE(four_digits(L.F()(0, 0), 2.0181e7));                             // F44 (yz)
  EXPECT_TRUE(four_digits(L.F()(1, 1), 2.0181e7));                             // F55 (xz)
  EXPECT_LE(L.B().cwiseAbs().maxCoeff(), 1e-14 * L.A()(0, 0) * L.thickness()); // B = 0 to round-off
}

TEST(Laminate, PoissonFreeSimplificationReproducesTheThesisAnnex2Print) {
  // Annex 2 prints A11 = 0.2873e9, A12 ≈ 0, D11 = 548.7, D22 = 113.9 (Q12 = 0, Q11 = E1, Q22 = E2).
  const Laminate L = make("[0_2/90_4/0_2]", 0.465e-3, ReducedStiffnessModel::poisson_free);
  EXPECT_TRUE(four_digits(L.A()(0, 0), 0.2873e9));
  EXPECT_NEAR(L.A()(0, 1), 0.0, 1e-12 * L.A()(0, 0));
  EXPECT_TRUE(four_digits(L.D()(0, 0), 548.7));
  EXPECT_TRUE(four_digits(L.D()(1, 1), 113.9));
}

TEST(Laminate, InertiasOfASingleMaterialPlate) {
  const Laminate L = make("[0_2/90_4/0_2]", 0.465e-3);
  const double h = 3.72e-3;
  EXPECT_NEAR(L.inertia()[0], 1389.2 * h, 1e-12);
  EXPECT_NEAR(L.inertia()[1], 0.0, 1e-18);
  EXPECT_NEAR(L.inertia()[2], 1389.2 * h * h * h / 12.0, 1e-15);
}

TEST(Laminate, InertiaCouplingI1OfTwoMaterialsHasTheSignOfTheHeavierLowerPly) {
  Material heavy = test::t300_976();
  heavy.name = "heavy";
  heavy.rho = 3000.0;
  const double t = 1e-3;
  const Laminate L({test::t300_976(), heavy}, {{0.0, t, 0}, {0.0, t, 1}}); // ply 2 (z > 0) is heavier
  EXPECT_NEAR(L.inertia()[1], (3000.0 - 1389.2) * t * t / 2.0, 1e-12);
}

TEST(Laminate, SymmetricLayupsHaveNoCouplingAndBalancedOnesNoA16A26) {
  for (const char* layup :
       {"[0_2/90_4/0_2]", "[45/90/-45/0]3s", "[0/±45/90]s", "[0/45/0/-45/0]2s", "[30/-30/60*]s"}) {
    const Laminate L = make(layup, 0.2e-3);
    EXPECT_TRUE(L.is_symmetric()) << layup << " B max " << L.B().cwiseAbs().maxCoeff();
    EXPECT_LE(L.B().cwiseAbs().maxCoeff(), 1e-12 * L.A().cwiseAbs().maxCoeff() * L.thickness()) << layup;
  }
  for (const char* layup : {"[45/90/-45/0]3s", "[0/±45/90]s", "[±30]", "[0_2/90_4/0_2]"})
    EXPECT_TRUE(make(layup, 0.2e-3).is_balanced()) << layup;
  EXPECT_FALSE(make("[45/0/45]", 0.2e-3).is_balanced());
  EXPECT_FALSE(make("[0/90]", 0.2e-3).is_symmetric());
}

TEST(Laminate, CrossPlyCouplingHasTheRightSign) {
  // [0/90]: ply 1 (0°) lies at z < 0, so B11 = −(Q11 − Q22) t²/2 = −B22, B12 = B66 = 0.
  const double t = 0.5e-3;
  const Laminate L = make("[0/90]", t);
  const Eigen::Matrix3d Q = reduced_stiffness(test::t300_976());
  const double expected = -(Q(0, 0) - Q(1, 1)) * t * t / 2.0;
  EXPECT_NEAR(L.B()(0, 0), expected, 1e-9 * std::abs(expected));
  EXPECT_NEAR(L.B()(1, 1), -expected, 1e-9 * std::abs(expected));
  EXPECT_NEAR(L.B()(0, 1), 0.0, 1e-9 * std::abs(expected));
  EXPECT_NEAR(L.B()(2, 2), 0.0, 1e-9 * std::abs(expected));
  EXPECT_NEAR(L.B()(0, 2), 0.0, 1e-9 * std::abs(expected));
}

TEST(Laminate, AnglePlyCouplingIsPureBendTwist) {
  // [45/−45]: Q̄16(±45°) = ±(Q11 − Q22)/4, so B16 = B26 = −(Q11 − Q22) t²/4 and all other B vanish.
  const double t = 0.5e-3;
  const Laminate L = make("[45/-45]", t);
  const Eigen::Matrix3d Q = reduced_stiffness(test::t300_976());
  const double expected = -(Q(0, 0) - Q(1, 1)) * t * t / 4.0;
  const double tol = 1e-9 * std::abs(expected);
  EXPECT_NEAR(L.B()(0, 2), expected, tol);
  EXPECT_NEAR(L.B()(1, 2), expected, tol);
  EXPECT_NEAR(L.B()(0, 0), 0.0, tol);
  EXPECT_NEAR(L.B()(1, 1), 0.0, tol);
  EXPECT_NEAR(L.B()(0, 1), 0.0, tol);
  EXPECT_NEAR(L.B()(2, 2), 0.0, tol);
}

TEST(Laminate, ThesisValidationPlateHas24PliesAnd465mm) {
  const Laminate L = make("[45/90/-45/0]3s", 0.19375e-3);
  EXPECT_EQ(L.ply_count(), 24U);
  EXPECT_NEAR(L.thickness(), 4.65e-3, 1e-15);
  EXPECT_NEAR(L.z_top(0), -2.325e-3, 1e-15);
  EXPECT_NEAR(L.z_bottom(23), 2.325e-3, 1e-15);
}

TEST(Laminate, EngineeringConstantsOfAUnidirectionalLaminateAreThePlyConstants) {
  const Laminate L = make("[0_4]", 0.25e-3);
  const auto e = L.engineering_constants();
  EXPECT_NEAR(e.Ex, 144.8e9, 1e-6 * 144.8e9);
  EXPECT_NEAR(e.Ey, 9.65e9, 1e-6 * 9.65e9);
  EXPECT_NEAR(e.Gxy, 7.10e9, 1e-6 * 7.10e9);
  EXPECT_NEAR(e.nuxy, 0.30, 1e-9);
}

TEST(HertzContact, ModifiedHertzConstantOfTheSpecCase) {
  // SPEC §4: R = 6.35 mm, Ei = 200 GPa, νi = 0.3, E2 = 9.65 GPa → k = 0.98218e9 N/m^1.5.
  EXPECT_TRUE(four_digits(hertz_constant(6.35e-3, 200e9, 0.3, 9.65e9), 0.98218e9));
  EXPECT_NEAR(hertz_constant(6.35e-3, 200e9, 0.3, 9.65e9), 0.98218e9, 0.00001e9);
}

} // namespace
} // namespace plyimpact::laminate_tests
