// Progressive ply damage at one material point (laminate/ply_damage.hpp, docs/progressive_damage.md):
// displacement-controlled single-point tests against closed forms of the bilinear law, energy
// invariants (dissipation = G per unit crack area, = work − stored energy), irreversibility, the
// viscous limit, the band limit and a finite-difference check of the tangent.
#include "plyimpact/laminate/failure_criteria.hpp"
#include "plyimpact/laminate/ply_damage.hpp"
#include "plyimpact/laminate/ply_stiffness.hpp"
#include "support/decks.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace plyimpact::ply_damage_tests {
namespace {

// T300/976 with the strengths and toughnesses of tests/support/decks.hpp (t300_976_damage).
using namespace test::t300_976_damage;

Material t300() {
  return test::t300_976_with_damage_data();
}

// --- a displacement-controlled material point ------------------------------------------------

/// The five one-mode tests of the issue: uniaxial stress along or across the fibres (the lateral
/// in-plane stress held at zero) and pure in-plane shear.
struct UniaxialCase {
  std::string name;
  int component;      ///< driven strain: 0 = ε11, 1 = ε22, 2 = γ12
  double sign;        ///< +1 tension / positive shear, −1 compression
  DamageMode mode;    ///< the mode it must damage
  double strength;    ///< σ0, the stress at initiation
  double modulus;     ///< K with σ = K ε before initiation (uniaxial stress: E1, E2; shear: G12)
  double toughness;   ///< G of the mode
  double char_length; ///< L_c, below the band limit 2GK/σ0²
};

std::vector<UniaxialCase> uniaxial_cases() {
  const Material m = t300();
  return {
      {"fibre_tension", 0, +1.0, DamageMode::fibre_tension, Xt, m.E1, G_ft, 2e-3},
      {"fibre_compression", 0, -1.0, DamageMode::fibre_compression, Xc, m.E1, G_fc, 2e-3},
      {"matrix_tension", 1, +1.0, DamageMode::matrix_tension, Yt, m.E2, G_mt, 0.5e-3},
      {"matrix_compression", 1, -1.0, DamageMode::matrix_compression, Yc, m.E2, G_mc, 0.1e-3},
      {"in_plane_shear", 2, +1.0, DamageMode::matrix_tension, S12, m.G12, G_mt, 0.2e-3},
  };
}

/// One converged point of a path.
struct PathPoint {
  double driven_strain = 0.0; ///< the prescribed component (signed)
  double driven_stress = 0.0; ///< its conjugate stress (signed)
  PlyDamageResponse response;
};

/// Result of a path: the points, the work done on the point and the dissipation the law reports
/// (both per unit volume).
struct PathResult {
  std::vector<PathPoint> points;
  double work = 0.0;
  double dissipation = 0.0;
  PlyDamageState state;
};

/// Drives `law` along the strain values `path` of component c.component, solving at each step for
/// the lateral in-plane strain that keeps the lateral stress zero (uniaxial stress; pure shear has
/// no lateral coupling). Each step is iterated from the committed state, as the engine will.
PathResult drive(const PlyDamageLaw& law, const UniaxialCase& c, const std::vector<double>& path, double dt,
                 PlyDamageState state = {}) {
  const int lateral = c.component == 0 ? 1 : (c.component == 1 ? 0 : -1);
  PathResult result;
  PlyStrain strain = state.strain;
  Eigen::Vector3d previous_stress = Eigen::Vector3d::Zero();
  if (!path.empty()) previous_stress = law.update(state, state.strain, c.char_length, 0.0).stress;
  for (const double value : path) {
    // First guess of the lateral strain: the previous lateral/driven ratio (exact while elastic).
    const double previous_value = strain.in_plane(c.component);
    if (lateral >= 0 && previous_value != 0.0) strain.in_plane(lateral) *= value / previous_value;
    strain.in_plane(c.component) = value;
    PlyDamageResponse r = law.update(state, strain, c.char_length, dt);
    for (int it = 0; lateral >= 0 && it < 50; ++it) {
      const double residual = r.stress(lateral);
      if (std::abs(residual) <= 1e-6 + 1e-15 * std::abs(r.stress(c.component))) break;
      strain.in_plane(lateral) -= residual / r.secant(lateral, lateral);
      r = law.update(state, strain, c.char_length, dt);
    }
    if (lateral >= 0) {
      EXPECT_LE(std::abs(r.stress(lateral)), 1e-3) << "lateral stress not cancelled";
    }
    result.work += 0.5 * (previous_stress + r.stress).dot(strain.in_plane - state.strain.in_plane);
    result.dissipation += r.dissipation.sum();
    previous_stress = r.stress;
    state = r.state;
    result.points.push_back({value, r.stress(c.component), r});
  }
  result.state = state;
  return result;
}

/// n + 1 equally spaced values from a to b.
std::vector<double> ramp(double a, double b, int n) {
  std::vector<double> v;
  for (int i = 0; i <= n; ++i)
    v.push_back(a + (b - a) * i / n);
  return v;
}

/// Onset and final equivalent strains of a one-mode case: ε0 = σ0/K, εf = 2G/(σ0 L_c).
double onset_strain(const UniaxialCase& c) {
  return c.strength / c.modulus;
}
double final_strain(const UniaxialCase& c) {
  return 2.0 * c.toughness / (c.strength * c.char_length);
}

/// ramp(0, end, n) with one more point just past the onset strain, ε0(1 + 1e-13): initiation is
/// detected at the end of a step, so this samples the onset itself.
std::vector<double> ramp_through_onset(const UniaxialCase& c, double end, int n) {
  std::vector<double> v = ramp(0.0, end, n);
  const double onset = c.sign * onset_strain(c) * (1.0 + 1e-13);
  if (std::abs(end) > std::abs(onset)) {
    v.push_back(onset);
    std::sort(v.begin(), v.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
  }
  return v;
}

// --- the one-mode tests of the issue ---------------------------------------------------------

class UniaxialDamage : public ::testing::TestWithParam<UniaxialCase> {};

TEST_P(UniaxialDamage, LinearToTheStrengthThenLinearSofteningToZero) {
  const UniaxialCase c = GetParam();
  const PlyDamageLaw law(t300());
  const double e0 = onset_strain(c), ef = final_strain(c);
  ASSERT_GT(ef, 1.5 * e0) << "test L_c too close to the band limit";
  const PathResult p = drive(law, c, ramp_through_onset(c, c.sign * 1.2 * ef, 2000), 0.0);
  double peak = 0.0;
  for (const PathPoint& pt : p.points) {
    const double e = std::abs(pt.driven_strain), s = c.sign * pt.driven_stress;
    peak = std::max(peak, s);
    // Closed form of the bilinear law in uniaxial stress (docs (PD9)): σ = Kε up to ε0, then
    // σ = σ0 (εf − ε)/(εf − ε0) down to 0 at εf, and 0 beyond.
    const double expected = e <= e0 ? c.modulus * e : (e < ef ? c.strength * (ef - e) / (ef - e0) : 0.0);
    ASSERT_NEAR(s, expected, 1e-9 * c.strength) << c.name << " at strain " << e;
  }
  EXPECT_LE(peak, c.strength * (1.0 + 1e-12)) << c.name;
  EXPECT_NEAR(p.state.onset_equivalent_stress[c.mode], c.strength, 1e-12 * c.strength) << c.name;
  EXPECT_NEAR(p.state.onset_equivalent_strain[c.mode], e0, 1e-12 * e0) << c.name;
  EXPECT_EQ(p.state.damage[c.mode], 1.0) << c.name;
  for (const DamageMode other : all_damage_modes)
    if (other != c.mode) {
      EXPECT_EQ(p.state.damage[other], 0.0) << c.name << " damaged " << to_string(other);
    }
}

TEST_P(UniaxialDamage, DissipatedEnergyPerUnitCrackAreaIsTheToughness) {
  const UniaxialCase c = GetParam();
  const PlyDamageLaw law(t300());
  const PathResult p = drive(law, c, ramp(0.0, c.sign * 1.2 * final_strain(c), 2000), 0.0);
  // Fully broken: the stored energy is zero, so the work done equals the energy dissipated.
  const double from_work = p.work * c.char_length;
  const double reported = p.dissipation * c.char_length;
  EXPECT_NEAR(from_work, c.toughness, 0.01 * c.toughness) << c.name;
  EXPECT_NEAR(reported, c.toughness, 0.01 * c.toughness) << c.name;
  std::printf(
      "[ measured ] %-18s G = %.6g J/m2: work x Lc = %.6g (%.2e rel), dissipation x Lc = %.6g (%.2e rel)\n",
      c.name.c_str(), c.toughness, from_work, from_work / c.toughness - 1.0, reported,
      reported / c.toughness - 1.0);
}

TEST_P(UniaxialDamage, UnloadingIsSecantToTheOriginAndReloadingRetracesIt) {
  const UniaxialCase c = GetParam();
  const PlyDamageLaw law(t300());
  const double e0 = onset_strain(c), ef = final_strain(c);
  const double e_max = 0.5 * (e0 + ef); // halfway down the softening branch
  const PathResult loading = drive(law, c, ramp_through_onset(c, c.sign * e_max, 400), 0.0);
  const double d = loading.state.damage[c.mode];
  ASSERT_GT(d, 0.1);
  ASSERT_LT(d, 0.99);
  const double secant = c.sign * loading.points.back().driven_stress / e_max;
  EXPECT_NEAR(secant, (1.0 - d) * c.modulus, 1e-9 * c.modulus) << c.name;

  const PathResult unloading = drive(law, c, ramp(c.sign * e_max, 0.0, 200), 0.0, loading.state);
  for (const PathPoint& pt : unloading.points)
    ASSERT_NEAR(pt.driven_stress, secant * pt.driven_strain, 1e-9 * c.strength) << c.name;
  EXPECT_NEAR(unloading.points.back().driven_stress, 0.0, 1e-9 * c.strength) << c.name;
  EXPECT_EQ(unloading.state.damage[c.mode], d) << c.name;
  EXPECT_EQ(unloading.dissipation, 0.0) << c.name;

  // Reloading climbs the same secant up to the largest strain reached, then softens on as before.
  const PathResult reloading = drive(law, c, ramp(0.0, c.sign * 1.1 * e_max, 220), 0.0, unloading.state);
  for (const PathPoint& pt : reloading.points) {
    const double e = std::abs(pt.driven_strain);
    const double expected = e <= e_max ? secant * e : c.strength * (ef - e) / (ef - e0);
    ASSERT_NEAR(c.sign * pt.driven_stress, expected, 1e-9 * c.strength) << c.name << " at " << e;
  }
}

INSTANTIATE_TEST_SUITE_P(OneMode, UniaxialDamage, ::testing::ValuesIn(uniaxial_cases()),
                         [](const ::testing::TestParamInfo<UniaxialCase>& p) { return p.param.name; });

// --- the stiffness ------------------------------------------------------------------------------

/// A state carrying the given damage variables (none initiated, so a small strain leaves them as they are).
PlyDamageState damaged_state(double ft, double fc, double mt, double mc) {
  PlyDamageState s;
  s.damage.values = {ft, fc, mt, mc};
  s.regularised_damage = s.damage;
  return s;
}

TEST(PlyDamageStiffness, UndamagedSecantIsTheReducedStiffness) {
  const PlyDamageLaw law(t300());
  PlyStrain e;
  e.in_plane << 1e-4, -2e-4, 3e-4;
  e.transverse_shear << 1e-4, 2e-4;
  const PlyDamageResponse r = law.update({}, e, 1e-3, 0.0);
  const Eigen::Matrix3d Q = reduced_stiffness(t300());
  EXPECT_LT((r.secant - Q).norm(), 1e-12 * Q.norm());
  EXPECT_LT((r.transverse_shear_secant - transverse_shear_stiffness(t300())).norm(), 1e-12 * 7.1e9);
  EXPECT_LT((r.tangent.topLeftCorner<3, 3>() - Q).norm(), 1e-12 * Q.norm());
  EXPECT_LT((r.stress - Q * e.in_plane).norm(), 1e-12 * (Q * e.in_plane).norm());
  EXPECT_EQ(r.dissipation.sum(), 0.0);
}

TEST(PlyDamageStiffness, ElasticShortcutEqualsTheGeneralPath) {
  // A virgin point below every surface takes a shortcut; the general path, reached here through a
  // state whose (inactive) fibre-compression mode has initiated without damage, must agree.
  const PlyDamageLaw law(t300());
  PlyDamageState initiated;
  initiated.onset_equivalent_strain[DamageMode::fibre_compression] = 0.008;
  initiated.onset_equivalent_stress[DamageMode::fibre_compression] = Xc;
  initiated.max_equivalent_strain[DamageMode::fibre_compression] = 0.008;
  std::mt19937 rng(15);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    PlyStrain e;
    e.in_plane << 0.004 * std::abs(u(rng)), 0.002 * u(rng), 0.005 * u(rng);
    e.transverse_shear << 0.01 * u(rng), 0.01 * u(rng);
    const PlyDamageResponse fast = law.update({}, e, 1e-3, 1e-6),
                            general = law.update(initiated, e, 1e-3, 1e-6);
    ASSERT_FALSE(general.state.initiated(DamageMode::matrix_tension)) << "strain range too large";
    EXPECT_LT((fast.stress - general.stress).norm(), 1e-15 * general.stress.norm() + 1e-300);
    EXPECT_LT((fast.secant - general.secant).norm(), 1e-15 * general.secant.norm());
    EXPECT_LT((fast.tangent - general.tangent).norm(), 1e-15 * general.tangent.norm());
    EXPECT_EQ(fast.transverse_shear_stress, general.transverse_shear_stress);
    EXPECT_EQ(fast.dissipation.sum(), 0.0);
    EXPECT_EQ(general.dissipation.sum(), 0.0);
  }
}

TEST(PlyDamageStiffness, DegradedStiffnessInvertsTheMatzenmillerCompliance) {
  // MLT (1995): the compliance degrades only its diagonal, S(d) = [[1/((1−d_f)E1), −ν21/E2, 0],
  // [−ν12/E1, 1/((1−d_m)E2), 0], [0, 0, 1/((1−d_s)G12)]]; the secant must be its inverse.
  const Material m = t300();
  const PlyDamageLaw law(m);
  const double ft = 0.3, fc = 0.6, mt = 0.45, mc = 0.2;
  const double ds = 1.0 - (1 - ft) * (1 - fc) * (1 - mt) * (1 - mc);
  struct Loading {
    Eigen::Vector3d strain;
    double df, dm;
  };
  // Small strains of each sign pair select (d_ft or d_fc) and (d_mt or d_mc).
  const std::vector<Loading> loadings = {{{1e-5, 2e-5, 1e-5}, ft, mt},
                                         {{-1e-5, 2e-5, 1e-5}, fc, mt},
                                         {{1e-5, -2e-5, 1e-5}, ft, mc},
                                         {{-1e-5, -2e-5, 1e-5}, fc, mc}};
  for (const Loading& l : loadings) {
    PlyStrain e;
    e.in_plane = l.strain;
    e.transverse_shear << 1e-5, 1e-5;
    const PlyDamageResponse r = law.update(damaged_state(ft, fc, mt, mc), e, 1e-3, 0.0);
    Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
    S(0, 0) = 1.0 / ((1.0 - l.df) * m.E1);
    S(1, 1) = 1.0 / ((1.0 - l.dm) * m.E2);
    S(0, 1) = -m.nu21() / m.E2;
    S(1, 0) = -m.nu12 / m.E1;
    S(2, 2) = 1.0 / ((1.0 - ds) * m.G12);
    EXPECT_LT((r.secant * S - Eigen::Matrix3d::Identity()).norm(), 1e-12) << l.strain.transpose();
    const double dt = 1.0 - (1 - mt) * (1 - mc); // matrix damage, open or closed cracks alike
    EXPECT_NEAR(r.transverse_shear_secant(0, 0), (1.0 - dt) * m.G23, 1e-12 * m.G23);
    EXPECT_NEAR(r.transverse_shear_secant(1, 1), (1.0 - dt) * m.G13, 1e-12 * m.G13);
    EXPECT_EQ(r.transverse_shear_secant(0, 1), 0.0);
    EXPECT_EQ(r.dissipation.sum(), 0.0); // nothing grows
  }
}

TEST(PlyDamageStiffness, ABrokenModeDoesNotActWhenTheLoadReverses) {
  // Fibres broken in tension (d_ft = 1) still carry compression (d_fc = 0): crack closure. A matrix
  // cracked in tension (d_mt = 1) carries σ22 again in compression, but neither in-plane shear
  // (d_s = 1 from any mode) nor transverse shear (d_t = 1 from either matrix mode).
  const Material m = t300();
  const PlyDamageLaw law(m);
  const PlyDamageState broken = damaged_state(1.0, 0.0, 1.0, 0.0);
  PlyStrain tension, compression;
  tension.in_plane << 1e-4, 1e-4, 1e-4;
  tension.transverse_shear << 1e-4, 1e-4;
  compression.in_plane << -1e-4, -1e-4, 1e-4;
  compression.transverse_shear << 1e-4, 1e-4;
  const PlyDamageResponse t = law.update(broken, tension, 1e-3, 0.0);
  EXPECT_EQ(t.stress.norm(), 0.0);
  EXPECT_EQ(t.transverse_shear_stress.norm(), 0.0);
  const PlyDamageResponse c = law.update(broken, compression, 1e-3, 0.0);
  const Eigen::Matrix3d Q = reduced_stiffness(m);
  EXPECT_NEAR(c.stress(0), Q(0, 0) * -1e-4 + Q(0, 1) * -1e-4, 1e-12 * Q(0, 0) * 1e-4);
  EXPECT_NEAR(c.stress(1), Q(1, 0) * -1e-4 + Q(1, 1) * -1e-4, 1e-12 * Q(0, 0) * 1e-4);
  EXPECT_EQ(c.stress(2), 0.0);
  EXPECT_EQ(c.transverse_shear_stress.norm(), 0.0);
}

TEST(PlyDamageStiffness, SecantAtAGivenDamageIsTheLawsSecantThere) {
  // The lagged step asks for C(d) at the committed damage without evolving it: for the four sign pairs
  // of a damaged state, secant_at must be the secant the law returns when nothing grows, and name the
  // loaded modes (bit 0 fibre compression, bit 1 matrix compression).
  const PlyDamageLaw law(t300());
  const PlyDamageState s = damaged_state(0.3, 0.6, 0.45, 0.2);
  const std::vector<std::pair<Eigen::Vector3d, unsigned>> cases = {{{1e-5, 2e-5, 1e-5}, 0U},
                                                                   {{-1e-5, 2e-5, 1e-5}, 1U},
                                                                   {{1e-5, -2e-5, 1e-5}, 2U},
                                                                   {{-1e-5, -2e-5, 1e-5}, 3U}};
  for (const auto& [strain, modes] : cases) {
    PlyStrain e;
    e.in_plane = strain;
    e.transverse_shear << 1e-5, -1e-5;
    const PlyDamageResponse r = law.update(s, e, 1e-3, 0.0);
    ASSERT_EQ(r.dissipation.sum(), 0.0) << "the strain must leave the damage as it is";
    const PlySecant c = law.secant_at(s.regularised_damage, e);
    EXPECT_EQ(c.in_plane, r.secant) << strain.transpose();
    EXPECT_EQ(c.transverse_shear, r.transverse_shear_secant);
    EXPECT_EQ(c.modes, modes) << strain.transpose();
  }
}

// --- initiation ----------------------------------------------------------------------------------

TEST(PlyDamageInitiation, HashinIndicesMatchTheFailureCriterionWithAlphaOne) {
  // With α = 1 the plane-stress indices are those of the 3-D Hashin criterion of
  // laminate/failure_criteria.hpp with σ33 = τ13 = τ23 = 0 (an independent implementation).
  const Material m = t300();
  std::mt19937 rng(18);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 500; ++i) {
    const Eigen::Vector3d s(1.5e9 * u(rng), 300e6 * u(rng), 120e6 * u(rng));
    const DamageMode fibre = s(0) >= 0.0 ? DamageMode::fibre_tension : DamageMode::fibre_compression;
    const DamageMode matrix = s(1) >= 0.0 ? DamageMode::matrix_tension : DamageMode::matrix_compression;
    const double ours = std::max(hashin_plane_stress_index(fibre, s, m.strength, 1.0),
                                 hashin_plane_stress_index(matrix, s, m.strength, 1.0));
    const FailureResult theirs = hashin(PlyStress{.s11 = s(0), .s22 = s(1), .t12 = s(2)}, m.strength);
    ASSERT_NEAR(ours, theirs.index, 1e-12 * std::max(1.0, std::abs(theirs.index))) << s.transpose();
  }
}

