// Failure criteria of thesis chapter 2.5 (2.32)–(2.43), SPEC §6.
#include "plyimpact/laminate/failure_criteria.hpp"
#include "support/decks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace plyimpact::failure_criteria_tests {
namespace {

constexpr double kTol = 1e-12;
constexpr double kInf = std::numeric_limits<double>::infinity();

// T300/976 (SPEC §2 moduli, SPEC §6 / thesis Table 4.2 strengths; Xt, Xc typical values).
constexpr double Xt = 1.5e9;
constexpr double Xc = 1.2e9;
constexpr double Yt = 55.2e6;
constexpr double Yc = 294.0e6;
constexpr double S12 = 101.1e6;
constexpr double S23 = 32.94e6;
constexpr double Da = 1.8;

Strengths t300_strengths() {
  Strengths s;
  s.Xt = Xt;
  s.Xc = Xc;
  s.Yt = Yt;
  s.Yc = Yc;
  s.S12 = S12;
  s.S23 = S23;
  s.Da = Da;
  return s;
}

/// T300/976 elastic constants (tests/support/decks.hpp) with the SPEC §6 strengths.
Material t300() {
  Material m = test::t300_976();
  m.strength = t300_strengths();
  return m;
}

/// Evaluates any criterion; for the interface criterion the same stress is given to both plies.
FailureResult eval(Criterion c, const PlyStress& s) {
  const Material m = t300();
  if (is_interface_criterion(c)) return choi_chang_delamination(s, m.strength, s, m.strength);
  return evaluate(c, s, m);
}

struct ModeCase {
  Criterion criterion;
  PlyStress stress;
  FailureMode mode;
};

std::string describe(const ModeCase& c) {
  return std::string(to_string(c.criterion)) + " s11=" + std::to_string(c.stress.s11) +
         " s22=" + std::to_string(c.stress.s22) + " t23=" + std::to_string(c.stress.t23) +
         " t12=" + std::to_string(c.stress.t12);
}

void expect_cases_at_index_one(const std::vector<ModeCase>& cases) {
  for (const ModeCase& c : cases) {
    const FailureResult r = eval(c.criterion, c.stress);
    EXPECT_NEAR(r.index, 1.0, kTol) << describe(c);
    EXPECT_NEAR(r.strength_ratio, 1.0, kTol) << describe(c);
    EXPECT_EQ(r.mode, c.mode) << describe(c) << " got " << to_string(r.mode);
  }
}

// --- names --------------------------------------------------------------------------------------

TEST(FailureCriteriaNames, DeckNamesRoundTripForEveryCriterion) {
  const std::vector<std::string> names = {"max-stress", "max-strain",        "tsai-hill",
                                          "hoffman",    "tsai-wu",           "hashin",
                                          "sun",        "choi-chang-matrix", "choi-chang-delamination"};
  ASSERT_EQ(all_criteria().size(), names.size());
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto c = parse_criterion(names[i]);
    ASSERT_TRUE(c.has_value()) << names[i];
    EXPECT_EQ(*c, all_criteria()[i]);
    EXPECT_EQ(to_string(*c), names[i]);
  }
}

TEST(FailureCriteriaNames, UnknownOrMisspelledNamesAreRejected) {
  EXPECT_FALSE(parse_criterion("").has_value());
  EXPECT_FALSE(parse_criterion("tsai_wu").has_value());
  EXPECT_FALSE(parse_criterion("Tsai-Wu").has_value());
  EXPECT_FALSE(parse_criterion("choi-chang").has_value());
}

TEST(FailureCriteriaNames, ModeNamesAreHyphenatedLowerCase) {
  EXPECT_EQ(to_string(FailureMode::none), "none");
  EXPECT_EQ(to_string(FailureMode::fibre_tension), "fibre-tension");
  EXPECT_EQ(to_string(FailureMode::matrix_compression), "matrix-compression");
  EXPECT_EQ(to_string(FailureMode::matrix_cracking), "matrix-cracking");
  EXPECT_EQ(to_string(FailureMode::delamination), "delamination");
}

TEST(FailureCriteriaNames, OnlyChoiChangDelaminationIsAnInterfaceCriterion) {
  for (const Criterion c : all_criteria()) {
    EXPECT_EQ(is_interface_criterion(c), c == Criterion::choi_chang_delamination) << to_string(c);
  }
  EXPECT_THROW((void)evaluate(Criterion::choi_chang_delamination, PlyStress{}, t300()),
               std::invalid_argument);
}

