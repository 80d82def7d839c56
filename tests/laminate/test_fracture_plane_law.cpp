// The fracture-plane ply law at one point (laminate/fracture_plane_law.hpp, docs/progressive_damage.md):
// the band limits of the T700/M21 card against the hand values 2EG/X² the issue gives; a crack run to
// complete failure dissipates its toughness per unit crack area — G_mt in transverse tension, G_ms in pure
// shear and the Benzeggagh–Kenane value between them on a mixed path (work = dissipation, both against the
// closed form); compressive σ22 never softens, before or after the crack, and an open crack closes; the
// section's screen bounds the index.
#include "plyimpact/laminate/fracture_plane.hpp"
#include "plyimpact/laminate/fracture_plane_law.hpp"
#include "plyimpact/laminate/ply_law.hpp"
#include "plyimpact/laminate/ply_stiffness.hpp"
#include "support/decks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace plyimpact::fracture_plane_law_tests {
namespace {

Material card() {
  return test::t700_m21_tan2015();
}

PlyDamageOptions fracture_plane_options() {
  PlyDamageOptions o;
  o.law = PlyLawKind::fracture_plane;
  return o;
}

/// A point driven along a strain path: each increment from the committed state, as the section does.
struct Point {
  const PlyLaw& law;
  double Lc;
  PlyDamageState state{};
  Eigen::Vector3d stress = Eigen::Vector3d::Zero();
  double work = 0.0;        ///< ∫σ·dε (trapezoid) [J/m³]
  double dissipation = 0.0; ///< what the law reported [J/m³]

  PlyDamageUpdate to(const Eigen::Vector3d& e) {
    PlyDamageUpdate r = law.advance(state, {e, Eigen::Vector2d::Zero()}, Lc, 0.0);
    work += 0.5 * (stress + r.stress).dot(e - state.strain.in_plane);
    dissipation += r.dissipation.sum();
    stress = r.stress;
    state = r.state;
    return r;
  }
};

TEST(FracturePlaneLaw, MakePlyLawGivesItAndNamesWhatTheCardLacks) {
  const std::unique_ptr<PlyLaw> law = make_ply_law(card(), fracture_plane_options());
  ASSERT_NE(dynamic_cast<const FracturePlaneLaw*>(law.get()), nullptr);
  EXPECT_TRUE(law->undamaged_stiffness().isApprox(reduced_stiffness(card()), 1e-14));
  Material without = card();
  without.toughness.G_ms.reset();
  try {
    (void)make_ply_law(without, fracture_plane_options());
    FAIL() << "no error without G_ms";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("G_ms"), std::string::npos) << e.what();
  }
}

TEST(FracturePlaneLaw, BandLimitsOfTheCardAreTheIssuesHandValues) {
  // 2EG/X² by hand (issue 79): fibre tension 2·130e9·133e3/2080e6² = 7.992 mm, fibre compression
  // 2·130e9·10e3/1250e6² = 1.664 mm, transverse tension 2·7.7e9·500/60e6² = 2.139 mm, in-plane shear
  // 2·4.8e9·1600/110e6² = 1.2694 mm; an open crack softens at the smaller of the last two.
  const FracturePlaneLaw law(card());
  EXPECT_NEAR(law.band_limit(DamageMode::fibre_tension), 7.992e-3, 1e-6);
  EXPECT_NEAR(law.band_limit(DamageMode::fibre_compression), 1.664e-3, 1e-6);
  EXPECT_NEAR(law.band_limit(DamageMode::matrix_tension), 1.2694e-3, 1e-7);
  EXPECT_NEAR(law.band_limit(DamageMode::matrix_compression), 1.2694e-3, 1e-7);
  // The strengths an element of 1.5 mm would need: S12 lowered (shear limit 1.27 mm), Yc untouched.
  const Strengths s = law.band_limited_strengths(1.5e-3);
  EXPECT_LT(*s.S12, 110e6 * std::sqrt(1.2694 / 1.5) * 1.0001);
  EXPECT_EQ(*s.Yc, 290e6);
  EXPECT_EQ(*s.Xt, 2080e6);
}