TEST(PlyDamageInitiation, CombinedLoadingInitiatesOnTheHashinSurface) {
  // Matrix tension with shear along a proportional strain ray: the stored onset point lies on
  // (σ22/Yt)² + (τ12/S12)² = 1, and its equivalent stress is the work conjugate at that point.
  const Material m = t300();
  const PlyDamageLaw law(m);
  const Eigen::Vector3d direction(0.0, 1.0, 1.5);
  PlyDamageState state;
  double lambda = 0.0; // the step at which the mode initiates
  for (int i = 1; i <= 100 && !state.initiated(DamageMode::matrix_tension); ++i) {
    lambda = 1e-4 * i;
    PlyStrain e;
    e.in_plane = lambda * direction;
    state = law.update(state, e, 0.2e-3, 0.0).state;
  }
  ASSERT_TRUE(state.initiated(DamageMode::matrix_tension));
  // The onset point is R·ε with ε0 = R ε_eq(ε): undo it and evaluate the criterion by hand.
  const double e_eq = std::hypot(lambda * direction(1), lambda * direction(2));
  const double R = state.onset_equivalent_strain[DamageMode::matrix_tension] / e_eq;
  const Eigen::Vector3d onset = reduced_stiffness(m) * (R * lambda * direction);
  EXPECT_NEAR(std::pow(onset(1) / Yt, 2) + std::pow(onset(2) / S12, 2), 1.0, 1e-12);
  const double sigma_eq =
      (onset(1) * R * lambda * direction(1) + onset(2) * R * lambda * direction(2)) / (R * e_eq);
  EXPECT_NEAR(state.onset_equivalent_stress[DamageMode::matrix_tension], sigma_eq, 1e-12 * sigma_eq);
  EXPECT_FALSE(state.initiated(DamageMode::fibre_tension));
}