// --- required strengths ---------------------------------------------------------------------

TEST(RequiredStrengths, ChoiChangNeedsOnlyTransverseStrengthsAndDa) {
  EXPECT_EQ(required_strengths(Criterion::choi_chang_matrix),
            (std::vector<StrengthId>{StrengthId::Yt, StrengthId::Yc, StrengthId::S23}));
  EXPECT_EQ(required_strengths(Criterion::choi_chang_delamination),
            (std::vector<StrengthId>{StrengthId::Yt, StrengthId::Yc, StrengthId::S23, StrengthId::Da}));
}

TEST(RequiredStrengths, TsaiWuWithoutXcReportsXcMissing) {
  Strengths s = t300_strengths();
  s.Xc.reset();
  const std::vector<StrengthId> missing = missing_strengths(Criterion::tsai_wu, s);
  ASSERT_EQ(missing.size(), 1u);
  EXPECT_EQ(to_string(missing[0]), "Xc");
  EXPECT_TRUE(missing_strengths(Criterion::choi_chang_matrix, s).empty());
}

TEST(RequiredStrengths, TheFullT300SetSatisfiesEveryCriterion) {
  for (const Criterion c : all_criteria()) {
    EXPECT_TRUE(missing_strengths(c, t300_strengths()).empty()) << to_string(c);
    EXPECT_FALSE(required_strengths(c).empty()) << to_string(c);
  }
}

TEST(RequiredStrengths, AMissingStrengthGivesNaNNotASilentPass) {
  Strengths s = t300_strengths();
  s.Yc.reset();
  const FailureResult r = tsai_wu(PlyStress{.s22 = -400e6}, s);
  EXPECT_TRUE(std::isnan(r.index));
  EXPECT_FALSE(r.failed());
  // Yc is not read by this state (fibre and matrix tension) but Hashin needs it: still NaN.
  EXPECT_TRUE(std::isnan(hashin(PlyStress{.s11 = 1e9}, s).index));
  EXPECT_TRUE(std::isnan(hashin(PlyStress{.s11 = 1e9}, s).strength_ratio));
  // A strength the criterion does not need may be absent.
  Strengths no_x = t300_strengths();
  no_x.Xt.reset();
  no_x.Xc.reset();
  EXPECT_NEAR(choi_chang_matrix_cracking(PlyStress{.s22 = 0.5 * Yt}, no_x).index, 0.5, kTol);
}

// --- uniaxial strengths, pure shear ----------------------------------------------------------

TEST(UniaxialStrength, StressEqualToEachStrengthGivesIndexOneInTheRightMode) {
  using C = Criterion;
  using M = FailureMode;
  const PlyStress xt{.s11 = Xt}, xc{.s11 = -Xc}, yt{.s22 = Yt}, yc{.s22 = -Yc};
  expect_cases_at_index_one({
      {C::max_stress, xt, M::fibre_tension},
      {C::max_stress, xc, M::fibre_compression},
      {C::max_stress, yt, M::matrix_tension},
      {C::max_stress, yc, M::matrix_compression},
      {C::max_strain, xt, M::fibre_tension},
      {C::max_strain, xc, M::fibre_compression},
      {C::max_strain, yt, M::matrix_tension},
      {C::max_strain, yc, M::matrix_compression},
      {C::tsai_hill, xt, M::fibre_tension},
      {C::tsai_hill, xc, M::fibre_compression},
      {C::tsai_hill, yt, M::matrix_tension},
      {C::tsai_hill, yc, M::matrix_compression},
      {C::hoffman, xt, M::fibre_tension},
      {C::hoffman, xc, M::fibre_compression},
      {C::hoffman, yt, M::matrix_tension},
      {C::hoffman, yc, M::matrix_compression},
      {C::tsai_wu, xt, M::fibre_tension},
      {C::tsai_wu, xc, M::fibre_compression},
      {C::tsai_wu, yt, M::matrix_tension},
      {C::tsai_wu, yc, M::matrix_compression},
      {C::hashin, xt, M::fibre_tension},
      {C::hashin, xc, M::fibre_compression},
      {C::hashin, yt, M::matrix_tension},
      {C::hashin, yc, M::matrix_compression},
      {C::sun, xt, M::fibre_breakage},
      {C::sun, xc, M::fibre_breakage},
      {C::sun, yt, M::matrix_cracking},
      {C::sun, yc, M::matrix_crushing},
      {C::choi_chang_matrix, yt, M::matrix_cracking},
      {C::choi_chang_matrix, yc, M::matrix_cracking},
  });
}

