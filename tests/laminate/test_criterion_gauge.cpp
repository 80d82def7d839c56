// The Lipschitz gauges of the failure criteria (laminate/criterion_gauge.hpp): each is an upper bound of
// its criterion's index at every plate stress state, exact on the state's own mode, and its branches
// move by no more than the column norms of W times the change of the stresses.
#include "plyimpact/laminate/criterion_gauge.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace plyimpact::criterion_gauge_tests {
namespace {

/// T300/976 (thesis Table 4.2 strengths; Xt, Xc typical values) and a T700/M21-like set whose
/// (Yc/2S23)² − 1 has the other sign, so both signs of Hashin's linear term are covered.
Material material(bool t300) {
  Material m;
  m.E1 = t300 ? 144.8e9 : 130e9;
  m.E2 = t300 ? 9.65e9 : 7.7e9;
  m.G12 = t300 ? 7.1e9 : 4.8e9;
  m.nu12 = 0.3;
  m.strength.Xt = t300 ? 1.5e9 : 2.5e9;
  m.strength.Xc = t300 ? 1.2e9 : 1.2e9;
  m.strength.Yt = t300 ? 55.2e6 : 50e6;
  m.strength.Yc = t300 ? 294e6 : 200e6;
  m.strength.S12 = t300 ? 101.1e6 : 80e6;
  m.strength.S23 = t300 ? 32.94e6 : 75.4e6;
  return m;
}

const std::vector<Criterion> gauged{Criterion::max_stress, Criterion::max_strain, Criterion::tsai_hill,
                                    Criterion::hoffman,    Criterion::tsai_wu,    Criterion::hashin,
                                    Criterion::sun};

/// Random stresses around the failure surface: each component up to ~1.5× its strength, either sign,
/// some components zero (pure modes).
std::vector<PlateStressVector> random_states(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  std::bernoulli_distribution zero(0.3);
  const PlateStressVector scale{2e9, 150e6, 90e6, 90e6, 60e6};
  std::vector<PlateStressVector> out;
  for (int i = 0; i < n; ++i) {
    PlateStressVector s;
    for (Eigen::Index j = 0; j < 5; ++j)
      s(j) = zero(rng) ? 0.0 : u(rng) * scale(j);
    out.push_back(s);
  }
  return out;
}

PlyStress as_ply(const PlateStressVector& s) {
  return PlyStress{.s11 = s(0), .s22 = s(1), .t23 = s(4), .t13 = s(3), .t12 = s(2)};
}

double gauge_index(const std::vector<GaugeBranch>& gauge, const PlateStressVector& s) {
  double largest = -1e300;
  for (const GaugeBranch& b : gauge)
    largest = std::max(largest, b.index(s));
  return largest;
}

TEST(CriterionGauge, BoundsTheIndexAtEveryStateAndEqualsItOnAPureMode) {
  std::mt19937 rng(20261130);
  const std::vector<PlateStressVector> states = random_states(rng, 20000);
  for (const bool t300 : {true, false}) {
    const Material m = material(t300);
    for (const Criterion c : gauged) {
      const auto gauge = criterion_gauge(c, m);
      ASSERT_TRUE(gauge) << to_string(c);
      int tight = 0;
      for (const PlateStressVector& s : states) {
        const double index = evaluate(c, as_ply(s), m).index;
        const double bound = gauge_index(*gauge, s);
        ASSERT_LE(index, bound + 1e-12 * (1.0 + std::abs(index))) << to_string(c) << " at " << s.transpose();
        tight += std::abs(bound - index) <= 1e-12 * (1.0 + std::abs(index)) ? 1 : 0;
      }
      // Equal wherever the branches that do not hold at the state stay below the one that does: at
      // least a third of these states, all of them for the single-surface forms; Tsai–Hill's four
      // (X, Y) branches coincide only where σ11 = σ22 = 0 (about 9 % of these states).
      const auto n = static_cast<int>(states.size());
      if (c == Criterion::hoffman || c == Criterion::tsai_wu)
        EXPECT_EQ(tight, n) << to_string(c);
      else
        EXPECT_GT(tight, c == Criterion::tsai_hill ? n / 20 : n / 3) << to_string(c);
    }
  }
}

TEST(CriterionGauge, PureTransverseCompressionAtYcIsIndexOneOnTheCompletedSquare) {
  // Hashin's matrix compression at σ22 = −Yc alone: [(Yc/2S23)² − 1](−1) + Yc²/(4 S23²) = 1.
  for (const bool t300 : {true, false}) {
    const Material m = material(t300);
    const PlateStressVector s{0.0, -*m.strength.Yc, 0.0, 0.0, 0.0};
    EXPECT_NEAR(gauge_index(*criterion_gauge(Criterion::hashin, m), s), 1.0, 1e-12);
    EXPECT_NEAR(hashin(as_ply(s), m.strength).index, 1.0, 1e-12);
  }
}

TEST(CriterionGauge, EveryBranchMovesByAtMostItsColumnNormsTimesTheStressChange) {
  std::mt19937 rng(11);
  const std::vector<PlateStressVector> a = random_states(rng, 5000), b = random_states(rng, 5000);
  for (const Criterion c : gauged) {
    const auto gauge = criterion_gauge(c, material(false));
    for (const GaugeBranch& branch : *gauge) {
      const PlateStressVector columns = branch.W.colwise().norm().transpose();
      for (std::size_t i = 0; i < a.size(); ++i) {
        const double change = std::abs(branch.norm(a[i]) - branch.norm(b[i]));
        ASSERT_LE(change, columns.dot((a[i] - b[i]).cwiseAbs()) * (1.0 + 1e-12)) << to_string(c);
      }
    }
  }
}

TEST(CriterionGauge, ThresholdIsWhereTheBranchIndexReachesTheLimit) {
  for (const Criterion c : gauged) {
    const auto gauge = criterion_gauge(c, material(true));
    for (const GaugeBranch& b : *gauge)
      for (const double limit : {0.0, 0.3, 1.0}) {
        const double n = b.threshold(limit);
        EXPECT_NEAR(b.quadratic ? n * n - b.h.squaredNorm() : n, limit, 1e-12) << to_string(c);
      }
  }
}

TEST(CriterionGauge, NoneWhereTheFormIsNotAGaugeOrTheStrengthsAreMissing) {
  const Material m = material(true);
  EXPECT_FALSE(criterion_gauge(Criterion::choi_chang_matrix, m));
  EXPECT_FALSE(criterion_gauge(Criterion::choi_chang_delamination, m));
  // |F12*| > 1: Tsai–Wu's surface is open, its form indefinite.
  EXPECT_FALSE(criterion_gauge(Criterion::tsai_wu, m, CriterionOptions{.tsai_wu_f12_star = -1.5}));
  Material no_s23 = m;
  no_s23.strength.S23.reset();
  EXPECT_FALSE(criterion_gauge(Criterion::hashin, no_s23));
}

} // namespace
} // namespace plyimpact::criterion_gauge_tests