/// Drives ε = t·direction to complete failure and returns the point. `free_11`: ε11 is solved for σ11 = 0
/// in each increment (Newton on the secant, from the committed state), so that the state is uniaxial
/// across the fibres before and after the crack.
Point to_failure(const PlyLaw& law, double Lc, const Eigen::Vector3d& direction, double end, int steps,
                 bool free_11) {
  Point p{law, Lc};
  double e11 = 0.0;
  for (int i = 1; i <= steps; ++i) {
    Eigen::Vector3d e = direction * (end * i / steps);
    for (int it = 0; free_11 && it < 50; ++it) {
      e(0) = e11;
      const PlyDamageUpdate r = law.advance(p.state, {e, Eigen::Vector2d::Zero()}, Lc, 0.0);
      if (std::abs(r.stress(0)) <= 1e-9 * std::max(std::abs(r.stress(1)), 1e3)) break;
      e11 -= r.stress(0) / r.secant(0, 0);
    }
    if (free_11) e(0) = e11;
    (void)p.to(e);
  }
  return p;
}

TEST(FracturePlaneLaw, TransverseTensionDissipatesGmtAndPureShearGms) {
  const Material m = card();
  const FracturePlaneLaw law(m);
  const double Lc = 1.0e-3;
  // Transverse tension (σ11 = 0): fails at Yt, ε_f = 2G_mt/(Yt Lc) on ε22.
  const Point tension = to_failure(law, Lc, {0.0, 1.0, 0.0}, 1.2 * 2.0 * 500.0 / (60e6 * Lc), 4000, true);
  EXPECT_NEAR(tension.dissipation * Lc, 500.0, 0.005 * 500.0);
  EXPECT_NEAR(tension.work * Lc, 500.0, 0.005 * 500.0);
  EXPECT_NEAR(tension.state.onset_equivalent_stress[DamageMode::matrix_tension], 60e6, 1e-6 * 60e6);
  EXPECT_EQ(tension.state.damage[DamageMode::matrix_tension], 1.0);
  // Pure in-plane shear: fails at S12, ε_f = 2G_ms/(S12 Lc).
  const Point shear = to_failure(law, Lc, {0.0, 0.0, 1.0}, 1.2 * 2.0 * 1600.0 / (110e6 * Lc), 4000, false);
  EXPECT_NEAR(shear.dissipation * Lc, 1600.0, 0.005 * 1600.0);
  EXPECT_NEAR(shear.work * Lc, 1600.0, 0.005 * 1600.0);
  EXPECT_EQ(shear.state.damage[DamageMode::matrix_tension], 1.0);
}

TEST(FracturePlaneLaw, AMixedPathDissipatesTheBenzeggaghKenaneToughness) {
  const Material m = card();
  const FracturePlaneLaw law(m);
  const double Lc = 0.5e-3;
  const Eigen::Matrix3d& C = law.undamaged_stiffness();
  for (const double shear_per_tension : {0.5, 1.0, 3.0}) {
    // ε = t(0, 1, k) with ε11 = 0: σ̂22 = C22 ε22, τ̂12 = G12 γ12, so the shear share of the energy at
    // onset is B = G12 k²/(C22 + G12 k²) whatever t, and G_c = G_mt + (G_ms − G_mt) B^1.45.
    const double k = shear_per_tension;
    const double B = m.G12 * k * k / (C(1, 1) + m.G12 * k * k);
    const double Gc = 500.0 + (1600.0 - 500.0) * std::pow(B, 1.45);
    EXPECT_NEAR(law.crack_toughness(B), Gc, 1e-9 * Gc);
    const Point p = to_failure(law, Lc, {0.0, 1.0, k}, 0.1, 10000, false);
    EXPECT_NEAR(p.state.crack_toughness, Gc, 1e-9 * Gc) << k;
    EXPECT_NEAR(p.dissipation * Lc, Gc, 0.005 * Gc) << k;
    EXPECT_NEAR(p.work * Lc, Gc, 0.005 * Gc) << k;
    EXPECT_EQ(p.state.damage[DamageMode::matrix_tension], 1.0) << k;
  }
}