TEST(UniaxialStrength, PureInPlaneShearEqualToS12GivesIndexOneForEitherSign) {
  using C = Criterion;
  using M = FailureMode;
  for (const double sign : {1.0, -1.0}) {
    const PlyStress shear{.t12 = sign * S12};
    expect_cases_at_index_one({
        {C::max_stress, shear, M::in_plane_shear},
        {C::max_strain, shear, M::in_plane_shear},
        {C::tsai_hill, shear, M::in_plane_shear},
        {C::hoffman, shear, M::in_plane_shear},
        {C::tsai_wu, shear, M::in_plane_shear},
        {C::hashin, shear, M::matrix_tension}, // ties with fibre tension; the matrix mode wins
        {C::sun, shear, M::matrix_cracking},   // ties with fibre breakage (S_f = S12)
    });
  }
}

TEST(UniaxialStrength, PureTransverseShearEqualToS23GivesIndexOne) {
  using C = Criterion;
  using M = FailureMode;
  const PlyStress shear{.t23 = -S23};
  expect_cases_at_index_one({
      {C::hashin, shear, M::matrix_tension},
      {C::sun, shear, M::matrix_cracking},
      {C::choi_chang_matrix, shear, M::matrix_cracking},
  });
}

TEST(UniaxialStrength, TransverseShearTau13EqualToS12GivesOneInHashinAndSun) {
  // τ13 = S12 alone: Hashin's fibre- and matrix-tension modes both carry (τ12² + τ13²)/S12²; Sun's
  // fibre breakage (2.39) carries τ13 but its matrix cracking (2.40) does not.
  const PlyStress shear{.t13 = S12};
  const FailureResult h = hashin(shear, t300_strengths());
  EXPECT_NEAR(h.index, 1.0, kTol);
  EXPECT_EQ(h.mode, FailureMode::matrix_tension); // the matrix mode also carries τ13²/S12², tie → matrix
  const FailureResult s = sun(shear, t300_strengths());
  EXPECT_NEAR(s.index, 1.0, kTol);
  EXPECT_EQ(s.mode, FailureMode::fibre_breakage); // Sun's matrix cracking has no τ13 term
}

// --- Choi–Chang -----------------------------------------------------------------------------

TEST(ChoiChangMatrixCracking, TransverseTensionYtOrTransverseShearS23AloneGivesOne) {
  const Strengths st = t300_strengths();
  EXPECT_NEAR(choi_chang_matrix_cracking(PlyStress{.s22 = Yt}, st).index, 1.0, kTol);
  EXPECT_NEAR(choi_chang_matrix_cracking(PlyStress{.t23 = S23}, st).index, 1.0, kTol);
  EXPECT_NEAR(choi_chang_matrix_cracking(PlyStress{.s22 = -Yc}, st).index, 1.0, kTol);
}

TEST(ChoiChangMatrixCracking, IndexIsEmNotEmSquared) {
  // σ̄22 = 0.6 Yt, τ̄23 = 0.8 S23: e_M² = 0.36 + 0.64 = 1 → e_M = 1.
  // σ̄22 = 0.3 Yt, τ̄23 = 0.4 S23: e_M² = 0.25 → e_M = 0.5 (e², 0.25, is not what is reported).
  const Strengths st = t300_strengths();
  EXPECT_NEAR(choi_chang_matrix_cracking(PlyStress{.s22 = 0.6 * Yt, .t23 = 0.8 * S23}, st).index, 1.0, kTol);
  const FailureResult half = choi_chang_matrix_cracking(PlyStress{.s22 = 0.3 * Yt, .t23 = 0.4 * S23}, st);
  EXPECT_NEAR(half.index, 0.5, kTol);
  EXPECT_NEAR(half.strength_ratio, 2.0, kTol);
}

