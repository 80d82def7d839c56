// The fracture-plane criterion (laminate/fracture_plane.hpp): the uniaxial and pure-shear states crack at
// their strengths on the planes the construction of ST, ηT, ηL says (α0 under transverse compression — the
// closed forms FP3–FP5 are built so that the index's slope in α vanishes there), and the search finds the
// largest index a fine scan of the angles finds.
#include "plyimpact/laminate/fracture_plane.hpp"
#include "support/decks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace plyimpact::fracture_plane_tests {
namespace {

constexpr double degree = std::numbers::pi / 180.0;

FracturePlaneStrengths card(double alpha0 = 53.0 * degree) {
  return fracture_plane_strengths(test::t700_m21_tan2015().strength, alpha0);
}

TEST(FracturePlane, TransverseTensionAtYtCracksThePlaneAcrossTheThickness) {
  const FracturePlaneStrengths f = card();
  const FracturePlane p = critical_fracture_plane({f.Yt, 0.0}, f);
  EXPECT_NEAR(p.index, 1.0, 1e-12);
  EXPECT_NEAR(p.angle, 0.0, 1e-6);
}

TEST(FracturePlane, PureInPlaneShearAtS12CracksThePlaneAcrossTheThickness) {
  const FracturePlaneStrengths f = card();
  const FracturePlane p = critical_fracture_plane({0.0, f.SL}, f);
  EXPECT_NEAR(p.index, 1.0, 1e-12);
  EXPECT_NEAR(p.angle, 0.0, 1e-6);
}

TEST(FracturePlane, TransverseCompressionAtYcCracksThePlaneAtAlpha0) {
  for (const double alpha0 : {50.0 * degree, 53.0 * degree, 56.0 * degree}) {
    const FracturePlaneStrengths f = card(alpha0);
    const FracturePlane p = critical_fracture_plane({-f.Yc, 0.0}, f);
    EXPECT_NEAR(p.index, 1.0, 1e-10) << alpha0 / degree;
    EXPECT_NEAR(p.angle, alpha0, 2e-4) << alpha0 / degree; // the index is flat at its maximum
    // Below Yc no plane cracks.
    EXPECT_LT(critical_fracture_plane({-0.99 * f.Yc, 0.0}, f).index, 1.0) << alpha0 / degree;
  }
}

TEST(FracturePlane, TheCardsTransverseShearStrengthAndFrictionCoefficients) {
  // T700/M21, Yc = 290 MPa, S12 = 110 MPa, α0 = 53°, by hand: cos α0 = 0.601815, sin α0 = 0.798636,
  // tan 2α0 = tan 106° = −3.487414; ST = 290 · 0.601815 · (0.798636 − 0.172568) = 109.27 MPa,
  // ηT = 1/3.487414 = 0.28675, ηL = 110 · 0.275637 / (290 · 0.362181) = 0.28867.
  const FracturePlaneStrengths f = card();
  EXPECT_NEAR(f.ST, 109.27e6, 0.01e6);
  EXPECT_NEAR(f.eta_T, 0.28675, 1e-5);
  EXPECT_NEAR(f.eta_L, 0.28867, 1e-5);
}

TEST(FracturePlane, TheSearchFindsTheLargestIndexOfAFineScan) {
  const FracturePlaneStrengths f = card();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    const bool transverse_shear = trial % 2 == 1;
    const MatrixStress s{u(rng) * f.Yc, u(rng) * f.SL, transverse_shear ? u(rng) * f.ST : 0.0,
                         transverse_shear ? u(rng) * f.SL : 0.0};
    double scanned = 0.0;
    for (int i = -9000; i <= 9000; ++i) // every 0.01°
      scanned = std::max(scanned, fracture_plane_index(tractions_on_plane(s, i * 0.01 * degree), f));
    const FracturePlane p = critical_fracture_plane(s, f);
    EXPECT_GE(p.index, scanned * (1.0 - 1e-9)) << trial;
    EXPECT_NEAR(fracture_plane_index(tractions_on_plane(s, p.angle), f), p.index, 1e-14 * p.index) << trial;
  }
}

} // namespace
} // namespace plyimpact::fracture_plane_tests