TEST(FracturePlaneLaw, CompressiveTransverseStressNeverSoftens) {
  const Material m = card();
  const FracturePlaneLaw law(m);
  const double Lc = 1.0e-3;
  const Eigen::Matrix3d& C = law.undamaged_stiffness();
  Point p{law, Lc};
  // Transverse compression to three times Yc (σ11 = 0): σ22 = E2 ε22 throughout.
  const double e_end = -3.0 * 290e6 / m.E2;
  for (int i = 1; i <= 300; ++i) {
    const double e22 = e_end * i / 300;
    (void)p.to({-C(0, 1) / C(0, 0) * e22, e22, 0.0});
    ASSERT_NEAR(p.stress(1), m.E2 * e22, 1e-9 * m.E2 * std::abs(e22)) << i;
  }
  // Then shear at that compression: the crack forms closed (on the ray, where the compression has already
  // passed the surface: with a small shear stress at onset, a long softening branch — the crushed ply keeps
  // little shear, docs/progressive_damage.md) and softens the shear; σ22 stays elastic throughout, and the
  // energy reported dissipated is the work done less the energy stored.
  const Eigen::Vector3d compressed = p.state.strain.in_plane;
  const double work_before = p.work;
  for (int i = 1; i <= 2000; ++i)
    (void)p.to(compressed + Eigen::Vector3d(0.0, 0.0, 0.05 * i / 2000));
  EXPECT_TRUE(p.state.initiated(DamageMode::matrix_compression));
  EXPECT_FALSE(p.state.initiated(DamageMode::matrix_tension));
  EXPECT_GT(p.state.damage[DamageMode::matrix_compression], 0.9);
  EXPECT_NEAR(p.stress(1), m.E2 * compressed(1), 1e-9 * m.E2 * std::abs(compressed(1)));
  EXPECT_LT(std::abs(p.stress(2)), 0.1 * m.G12 * 0.05);
  EXPECT_GT(p.dissipation, 0.0);
  const double stored = 0.5 * p.stress.dot(p.state.strain.in_plane);
  EXPECT_NEAR(p.dissipation, p.work - stored, 0.01 * p.dissipation) << work_before;
}

TEST(FracturePlaneLaw, AnOpenCrackClosesUnderCompression) {
  const Material m = card();
  const FracturePlaneLaw law(m);
  const double Lc = 1.0e-3;
  const Eigen::Matrix3d& C = law.undamaged_stiffness();
  const auto uniaxial = [&](double e22) { return Eigen::Vector3d(-C(0, 1) / C(0, 0) * e22, e22, 0.0); };
  Point p{law, Lc};
  const double e0 = 60e6 / m.E2, ef = 2.0 * 500.0 / (60e6 * Lc);
  for (int i = 1; i <= 1000; ++i)
    (void)p.to(uniaxial(0.5 * (e0 + ef) * i / 1000));
  const double d = p.state.damage[DamageMode::matrix_tension];
  ASSERT_GT(d, 0.2);
  ASSERT_LT(d, 0.99);
  // Open: the secant across the fibres is (1 − d)E2 (σ11 = 0); closed: E2 again, and no damage grows.
  const PlySecant open = law.secant_at(p.state.damage, {uniaxial(1e-4), Eigen::Vector2d::Zero()});
  const PlySecant closed = law.secant_at(p.state.damage, {uniaxial(-1e-4), Eigen::Vector2d::Zero()});
  EXPECT_NEAR(1.0 / open.in_plane.inverse()(1, 1), (1.0 - d) * m.E2, 1e-9 * m.E2);
  EXPECT_NEAR(1.0 / closed.in_plane.inverse()(1, 1), m.E2, 1e-9 * m.E2);
  EXPECT_EQ(closed.modes, 2U);
  const PlyDamageState before = p.state;
  const PlyDamageUpdate r = p.to(uniaxial(-2.0 * e0));
  EXPECT_NEAR(r.stress(1), -2.0 * e0 * m.E2, 1e-9 * m.E2 * e0);
  EXPECT_EQ(r.state.damage.values, before.damage.values);
}

TEST(FracturePlaneLaw, TheScreensBoundIsNeverBelowTheIndexAlongASegment) {
  const Material m = card();
  const FracturePlaneLaw law(m);
  const FracturePlaneStrengths& f = law.plane_strengths();
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (int trial = 0; trial < 200; ++trial) {
    const auto draw = [&] { return Eigen::Vector3d(u(rng) * 2080e6, u(rng) * 290e6, u(rng) * 110e6); };
    const Eigen::Vector3d s0 = draw(), s1 = draw();
    double largest = 0.0;
    for (int i = 0; i <= 200; ++i) {
      const Eigen::Vector3d s = s0 + (s1 - s0) * (i / 200.0);
      const double fibre = std::pow(s(0) / (s(0) >= 0.0 ? 2080e6 : 1250e6), 2);
      largest = std::max({largest, fibre, critical_fracture_plane({s(1), s(2)}, f).index});
    }
    EXPECT_GE(law.onset_bound(s0, s1), largest * (1.0 - 1e-12)) << trial;
  }
}

TEST(FracturePlaneLaw, AnElementBeyondTheBandLimitIsRefused) {
  const FracturePlaneLaw law(card());
  const double Lc = 3.0e-3; // > 2.139 mm of transverse tension
  EXPECT_THROW((void)to_failure(law, Lc, {0.0, 1.0, 0.0}, 2.0 * 60e6 / 7.7e9, 100, true), BandLimitError);
}

} // namespace
} // namespace plyimpact::fracture_plane_law_tests