TEST(ChoiChangMatrixCracking, OnlyTransverseStressesMatter) {
  // σ11, τ12, τ13 do not enter (2.42).
  const FailureResult r = choi_chang_matrix_cracking(
      PlyStress{.s11 = 2 * Xt, .s22 = 0.5 * Yt, .t13 = 3 * S12, .t12 = 3 * S12}, t300_strengths());
  EXPECT_NEAR(r.index, 0.5, kTol);
}

TEST(ChoiChangDelamination, EachTermAloneAtStrengthOverSqrtDaGivesOne) {
  const Strengths st = t300_strengths();
  const double k = 1.0 / std::sqrt(Da);
  // τ̄23 of ply n (upper by default), τ̄13 and σ̄22 of ply n+1 (lower).
  EXPECT_NEAR(choi_chang_delamination(PlyStress{.t23 = k * S23}, st, PlyStress{}, st).index, 1.0, kTol);
  EXPECT_NEAR(choi_chang_delamination(PlyStress{}, st, PlyStress{.t13 = k * S23}, st).index, 1.0, kTol);
  EXPECT_NEAR(choi_chang_delamination(PlyStress{}, st, PlyStress{.s22 = k * Yt}, st).index, 1.0, kTol);
  EXPECT_NEAR(choi_chang_delamination(PlyStress{}, st, PlyStress{.s22 = -k * Yc}, st).index, 1.0, kTol);
  EXPECT_EQ(choi_chang_delamination(PlyStress{.t23 = k * S23}, st, PlyStress{}, st).mode,
            FailureMode::delamination);
}

TEST(ChoiChangDelamination, UpperPlyIsNByDefaultAndTheChoiceIsSwitchable) {
  const Strengths st = t300_strengths();
  const PlyStress upper{.s22 = 20e6, .t23 = 10e6, .t13 = 5e6};
  const PlyStress lower{.s22 = -40e6, .t23 = 3e6, .t13 = 12e6};
  // Upper = n: Da[(10/32.94)² + (12/32.94)² + (40/294)²] = 1.8·(0.092162 + 0.132714 + 0.018511)
  //          = 1.8·0.243387 = 0.438097 → e_D = 0.661888
  const double e_upper =
      std::sqrt(Da * (std::pow(10e6 / S23, 2) + std::pow(12e6 / S23, 2) + std::pow(40e6 / Yc, 2)));
  // Lower = n: Da[(3/32.94)² + (5/32.94)² + (20/55.2)²] → e_D = 0.541016
  const double e_lower =
      std::sqrt(Da * (std::pow(3e6 / S23, 2) + std::pow(5e6 / S23, 2) + std::pow(20e6 / Yt, 2)));
  EXPECT_NEAR(choi_chang_delamination(upper, st, lower, st).index, e_upper, kTol);
  EXPECT_NEAR(choi_chang_delamination(upper, st, lower, st, DelaminationPlyN::upper).index, e_upper, kTol);
  EXPECT_NEAR(choi_chang_delamination(upper, st, lower, st, DelaminationPlyN::lower).index, e_lower, kTol);
  EXPECT_NEAR(e_upper, 0.661888, 1e-6);
  EXPECT_NEAR(e_lower, 0.541016, 1e-6);
}

TEST(ChoiChangDelamination, StrengthsOfEachPlyAreUsedForItsOwnTerms) {
  // Ply n+1 (lower) is twice as strong transversely: its σ̄22 term uses its own Yt.
  const Strengths weak = t300_strengths();
  Strengths strong = weak;
  strong.Yt = 2 * Yt;
  const double k = 1.0 / std::sqrt(Da);
  EXPECT_NEAR(choi_chang_delamination(PlyStress{}, weak, PlyStress{.s22 = 2 * k * Yt}, strong).index, 1.0,
              kTol);
  EXPECT_NEAR(choi_chang_delamination(PlyStress{}, strong, PlyStress{.s22 = k * Yt}, weak).index, 1.0, kTol);
}

// --- strength ratio ----------------------------------------------------------------------------