TEST(PlyDamageInitiation, WithAlphaOneInPlaneShearAlsoBreaksFibres) {
  // Why α = 0 is the default: with Hashin's (1980) α = 1, pure in-plane shear meets the
  // fibre-tension surface at τ12 = S12 together with the matrix mode, and the fibre damage then
  // grows as 1 − ε0/ε (its G is ~300× larger), degrading E1 under shear alone.
  Material m = t300();
  const PlyDamageLaw hashin_1980(m, {.alpha = 1.0});
  const PlyDamageLaw abaqus_default(m);
  PlyStrain e;
  e.in_plane << 0.0, 0.0, 2.0 * S12 / m.G12;
  PlyDamageState s1980, s0;
  for (int i = 1; i <= 20; ++i) {
    PlyStrain ei;
    ei.in_plane = e.in_plane * i / 20.0;
    s1980 = hashin_1980.update(s1980, ei, 0.2e-3, 0.0).state;
    s0 = abaqus_default.update(s0, ei, 0.2e-3, 0.0).state;
  }
  EXPECT_NEAR(s1980.damage[DamageMode::fibre_tension], 0.5, 0.02); // ≈ 1 − ε0/ε at ε = 2ε0
  EXPECT_GT(s1980.damage[DamageMode::matrix_tension], 0.5);
  EXPECT_EQ(s0.damage[DamageMode::fibre_tension], 0.0);
  EXPECT_GT(s0.damage[DamageMode::matrix_tension], 0.5);
}