TEST(StrengthRatio, ScalingAnyStressStateByItsStrengthRatioLandsExactlyOnTheFailureSurface) {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Material m = t300();
  for (const Criterion c : all_criteria()) {
    int finite = 0;
    for (int i = 0; i < 2000; ++i) {
      const PlyStress s{.s11 = 2 * Xt * u(rng),
                        .s22 = 1.5 * Yc * u(rng),
                        .s33 = 0.5 * Yt * u(rng),
                        .t23 = 2 * S23 * u(rng),
                        .t13 = 2 * S12 * u(rng),
                        .t12 = 2 * S12 * u(rng)};
      const PlyStress s2{.s11 = Xt * u(rng), .s22 = Yc * u(rng), .t23 = S23 * u(rng), .t13 = S23 * u(rng)};
      const FailureResult r = is_interface_criterion(c)
                                  ? choi_chang_delamination(s, m.strength, s2, m.strength)
                                  : evaluate(c, s, m);
      if (!std::isfinite(r.strength_ratio)) {
        EXPECT_EQ(r.mode, FailureMode::none);
        continue;
      }
      ++finite;
      const double R = r.strength_ratio;
      const FailureResult on = is_interface_criterion(c) ? choi_chang_delamination(s.scaled(R), m.strength,
                                                                                   s2.scaled(R), m.strength)
                                                         : evaluate(c, s.scaled(R), m);
      // The index along the ray is a R² + b R with a, b of either sign: the rounding of the two
      // terms grows with R (Hashin matrix compression with σ33 ≠ 0 can reach R ~ 1e3).
      ASSERT_NEAR(on.index, 1.0, kTol * std::max(1.0, R)) << to_string(c) << " sample " << i << " R = " << R;
      EXPECT_NEAR(on.strength_ratio, 1.0, kTol) << to_string(c) << " sample " << i;
      EXPECT_EQ(on.mode, r.mode) << to_string(c) << " sample " << i; // the mode is scale-invariant
      // Failure ⇔ R ≤ 1 (away from the surface itself).
      if (std::abs(R - 1.0) > 1e-9) {
        EXPECT_EQ(r.failed(), R < 1.0) << to_string(c) << " sample " << i;
      }
    }
    EXPECT_GT(finite, 1900) << to_string(c);
  }
}

TEST(StrengthRatio, LinearCriteriaGiveOneOverIndexAndTsaiHillOneOverRootIndex) {
  const Strengths st = t300_strengths();
  const PlyStress s{.s11 = 300e6, .s22 = -80e6, .t23 = 5e6, .t12 = 30e6};
  const FailureResult ms = max_stress(s, st);
  EXPECT_NEAR(ms.strength_ratio, 1.0 / ms.index, kTol);
  const FailureResult cc = choi_chang_matrix_cracking(s, st);
  EXPECT_NEAR(cc.strength_ratio, 1.0 / cc.index, kTol);
  const FailureResult th = tsai_hill(s, st);
  EXPECT_NEAR(th.strength_ratio, 1.0 / std::sqrt(th.index), kTol);
}

TEST(StrengthRatio, ZeroStressHasIndexZeroInfiniteRatioAndNoMode) {
  for (const Criterion c : all_criteria()) {
    const FailureResult r = eval(c, PlyStress{});
    EXPECT_EQ(r.index, 0.0) << to_string(c);
    EXPECT_EQ(r.strength_ratio, kInf) << to_string(c);
    EXPECT_EQ(r.mode, FailureMode::none) << to_string(c);
    EXPECT_FALSE(r.failed()) << to_string(c);
  }
}

TEST(StrengthRatio, StressesACriterionIgnoresNeverReachItsSurface) {
  // Choi–Chang matrix cracking sees neither σ11 nor τ12; plane-stress Tsai–Wu does not see τ23.
  const FailureResult cc =
      choi_chang_matrix_cracking(PlyStress{.s11 = 5 * Xt, .t12 = 5 * S12}, t300_strengths());
  EXPECT_EQ(cc.index, 0.0);
  EXPECT_EQ(cc.strength_ratio, kInf);
  EXPECT_EQ(cc.mode, FailureMode::none);
  const FailureResult tw = tsai_wu(PlyStress{.t23 = 10 * S23}, t300_strengths());
  EXPECT_EQ(tw.strength_ratio, kInf);
  EXPECT_EQ(tw.mode, FailureMode::none);
}

// --- Tsai–Wu hand calculations -----------------------------------------------------------------

TEST(TsaiWu, BiaxialTensionWithShearMatchesHandCalculation) {
  // σ11 = 600 MPa, σ22 = 20 MPa, τ12 = 40 MPa, T300/976:
  //   F11 = 1/(1.5e9·1.2e9)   = 5.5556e-19     F11σ11²     =  0.200000
  //   F22 = 1/(55.2e6·294e6)  = 6.16189e-17    F22σ22²     =  0.024648
  //   F66 = 1/101.1e6²        = 9.78358e-17    F66τ12²     =  0.156537
  //   F12 = −½√(F11F22)       = −2.92544e-18   2F12σ11σ22  = −0.070210
  //   F1  = 1/Xt − 1/Xc       = −1.66667e-10   F1σ11       = −0.100000
  //   F2  = 1/Yt − 1/Yc       = 1.47146e-8     F2σ22       =  0.294292
  //   index = 0.505266; quadratic part a = 0.310974, linear part b = 0.194292,
  //   R = positive root of a R² + b R − 1 = 0 = 2/(b + √(b² + 4a)) = 1.507852.
  const PlyStress s{.s11 = 600e6, .s22 = 20e6, .t12 = 40e6};
  const FailureResult r = tsai_wu(s, t300_strengths());
  EXPECT_NEAR(r.index, 0.5052659542791416, 1e-12);
  EXPECT_NEAR(r.strength_ratio, 1.507852232573488, 1e-12);
  EXPECT_FALSE(r.failed());
  // With F12* = 0 the interaction term vanishes: 0.505266 + 0.070210 = 0.575476.
  EXPECT_NEAR(tsai_wu(s, t300_strengths(), 0.0).index, 0.5754764095909973, 1e-12);
  CriterionOptions opt;
  opt.tsai_wu_f12_star = 0.0;
  EXPECT_NEAR(evaluate(Criterion::tsai_wu, s, t300(), opt).index, 0.5754764095909973, 1e-12);
}

TEST(TsaiWu, MildBiaxialCompressionGivesNegativeIndexWhichIsSafe) {
  // σ11 = −400 MPa, σ22 = −150 MPa, τ12 = 30 MPa:
  //   F11σ11² = 0.088889, 2F12σ11σ22 = −0.351052, F22σ22² = 1.386424, F66τ12² = 0.088052,
  //   F1σ11 = 0.066667, F2σ22 = −2.207187  →  index = −0.928208 (the linear term F2σ22 dominates).
  const FailureResult r = tsai_wu(PlyStress{.s11 = -400e6, .s22 = -150e6, .t12 = 30e6}, t300_strengths());
  EXPECT_NEAR(r.index, -0.9282076115049718, 1e-12);
  EXPECT_FALSE(r.failed());
  EXPECT_GT(r.strength_ratio, 1.0);
  EXPECT_EQ(r.mode, FailureMode::matrix_compression); // σ22/Yc = 0.51 is the largest stress ratio
}

// --- Hashin hand calculations ------------------------------------------------------------------

TEST(Hashin, MatrixTensionWithBothShearsMatchesHandCalculation) {
  // σ22 = 30 MPa, τ23 = 10 MPa, τ12 = 50 MPa:
  //   (30/55.2)² + (10/32.94)² + (50/101.1)² = 0.295369 + 0.092162 + 0.244589 = 0.632120.
  const FailureResult r = hashin(PlyStress{.s22 = 30e6, .t23 = 10e6, .t12 = 50e6}, t300_strengths());
  EXPECT_NEAR(r.index, 0.6321202522418252, 1e-12);
  EXPECT_EQ(r.mode, FailureMode::matrix_tension);
  EXPECT_NEAR(r.strength_ratio, 1.0 / std::sqrt(0.6321202522418252), 1e-12);
}

TEST(Hashin, FibreTensionIncludesBothAxialShears) {
  // σ11 = 1.2 GPa, τ12 = 50 MPa, τ13 = 20 MPa: (1.2/1.5)² + (50² + 20²)/101.1² = 0.64 + 0.283724 = 0.923724.
  // The matrix-tension mode (σ22 = 0) only sees the shears: 0.283724, so fibre tension governs.
  const FailureResult r = hashin(PlyStress{.s11 = 1.2e9, .t13 = 20e6, .t12 = 50e6}, t300_strengths());
  EXPECT_NEAR(r.index, 0.923723746992773, 1e-12);
  EXPECT_EQ(r.mode, FailureMode::fibre_tension);
}