// --- irreversibility and energy -------------------------------------------------------------------

TEST(PlyDamageHistory, DamageNeverDecreasesOnARandomStrainHistory) {
  const Material m = t300();
  const PlyDamageLaw law(m);
  std::mt19937 rng(2007);
  std::normal_distribution<double> step(0.0, 1.0);
  const Eigen::Matrix<double, 5, 1> scale =
      (Eigen::Matrix<double, 5, 1>() << 4e-4, 4e-4, 8e-4, 4e-4, 4e-4).finished();
  PlyDamageState state;
  PlyStrain walk;
  int initiated_modes = 0;
  for (int i = 0; i < 3000; ++i) {
    for (int k = 0; k < 5; ++k) {
      double& c = k < 3 ? walk.in_plane(k) : walk.transverse_shear(k - 3);
      c += scale(k) * step(rng) - 0.002 * c; // a random walk pulled weakly back to zero
    }
    // plus slow cycles of ε11 (±1.5 %) and ε22 (±4 %) so that every mode is visited
    PlyStrain e = walk;
    e.in_plane(0) += 0.015 * std::sin(2.0 * std::numbers::pi * i / 700.0);
    e.in_plane(1) += 0.04 * std::sin(2.0 * std::numbers::pi * i / 1100.0);
    const PlyDamageResponse r = law.update(state, e, 0.02e-3, 0.0);
    for (const DamageMode mode : all_damage_modes) {
      ASSERT_GE(r.state.damage[mode], state.damage[mode]) << i << " " << to_string(mode);
      ASSERT_GE(r.state.max_equivalent_strain[mode], state.max_equivalent_strain[mode]);
      ASSERT_GE(r.state.damage[mode], 0.0);
      ASSERT_LE(r.state.damage[mode], 1.0);
      ASSERT_GE(r.dissipation[mode], 0.0);
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(r.secant);
    ASSERT_GE(eig.eigenvalues().minCoeff(), -1e-6 * m.E1) << "secant not positive semi-definite";
    state = r.state;
  }
  for (const DamageMode mode : all_damage_modes) {
    initiated_modes += state.initiated(mode) ? 1 : 0;
    std::printf("[ measured ] random walk: %s initiated %d, d = %.4f\n", std::string(to_string(mode)).c_str(),
                state.initiated(mode) ? 1 : 0, state.damage[mode]);
  }
  EXPECT_EQ(initiated_modes, 4) << "the walk should visit every mode";
}

TEST(PlyDamageHistory, AdvanceIsTheUpdateWithoutItsTangentBitForBit) {
  // The plate calls advance(), the tests and Newton iterations update(): along a random strain history that
  // initiates and softens modes (with and without viscosity), the two give the same state, stresses, secants
  // and dissipation to the last bit, and a point reports undamaged() exactly when its secants are C(0).
  for (const double viscosity : {0.0, 3e-7}) {
    const PlyDamageLaw law(t300(), {.alpha = 0.0, .viscosity = viscosity});
    std::mt19937 rng(1995);
    std::normal_distribution<double> step(0.0, 1.0);
    PlyDamageState state;
    PlyStrain e;
    int damaged_steps = 0;
    for (int i = 0; i < 1500; ++i) {
      e.in_plane +=
          Eigen::Vector3d(6e-4 * step(rng), 6e-4 * step(rng), 1e-3 * step(rng)) - 0.004 * e.in_plane;
      e.transverse_shear += Eigen::Vector2d(5e-4 * step(rng), 5e-4 * step(rng));
      const PlyDamageResponse full = law.update(state, e, 0.02e-3, 1e-7);
      const PlyDamageUpdate fast = law.advance(state, e, 0.02e-3, 1e-7);
      ASSERT_EQ(fast.state.damage.values, full.state.damage.values) << i;
      ASSERT_EQ(fast.state.regularised_damage.values, full.state.regularised_damage.values) << i;
      ASSERT_EQ(fast.state.max_equivalent_strain.values, full.state.max_equivalent_strain.values) << i;
      ASSERT_EQ(fast.state.onset_equivalent_strain.values, full.state.onset_equivalent_strain.values) << i;
      ASSERT_EQ(fast.state.onset_equivalent_stress.values, full.state.onset_equivalent_stress.values) << i;
      ASSERT_EQ(fast.stress, full.stress) << i;
      ASSERT_EQ(fast.transverse_shear_stress, full.transverse_shear_stress) << i;
      ASSERT_EQ(fast.secant, full.secant) << i;
      ASSERT_EQ(fast.transverse_shear_secant, full.transverse_shear_secant) << i;
      ASSERT_EQ(fast.dissipation.values, full.dissipation.values) << i;
      const bool secants_undamaged = fast.secant == law.undamaged_stiffness() &&
                                     fast.transverse_shear_secant == law.undamaged_transverse_shear();
      ASSERT_EQ(fast.undamaged(), secants_undamaged) << i;
      damaged_steps += fast.undamaged() ? 0 : 1;
      state = fast.state;
    }
    // The walk must leave the undamaged state early, or the comparison covered only the elastic shortcut.
    EXPECT_GT(damaged_steps, 1000) << "viscosity " << viscosity;
  }
}

TEST(PlyDamageHistory, AVirginPlyBelowEverySurfaceKeepsItsStateAndTheUndamagedStiffness) {
  // What the plate's screen relies on when it skips the law for a virgin ply below the Hashin surfaces
  // (fem/damaged_plate.cpp): the law's answer there is the state given, its strain replaced, with the
  // undamaged secants to the bit and a dissipation of +0. Once a mode initiates, the state is no longer
  // virgin, even where the strain returns to zero.
  const PlyDamageLaw law(t300());
  const Eigen::Matrix3d Q = reduced_stiffness(t300());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  PlyDamageState state;
  ASSERT_TRUE(state.virgin());
  int below = 0;
  for (int i = 0; i < 400; ++i) {
    PlyStrain e;
    e.in_plane << 0.01 * u(rng), 0.006 * u(rng), 0.01 * u(rng);
    e.transverse_shear << 0.01 * u(rng), 0.01 * u(rng);
    const Eigen::Vector3d s = Q * e.in_plane;
    const DamageMode fibre = s(0) >= 0.0 ? DamageMode::fibre_tension : DamageMode::fibre_compression;
    const DamageMode matrix = s(1) >= 0.0 ? DamageMode::matrix_tension : DamageMode::matrix_compression;
    const Material m = t300();
    if (std::max(hashin_plane_stress_index(fibre, s, m.strength, 0.0),
                 hashin_plane_stress_index(matrix, s, m.strength, 0.0)) >= 1.0)
      continue;
    ++below;
    const PlyDamageUpdate r = law.advance(state, e, 1e-3, 1e-7);
    ASSERT_TRUE(r.state.virgin()) << i;
    ASSERT_EQ(r.state.damage.values, state.damage.values) << i;
    ASSERT_EQ(r.state.max_equivalent_strain.values, state.max_equivalent_strain.values) << i;
    ASSERT_EQ(r.state.strain.in_plane, e.in_plane) << i;
    ASSERT_EQ(r.state.strain.transverse_shear, e.transverse_shear) << i;
    ASSERT_EQ(r.secant, law.undamaged_stiffness()) << i;
    ASSERT_EQ(r.transverse_shear_secant, law.undamaged_transverse_shear()) << i;
    for (const DamageMode mode : all_damage_modes)
      ASSERT_FALSE(std::signbit(r.dissipation[mode]) || r.dissipation[mode] != 0.0) << i;
    state = r.state;
  }
  EXPECT_GT(below, 100) << "the strain range leaves too few points below the surfaces";
  PlyStrain beyond; // transverse tension at twice Yt/E2: the matrix mode initiates
  beyond.in_plane << 0.0, 2.0 * Yt / t300().E2, 0.0;
  const PlyDamageState cracked = law.advance(state, beyond, 1e-3, 1e-7).state;
  EXPECT_FALSE(cracked.virgin());
  EXPECT_FALSE(law.advance(cracked, PlyStrain{}, 1e-3, 1e-7).state.virgin());
}

TEST(PlyDamageHistory, ReportedDissipationIsWorkMinusStoredEnergy) {
  // Energy balance at the material point along a smooth mixed history: the sum of the reported
  // dissipation equals the work ∫σ:dε minus the final stored energy ½ε:C(d)ε (both integrated
  // independently here), to the accuracy of the two quadratures (midpoint for the law, trapezoid here).
  const Material m = t300();
  const PlyDamageLaw law(m);
  PlyDamageState state;
  Eigen::Matrix<double, 5, 1> previous_stress = Eigen::Matrix<double, 5, 1>::Zero();
  double work = 0.0, dissipation = 0.0;
  const int n = 20000;
  PlyDamageResponse r;
  for (int i = 1; i <= n; ++i) {
    const double t = static_cast<double>(i) / n;
    PlyStrain e;
    e.in_plane << 0.015 * std::sin(7.0 * t) * t, 0.012 * std::sin(11.0 * t + 1.0) * t,
        0.03 * std::sin(5.0 * t) * t;
    e.transverse_shear << 0.02 * t * std::cos(3.0 * t), 0.01 * t;
    r = law.update(state, e, 0.05e-3, 0.0);
    Eigen::Matrix<double, 5, 1> stress, de;
    stress << r.stress, r.transverse_shear_stress;
    de << e.in_plane - state.strain.in_plane, e.transverse_shear - state.strain.transverse_shear;
    work += 0.5 * (previous_stress + stress).dot(de);
    dissipation += r.dissipation.sum();
    previous_stress = stress;
    state = r.state;
  }
  const double stored = 0.5 * state.strain.in_plane.dot(r.stress) +
                        0.5 * state.strain.transverse_shear.dot(r.transverse_shear_stress);
  EXPECT_GT(dissipation, 0.05 * work) << "the history should damage the point";
  EXPECT_NEAR(dissipation, work - stored, 1e-6 * work);
  std::printf("[ measured ] mixed history: work %.6g J/m3, stored %.6g, dissipation %.6g, balance error %.2e "
              "of work\n",
              work, stored, dissipation, (work - stored - dissipation) / work);
}

// --- viscous regularisation --------------------------------------------------------------------

/// Fibre tension at a constant strain rate: strain and time steps of one path.
struct RatePath {
  std::vector<double> strain;
  double dt;
};

RatePath at_rate(double end_strain, int steps, double rate) {
  return {ramp(0.0, end_strain, steps), end_strain / steps / rate};
}

TEST(PlyDamageViscosity, ZeroViscosityIsTheRateIndependentLaw) {
  const UniaxialCase c = uniaxial_cases()[0];
  const PlyDamageLaw plain(t300()), zero(t300(), {.viscosity = 0.0});
  const RatePath path = at_rate(1.2 * final_strain(c), 500, 100.0);
  const PathResult a = drive(plain, c, path.strain, 0.0), b = drive(zero, c, path.strain, path.dt);
  for (std::size_t i = 0; i < a.points.size(); ++i)
    ASSERT_EQ(a.points[i].driven_stress, b.points[i].driven_stress);
}

TEST(PlyDamageViscosity, SmallViscosityTendsToTheRateIndependentResponse) {
  // τ_soft = (εf − ε0)/ε̇ is the time the inviscid law takes to soften; the viscous response
  // overshoots the strength and lags by O(η/τ_soft), vanishing linearly as η → 0.
  const UniaxialCase c = uniaxial_cases()[0];
  const double rate = 100.0; // 1/s
  const double e0 = onset_strain(c), ef = final_strain(c);
  const double t_soft = (ef - e0) / rate;
  const RatePath path = at_rate(1.5 * ef, 6000, rate);
  const PathResult inviscid = drive(PlyDamageLaw(t300()), c, path.strain, path.dt);
  double previous_gap = 0.0;
  for (const double eta_ratio : {1e-1, 1e-2, 1e-3}) {
    const PathResult viscous =
        drive(PlyDamageLaw(t300(), {.viscosity = eta_ratio * t_soft}), c, path.strain, path.dt);
    double gap = 0.0, peak = 0.0;
    for (std::size_t i = 0; i < viscous.points.size(); ++i) {
      gap = std::max(gap, std::abs(viscous.points[i].driven_stress - inviscid.points[i].driven_stress));
      peak = std::max(peak, viscous.points[i].driven_stress);
    }
    EXPECT_GT(peak, Xt) << "viscous stress overshoots the strength, eta/t_soft = " << eta_ratio;
    if (previous_gap > 0.0) {
      EXPECT_LT(gap, 0.2 * previous_gap) << "eta/t_soft = " << eta_ratio;
    }
    std::printf(
        "[ measured ] eta/t_soft = %.0e: max |sigma_visc - sigma_inviscid| = %.4g Xt, peak = %.6f Xt\n",
        eta_ratio, gap / Xt, peak / Xt);
    previous_gap = gap;
  }
  EXPECT_LT(previous_gap, 0.01 * Xt);
}

TEST(PlyDamageViscosity, ViscousDissipationStillEqualsTheToughness) {
  const UniaxialCase c = uniaxial_cases()[0];
  const double rate = 100.0;
  const double e0 = onset_strain(c), ef = final_strain(c);
  const double eta = 1e-3 * (ef - e0) / rate;
  // Strain on until d_v has relaxed to 1 (many η past εf).
  const RatePath path = at_rate(1.5 * ef, 6000, rate);
  const PathResult p = drive(PlyDamageLaw(t300(), {.viscosity = eta}), c, path.strain, path.dt);
  ASSERT_GT(p.state.regularised_damage[c.mode], 1.0 - 1e-9);
  const double from_work = p.work * c.char_length, reported = p.dissipation * c.char_length;
  EXPECT_NEAR(from_work, G_ft, 0.01 * G_ft);
  EXPECT_NEAR(reported, from_work, 1e-3 * from_work);
  std::printf("[ measured ] viscous (eta = 1e-3 t_soft): work x Lc = %.6g J/m2 (%.2e rel to G), dissipation "
              "x Lc = %.6g\n",
              from_work, from_work / G_ft - 1.0, reported);
}

// --- band limit -------------------------------------------------------------------------------

TEST(PlyDamageBandLimit, MaximumCharacteristicLengthsByHand) {
  const Material m = t300();
  const PlyDamageLaw law(m);
  const auto limit = [](double G, double K, double s) { return 2.0 * G * K / (s * s); };
  EXPECT_NEAR(law.max_characteristic_length(DamageMode::fibre_tension), limit(G_ft, m.E1, Xt), 1e-15);
  EXPECT_NEAR(law.max_characteristic_length(DamageMode::fibre_compression), limit(G_fc, m.E1, Xc), 1e-15);
  EXPECT_NEAR(law.max_characteristic_length(DamageMode::matrix_tension),
              std::min(limit(G_mt, m.E2, Yt), limit(G_mt, m.G12, S12)), 1e-15);
  EXPECT_NEAR(law.max_characteristic_length(DamageMode::matrix_compression),
              std::min(limit(G_mc, m.E2, Yc), limit(G_mc, m.G12, S12)), 1e-15);
  EXPECT_NEAR(law.max_characteristic_length(), limit(G_mc, m.E2, Yc), 1e-15); // 0.176 mm
  std::printf("[ measured ] band limits [mm]: ft %.4g, fc %.4g, mt %.4g, mc %.4g, all %.4g\n",
              law.max_characteristic_length(DamageMode::fibre_tension) * 1e3,
              law.max_characteristic_length(DamageMode::fibre_compression) * 1e3,
              law.max_characteristic_length(DamageMode::matrix_tension) * 1e3,
              law.max_characteristic_length(DamageMode::matrix_compression) * 1e3,
              law.max_characteristic_length() * 1e3);
}

TEST(PlyDamageBandLimit, AnElementAboveTheBandLimitIsAClearError) {
  // Transverse tension: L_max = 2 G_mt E2/Yt² = 1.755 mm.
  const Material m = t300();
  const PlyDamageLaw law(m);
  const double l_max = 2.0 * G_mt * m.E2 / (Yt * Yt);
  UniaxialCase below = uniaxial_cases()[2], above = below;
  below.char_length = 0.999 * l_max;
  above.char_length = 1.001 * l_max;
  EXPECT_NO_THROW((void)drive(law, below, ramp_through_onset(below, 1.2 * onset_strain(below), 120), 0.0));
  try {
    (void)drive(law, above, ramp_through_onset(above, 1.2 * onset_strain(above), 120), 0.0);
    FAIL() << "no BandLimitError";
  } catch (const BandLimitError& error) {
    EXPECT_EQ(error.mode(), DamageMode::matrix_tension);
    EXPECT_NEAR(error.max_characteristic_length(), l_max, 1e-12 * l_max);
    EXPECT_EQ(error.characteristic_length(), above.char_length);
    const std::string what = error.what();
    EXPECT_NE(what.find("T300_976"), std::string::npos) << what;
    EXPECT_NE(what.find("matrix-tension"), std::string::npos) << what;
    char expected[64];
    std::snprintf(expected, sizeof expected, "of %.4g mm", l_max * 1e3);
    EXPECT_NE(what.find(std::string("maximum element size (characteristic length) ") + expected),
              std::string::npos)
        << what;
  }
}

TEST(PlyDamageBandLimit, StrengthsBelowTheBandLimitOfTheElementAreKept) {
  // L_c below every band limit (0.176 mm is the smallest, matrix compression): nothing to lower.
  const Material m = t300();
  const Strengths s = band_limited_strengths(m, 0.1e-3, 0.0);
  EXPECT_EQ(*s.Xt, Xt);
  EXPECT_EQ(*s.Xc, Xc);
  EXPECT_EQ(*s.Yt, Yt);
  EXPECT_EQ(*s.Yc, Yc);
  EXPECT_EQ(*s.S12, S12);
  EXPECT_EQ(*s.S23, *m.strength.S23);
}

TEST(PlyDamageBandLimit, LoweredStrengthsStillDissipateTheToughnessInLargeElements) {
  // Maimí et al. (2007): an 8 mm element, 4.6 to 46 times the band limits of the matrix modes, with
  // its strengths lowered: every one-mode test softens without snap-back and dissipates G per unit
  // area (1 %), starting at the lowered strength.
  const double Lc = 8e-3;
  Material m = t300();
  m.strength = band_limited_strengths(m, Lc, 0.0);
  const PlyDamageLaw law(m);
  const double lowered[] = {*m.strength.Xt, *m.strength.Xc, *m.strength.Yt, *m.strength.Yc, *m.strength.S12};
  std::size_t i = 0;
  for (UniaxialCase c : uniaxial_cases()) {
    c.strength = lowered[i++];
    c.char_length = Lc;
    const double limit = 2.0 * c.toughness * c.modulus / (c.strength * c.strength);
    EXPECT_GT(limit, Lc) << c.name << ": the lowered strength must fit the element";
    const PathResult p = drive(law, c, ramp_through_onset(c, c.sign * 1.2 * final_strain(c), 2000), 0.0);
    EXPECT_NEAR(p.state.onset_equivalent_stress[c.mode], c.strength, 1e-9 * c.strength) << c.name;
    EXPECT_EQ(p.state.damage[c.mode], 1.0) << c.name;
    EXPECT_NEAR(p.dissipation * Lc, c.toughness, 0.01 * c.toughness) << c.name;
  }
  EXPECT_LT(*m.strength.Yc, 0.2 * Yc); // matrix compression: limit 0.176 mm, √(0.176/8) = 0.15
  std::printf("[ measured ] strengths for L_c = 8 mm [MPa]: Xt %.4g, Xc %.4g, Yt %.4g, Yc %.4g, S12 %.4g\n",
              lowered[0] * 1e-6, lowered[1] * 1e-6, lowered[2] * 1e-6, lowered[3] * 1e-6, lowered[4] * 1e-6);
}

TEST(PlyDamageBandLimit, LoweredStrengthsCoverTransverseTensionUnderFibreCompression) {
  // The Poisson coupling: with σ11 near −Xc the transverse strain at the matrix-tension onset exceeds
  // Yt/E2 and so does σ⁰ε⁰; the lowered strengths include it, so this biaxial path does not snap back.
  const double Lc = 8e-3;
  Material m = t300();
  m.strength = band_limited_strengths(m, Lc, 0.0);
  const PlyDamageLaw law(m);
  const Eigen::Matrix3d C = law.update({}, {}, Lc, 0.0).secant;
  const Eigen::Vector3d fibre_stress(-0.95 * *m.strength.Xc, 0.0, 0.0);
  PlyStrain e;
  e.in_plane = C.inverse() * fibre_stress; // σ11 = −0.95 Xc, σ22 = 0
  PlyDamageState state;
  const double step = 0.01 * *m.strength.Yt / m.E2;
  for (int k = 0; k < 2000 && state.damage[DamageMode::matrix_tension] < 1.0; ++k) {
    e.in_plane(1) += step;
    PlyDamageResponse r;
    ASSERT_NO_THROW(r = law.update(state, e, Lc, 0.0)) << "step " << k;
    state = r.state;
  }
  EXPECT_EQ(state.damage[DamageMode::matrix_tension], 1.0);
}

// --- the tangent --------------------------------------------------------------------------------

/// Central finite differences of the stress (5 components) from a committed state.
Eigen::Matrix<double, 5, 5> finite_difference_tangent(const PlyDamageLaw& law, const PlyDamageState& state,
                                                      const PlyStrain& e, double lc, double dt, double h) {
  Eigen::Matrix<double, 5, 5> T;
  for (int k = 0; k < 5; ++k) {
    PlyStrain plus = e, minus = e;
    (k < 3 ? plus.in_plane(k) : plus.transverse_shear(k - 3)) += h;
    (k < 3 ? minus.in_plane(k) : minus.transverse_shear(k - 3)) -= h;
    const PlyDamageResponse a = law.update(state, plus, lc, dt), b = law.update(state, minus, lc, dt);
    T.col(k) << (a.stress - b.stress) / (2 * h),
        (a.transverse_shear_stress - b.transverse_shear_stress) / (2 * h);
  }
  return T;
}

TEST(PlyDamageTangent, MatchesCentralFiniteDifferences) {
  // FEBio-style check: from committed damaged states, the analytical tangent against central
  // differences of update(), loading (damage growing) and unloading, with and without viscosity.
  const Material m = t300();
  struct Case {
    std::string name;
    Eigen::Vector3d direction; ///< strain ray that initiates the modes
    Eigen::Vector2d transverse;
    double overshoot; ///< evaluation point, beyond the committed strain
    double viscosity;
  };
  const std::vector<Case> cases = {
      {"fibre tension, loading", {1.0, -0.1, 0.2}, {0.1, 0.1}, 1.02, 0.0},
      {"fibre compression, loading", {-1.0, 0.1, 0.2}, {0.1, 0.1}, 1.02, 0.0},
      {"matrix tension + shear, loading", {0.0, 1.0, 1.5}, {0.5, 0.3}, 1.02, 0.0},
      {"matrix compression + shear, loading", {0.0, -1.0, 0.6}, {0.5, 0.3}, 1.02, 0.0},
      {"matrix tension + shear, unloading", {0.0, 1.0, 1.5}, {0.5, 0.3}, 0.9, 0.0},
      {"matrix tension + shear, viscous", {0.0, 1.0, 1.5}, {0.5, 0.3}, 1.02, 1e-6},
  };
  for (const Case& c : cases) {
    const PlyDamageLaw law(m, {.viscosity = c.viscosity});
    const double lc = 0.05e-3, dt = 1e-6;
    // Load along the ray until some mode has initiated and grown a little, then commit.
    PlyDamageState state;
    PlyStrain e;
    double lambda = 0.0;
    for (int i = 0; i < 5000; ++i) {
      lambda += 2e-5;
      e.in_plane = lambda * c.direction;
      e.transverse_shear = lambda * c.transverse;
      state = law.update(state, e, lc, dt).state;
      if (*std::max_element(state.damage.values.begin(), state.damage.values.end()) > 0.2) break;
    }
    PlyStrain at = e;
    at.in_plane *= c.overshoot;
    at.transverse_shear *= c.overshoot;
    const PlyDamageResponse r = law.update(state, at, lc, dt);
    const Eigen::Matrix<double, 5, 5> fd = finite_difference_tangent(law, state, at, lc, dt, 1e-9);
    const double error = (r.tangent - fd).norm() / fd.norm();
    EXPECT_LT(error, 1e-6) << c.name << "\nanalytical\n" << r.tangent << "\nfinite differences\n" << fd;
    // Where damage grows the tangent must differ from the secant, or the check proves nothing.
    Eigen::Matrix<double, 5, 5> secant = Eigen::Matrix<double, 5, 5>::Zero();
    secant.topLeftCorner<3, 3>() = r.secant;
    secant.bottomRightCorner<2, 2>() = r.transverse_shear_secant;
    const double growth = (r.tangent - secant).norm() / secant.norm();
    if (c.overshoot > 1.0) {
      EXPECT_GT(growth, 1e-3) << c.name << ": damage should grow here";
    }
    if (c.overshoot < 1.0) {
      EXPECT_EQ(growth, 0.0) << c.name << ": unloading is secant";
    }
    std::printf("[ measured ] tangent vs central differences, %-36s: %.2e relative\n", c.name.c_str(), error);
  }
}

// --- input checks -------------------------------------------------------------------------------

TEST(PlyDamageInput, MissingToughnessIsNamed) {
  Material m = t300();
  m.toughness.G_mt.reset();
  m.strength.S23.reset();
  try {
    const PlyDamageLaw law(m);
    FAIL() << "no error";
  } catch (const std::invalid_argument& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("G_mt"), std::string::npos) << what;
    EXPECT_NE(what.find("S23"), std::string::npos) << what;
    EXPECT_NE(what.find("T300_976"), std::string::npos) << what;
  }
  EXPECT_THROW(PlyDamageLaw(t300(), {.alpha = 1.5}), std::invalid_argument);
  EXPECT_THROW(PlyDamageLaw(t300(), {.viscosity = -1.0}), std::invalid_argument);
  const PlyDamageLaw law(t300());
  EXPECT_THROW((void)law.update({}, {}, 0.0, 0.0), std::invalid_argument);
  EXPECT_THROW((void)law.update({}, {}, 1e-3, -1.0), std::invalid_argument);
}

} // namespace
} // namespace plyimpact::ply_damage_tests