TEST(Hashin, MatrixCompressionAtYcWithShearExceedsOne) {
  // σ22 = −Yc: [(Yc/2S23)² − 1](−1) + (Yc/2S23)² = 1 exactly; τ12 = 40 MPa adds (40/101.1)² = 0.156537.
  const FailureResult r = hashin(PlyStress{.s22 = -Yc, .t12 = 40e6}, t300_strengths());
  EXPECT_NEAR(r.index, 1.0 + std::pow(40e6 / S12, 2), 1e-12);
  EXPECT_NEAR(r.index, 1.1565372397201506, 1e-12);
  EXPECT_EQ(r.mode, FailureMode::matrix_compression);
  EXPECT_TRUE(r.failed());
}

TEST(Hashin, ModerateTransverseCompressionIsGovernedByMatrixCompressionDespiteItsNegativeIndex) {
  // σ22 = −150 MPa, τ12 = 40 MPa: (Yc/2S23)² − 1 = 18.915329;
  //   matrix compression: 18.915329·(−150/294) + (150/65.88)² + (40/101.1)²
  //                       = −9.650678 + 5.184123 + 0.156537 = −4.310017  (a = 5.340661, b = −9.650678)
  //   fibre tension (σ11 = 0 counts as tension): (40/101.1)² = 0.156537.
  // The reported index is the larger, 0.156537, but growing the load reaches matrix compression
  // first: R_mc = 2/(b + √(b² + 4a)) = 1.90 < R_ft = 1/√0.156537 = 2.53, so the mode is
  // matrix-compression and the strength ratio is R_mc.
  const FailureResult r = hashin(PlyStress{.s22 = -150e6, .t12 = 40e6}, t300_strengths());
  EXPECT_NEAR(r.index, std::pow(40e6 / S12, 2), 1e-12);
  const double a = std::pow(150e6 / (2 * S23), 2) + std::pow(40e6 / S12, 2);
  const double b = (std::pow(Yc / (2 * S23), 2) - 1.0) * (-150e6 / Yc);
  EXPECT_NEAR(a + b, -4.310017216276469, 1e-12);
  EXPECT_NEAR(r.strength_ratio, 2.0 / (b + std::sqrt(b * b + 4 * a)), 1e-12);
  EXPECT_NEAR(r.strength_ratio, 1.90, 0.01);
  EXPECT_EQ(r.mode, FailureMode::matrix_compression);
  const FailureResult at_failure =
      hashin(PlyStress{.s22 = -150e6, .t12 = 40e6}.scaled(r.strength_ratio), t300_strengths());
  EXPECT_NEAR(at_failure.index, 1.0, kTol);
  EXPECT_EQ(at_failure.mode, FailureMode::matrix_compression);
}

TEST(Hashin, SigmaThirtyThreeEntersTheMatrixModesThroughSigma22PlusSigma33) {
  // σ22 = 30 MPa, σ33 = 10 MPa: (40/55.2)² + (0 − 30·10)/32.94² (in MPa²) = 0.525098 − 0.276490 = 0.248608.
  const FailureResult r = hashin(PlyStress{.s22 = 30e6, .s33 = 10e6}, t300_strengths());
  EXPECT_NEAR(r.index, std::pow(40e6 / Yt, 2) - 300e12 / (S23 * S23), 1e-12);
  EXPECT_EQ(r.mode, FailureMode::matrix_tension);
}

// --- Tsai–Hill, Sun, max-strain ------------------------------------------------------------------

TEST(TsaiHill, CompressiveSigma22UsesYcAndTensileUsesYt) {
  const Strengths st = t300_strengths();
  // σ22 = −100 MPa: (100/294)² = 0.115693 (the thesis's swapped choice would give (100/55.2)² = 3.28).
  EXPECT_NEAR(tsai_hill(PlyStress{.s22 = -100e6}, st).index, 0.1156925355176084, 1e-12);
  EXPECT_NEAR(tsai_hill(PlyStress{.s22 = 100e6}, st).index, 3.281873555975635, 1e-12);
  EXPECT_TRUE(tsai_hill(PlyStress{.s22 = 100e6}, st).failed());
}

TEST(TsaiHill, CompressiveSigma11UsesXcInTheInteractionTerm) {
  // σ11 = −600 MPa, σ22 = −100 MPa: (600/1200)² − (600·100)/1200² + (100/294)²
  //   = 0.25 − 0.041667 + 0.115693 = 0.324026.
  EXPECT_NEAR(tsai_hill(PlyStress{.s11 = -600e6, .s22 = -100e6}, t300_strengths()).index, 0.32402586885094176,
              1e-12);
}

TEST(Hoffman, EqualsTsaiWuWithItsOwnInteractionCoefficient) {
  // Plane-stress Hoffman is Tsai–Wu with 2F12 = −1/(XtXc), i.e. F12* = −½·√(YtYc/(XtXc)).
  const double f12_star = -0.5 * std::sqrt(Yt * Yc / (Xt * Xc));
  const PlyStress s{.s11 = -500e6, .s22 = 40e6, .t12 = 60e6};
  EXPECT_NEAR(hoffman(s, t300_strengths()).index, tsai_wu(s, t300_strengths(), f12_star).index, 1e-12);
}

TEST(Sun, MatrixCrushingAtYcIsIndependentOfTheShearStrength) {
  // (2.41) at σ22 = −Yc: ¼Yc²/S12² − ¼Yc²/S12² + 1 = 1 whatever S12.
  Strengths st = t300_strengths();
  st.S12 = 50e6;
  EXPECT_NEAR(sun(PlyStress{.s22 = -Yc}, st).index, 1.0, kTol);
}

TEST(Sun, MatrixCrackingCombinesTransverseTensionAndBothShears) {
  // σ22 = 30 MPa, τ12 = 50 MPa, τ23 = 10 MPa: same sum as Hashin's matrix tension, 0.632120.
  const FailureResult r = sun(PlyStress{.s22 = 30e6, .t23 = 10e6, .t12 = 50e6}, t300_strengths());
  EXPECT_NEAR(r.index, 0.6321202522418252, 1e-12);
  EXPECT_EQ(r.mode, FailureMode::matrix_cracking);
}

TEST(MaxStrain, AllowablesAreStrengthsOverModuli) {
  const StrainAllowables a = strain_allowables(t300());
  EXPECT_DOUBLE_EQ(a.e1t, Xt / 144.8e9);
  EXPECT_DOUBLE_EQ(a.e1c, Xc / 144.8e9);
  EXPECT_DOUBLE_EQ(a.e2t, Yt / 9.65e9);
  EXPECT_DOUBLE_EQ(a.e2c, Yc / 9.65e9);
  EXPECT_DOUBLE_EQ(a.g12, S12 / 7.10e9);
}

TEST(MaxStrain, PoissonContractionMakesBiaxialStatesDifferFromMaxStress) {
  // σ11 = Xt, σ22 = −Yc/2: ε11 = (Xt + ν12·Yc/2)/E1 exceeds Xt/E1 by ν12·Yc/(2Xt) = 0.0294,
  // while max-stress sees exactly 1.
  const PlyStress s{.s11 = Xt, .s22 = -0.5 * Yc};
  EXPECT_NEAR(max_stress(s, t300_strengths()).index, 1.0, kTol);
  const FailureResult r = max_strain(s, t300());
  EXPECT_NEAR(r.index, 1.0 + 0.30 * Yc / (2 * Xt), kTol);
  EXPECT_EQ(r.mode, FailureMode::fibre_tension);
}

TEST(MaxStrain, ExplicitAllowablesOverrideTheDerivedOnes) {
  StrainAllowables a = strain_allowables(t300());
  a.e2t = 0.5 * a.e2t;
  EXPECT_NEAR(max_strain(PlyStress{.s22 = 0.5 * Yt}, t300(), a).index, 1.0, kTol);
}

// --- latch -----------------------------------------------------------------------------------------

TEST(FailureLatch, OnceFailedStaysFailedAndReportsTheFirstMode) {
  FailureLatch latch;
  EXPECT_FALSE(latch.update({0.5, FailureMode::matrix_cracking, 2.0}));
  EXPECT_FALSE(latch.failed);
  EXPECT_TRUE(latch.update({1.2, FailureMode::matrix_cracking, 0.9}));
  EXPECT_FALSE(latch.update({1.5, FailureMode::delamination, 0.8})); // reported only once
  EXPECT_FALSE(latch.update({0.1, FailureMode::none, 10.0}));        // unloading does not heal
  EXPECT_TRUE(latch.failed);
  EXPECT_EQ(latch.first_mode, FailureMode::matrix_cracking);
  EXPECT_DOUBLE_EQ(latch.peak_index, 1.5);
}

} // namespace
} // namespace plyimpact::failure_criteria_tests
