// Damage tracking and the threshold velocity (SPEC §6–7): irreversibility, consistency of the fast
// path with direct stress recovery, threshold monotonicity, tolerance and determinism.
#include "plyimpact/analysis/fields/damage_tracker.hpp"
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/analysis/thresholds/threshold_search.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/io/results/impact_report.hpp"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <set>
#include <tuple>

namespace plyimpact::damage_tests {
namespace {

/// Thesis Table 4.2 plate (T300/976, [0_2/90_4/0_2], simply supported), a coarse mesh for speed,
/// steel sphere R = 6.35 mm.
Deck table42_deck(double velocity,
                  const std::string& criteria = R"("choi-chang-matrix", "choi-chang-delamination")",
                  double end = 80e-6, double Da = 1.8) {
  return parse_deck(R"(
[materials.T300_976]
E1 = 144.8e9
E2 = 9.65e9
G12 = 7.10e9
G23 = 5.92e9
nu12 = 0.30
rho = 1389.2
Xt = 1.5e9
Xc = 1.2e9
Yt = 55.2e6
Yc = 294.0e6
S12 = 101.1e6
S23 = 32.94e6
Da = )" + std::to_string(Da) +
                        R"(
[laminate]
material = "T300_976"
layup = "[0_2/90_4/0_2]"
ply_thickness = 0.465e-3
[plate]
a = 0.127
b = 0.0762
[mesh]
nx = 7
ny = 5
[boundary]
x0 = "ss"
xa = "ss"
y0 = "ss"
yb = "ss"
[impactor]
density = 7870.0
radius = 6.35e-3
E = 200e9
velocity = )" + std::to_string(velocity) +
                        R"(
[contact]
alpha_cr = 8.03e-5
[time]
dt = 0.27e-6
end = )" + std::to_string(end) +
                        R"(
[damage]
criteria = [)" + criteria +
                        "]\n",
                    "table42.toml");
}

struct DamageRun {
  std::vector<DamageOnset> onsets;
  std::vector<DamageAreaSample> areas;
  std::vector<double> peaks;        ///< largest index over the run, per criterion of the deck
  long evaluated = 0, observed = 0; ///< point evaluations, points × observations
};

DamageRun run_with_damage(const Deck& deck, bool skip = true) {
  const ImpactCase impact(impact_case_description(deck));
  DamageOptions options;
  options.skip_proven_points = skip;
  DamageTracker tracker(impact.model(), parse_criteria(deck.damage.criteria), options);
  RunRequest run;
  run.observers = {&tracker};
  (void)impact.run(run);
  DamageRun out;
  out.onsets = tracker.onsets();
  out.areas = tracker.area_history();
  for (const Criterion c : tracker.criteria())
    out.peaks.push_back(tracker.peak_index(c));
  out.evaluated = tracker.evaluated_points();
  out.observed = tracker.observed_points();
  return out;
}

TEST(Damage, FailedPointsStayFailedAndFailedAreaNeverShrinks) {
  const DamageRun r = run_with_damage(table42_deck(20.0));
  ASSERT_FALSE(r.onsets.empty());
  std::set<std::tuple<int, int, int, int, int, int>> seen;
  for (const auto& o : r.onsets) // each (criterion, layer, Gauss point) fails once
    EXPECT_TRUE(seen.insert(std::make_tuple(static_cast<int>(o.criterion), o.ply, o.interface, o.element,
                                            o.ipgs, o.jpgs))
                    .second);
  std::map<std::tuple<int, int, int>, double> area;
  double last_time = 0.0;
  for (const auto& a : r.areas) {
    auto& previous = area[std::make_tuple(static_cast<int>(a.criterion), a.ply, a.interface)];
    EXPECT_GT(a.area, previous);
    EXPECT_GE(a.time, last_time);
    previous = a.area;
    last_time = a.time;
  }
}

TEST(Damage, DelaminationOnlyWhereAnAdjacentPlyHasCracked) {
  const DamageRun r = run_with_damage(table42_deck(20.0));
  int delaminations = 0;
  for (const auto& d : r.onsets)
    delaminations += d.criterion == Criterion::choi_chang_delamination ? 1 : 0;
  ASSERT_GT(delaminations, 0);
  for (const auto& d : r.onsets) {
    if (d.criterion != Criterion::choi_chang_delamination) continue;
    bool cracked_neighbour = false;
    for (const auto& m : r.onsets)
      if (m.criterion == Criterion::choi_chang_matrix && m.element == d.element && m.ipgs == d.ipgs &&
          m.jpgs == d.jpgs && (m.ply == d.interface || m.ply == d.interface + 1) && m.time <= d.time)
        cracked_neighbour = true;
    EXPECT_TRUE(cracked_neighbour) << "interface " << d.interface << " element " << d.element;
  }
}

/// The tracker skips points while exact bounds (and their growth along the element's path since the
/// point was last evaluated) prove that nothing can change; without the skipping it evaluates every
/// point every step. The onsets and peak indices must be the same, point for point and bit for bit.
DamageRun expect_fast_path_equals_general_path(double velocity, const std::string& criteria, double end) {
  const Deck deck = table42_deck(velocity, criteria, end);
  const DamageRun fast = run_with_damage(deck);
  const DamageRun general = run_with_damage(deck, false);
  const std::vector<DamageOnset>& g = general.onsets;
  EXPECT_FALSE(g.empty());
  EXPECT_EQ(general.evaluated, general.observed); // the reference skips nothing
  EXPECT_EQ(fast.onsets.size(), g.size());
  for (std::size_t i = 0; i < std::min(g.size(), fast.onsets.size()); ++i) {
    EXPECT_EQ(fast.onsets[i].criterion, g[i].criterion);
    EXPECT_EQ(fast.onsets[i].element, g[i].element);
    EXPECT_EQ(fast.onsets[i].ipgs, g[i].ipgs);
    EXPECT_EQ(fast.onsets[i].jpgs, g[i].jpgs);
    EXPECT_EQ(fast.onsets[i].ply, g[i].ply);
    EXPECT_EQ(fast.onsets[i].interface, g[i].interface);
    EXPECT_EQ(fast.onsets[i].time, g[i].time);
    EXPECT_NEAR(fast.onsets[i].sigma22, g[i].sigma22, 1e-6 * 1e6);
    EXPECT_NEAR(fast.onsets[i].tau23, g[i].tau23, 1e-6 * 1e6);
  }
  EXPECT_EQ(fast.peaks, general.peaks);
  return fast;
}

TEST(Damage, FastChoiChangPathEqualsTheGeneralPath) {
  expect_fast_path_equals_general_path(20.0, R"("choi-chang-matrix", "choi-chang-delamination")", 80e-6);
}

TEST(Damage, FastPathEqualsTheGeneralPathOverAWholeEventWithVibration) {
  // 400 µs: the impactor leaves and the plate rings, so points are proven, re-evaluated and
  // proven again many times.
  expect_fast_path_equals_general_path(20.0, R"("choi-chang-matrix", "choi-chang-delamination")", 400e-6);
}

TEST(Damage, FastPathWithDelaminationAloneStillFollowsTheMatrixCracksThatGateIt) {
  // Without the matrix criterion the cracks that open (2.43) are still tracked exactly.
  expect_fast_path_equals_general_path(20.0, R"("choi-chang-delamination")", 200e-6);
}

TEST(Damage, FaceCriteriaSkipThroughTheirGaugesWithTheSameOnsetsAndPeaks) {
  // Hashin, Sun, max-stress, max-strain, Tsai–Wu, Hoffman and Tsai–Hill at the ply faces, proven safe through
  // their gauges (laminate/criterion_gauge.hpp), over the contact and the ringing after it.
  const DamageRun hashin =
      expect_fast_path_equals_general_path(20.0, R"("hashin", "choi-chang-matrix")", 400e-6);
  EXPECT_LT(hashin.evaluated, hashin.observed / 2) << "the gauges prove most points safe";
  expect_fast_path_equals_general_path(
      20.0, R"("sun", "max-stress", "max-strain", "tsai-wu", "hoffman", "tsai-hill")", 400e-6);
}

TEST(Damage, ACriterionWithoutAGaugeEvaluatesEveryPoint) {
  // Tsai–Wu with |F12*| > 1 (an open surface, an indefinite form) has no gauge: no point is skipped.
  const ImpactCase impact(impact_case_description(table42_deck(20.0, R"("tsai-wu")", 40e-6)));
  DamageOptions open_surface;
  open_surface.criterion_options.tsai_wu_f12_star = -1.5;
  DamageTracker tracker(impact.model(), {Criterion::tsai_wu}, open_surface);
  RunRequest run;
  run.observers = {&tracker};
  (void)impact.run(run);
  EXPECT_GT(tracker.observed_points(), 0);
  EXPECT_EQ(tracker.evaluated_points(), tracker.observed_points());
}
/// Random bending fields (w, θx, θy on the free DOFs, in-plane DOFs zero), seeded.
Eigen::VectorXd random_bending_field(const DiscretePlate& model, std::mt19937& rng) {
  std::normal_distribution<double> n01;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(model.dofs().free_count());
  for (int n = 0; n < model.mesh().node_count(); ++n)
    for (int d = 2; d < 5; ++d)
      if (const int eq = model.dofs().equation(n, d); eq >= 0) u(eq) = n01(rng) * (d == 2 ? 1e-4 : 1e-2);
  return u;
}

class SkippingOnRandomStates : public testing::TestWithParam<double> {};

TEST_P(SkippingOnRandomStates, NeverHidesAFailureOrAPeak) {
  // The skipping rests on two inequalities (the index bound, and its growth along the element's path
  // since the last evaluation); a state sequence that drifts slowly and sometimes jumps, changes
  // shape and sign, and crosses failure at some points and not others, tests both harder than an
  // impact does. The reference is the tracker without skipping.
  // Da < 1: the delamination bound no longer covers the matrix cracks that gate it, so the cracks'
  // own bound must keep points evaluated (with Da ≥ 1 it never binds).
  const ImpactCase impact(impact_case_description(
      table42_deck(20.0, R"("choi-chang-matrix", "choi-chang-delamination")", 80e-6, GetParam())));
  const DiscretePlate& model = impact.model();
  std::mt19937 rng(20261126);
  const Eigen::VectorXd shape1 = random_bending_field(model, rng), shape2 = random_bending_field(model, rng);
  const auto peak_of = [&](const Eigen::VectorXd& u) {
    DamageTracker probe(model, {Criterion::choi_chang_matrix});
    probe.observe(0, 0.0, 0.0, u);
    return probe.peak_index(Criterion::choi_chang_matrix);
  };
  const Eigen::VectorXd phi1 = shape1 / peak_of(shape1),
                        phi2 = shape2 / peak_of(shape2); // index 1 at amplitude 1
  std::vector<Eigen::VectorXd> states;
  std::normal_distribution<double> n01;
  double s = 0.1, r = 0.0;
  for (int k = 0; k < 600; ++k) {
    s = std::clamp(s + 0.03 * n01(rng) + (k % 97 == 96 ? 0.6 * n01(rng) : 0.0), -1.6, 1.6);
    r = std::clamp(r + 0.03 * n01(rng), -1.2, 1.2);
    const double spike = k % 31 == 30 ? 1.5 * n01(rng) : 0.0; // one state only, then back
    states.emplace_back(0.8 * (s + spike) * phi1 + 0.5 * r * phi2);
  }
  for (const std::vector<Criterion>& criteria :
       {std::vector{Criterion::choi_chang_matrix, Criterion::choi_chang_delamination},
        std::vector{Criterion::choi_chang_delamination}, std::vector{Criterion::choi_chang_matrix},
        std::vector{Criterion::hashin, Criterion::choi_chang_delamination},
        std::vector{Criterion::max_stress, Criterion::max_strain, Criterion::tsai_wu, Criterion::hoffman,
                    Criterion::sun, Criterion::tsai_hill}}) {
    DamageOptions every_point;
    every_point.skip_proven_points = false;
    DamageTracker fast(model, criteria), general(model, criteria, every_point);
    for (std::size_t k = 0; k < states.size(); ++k) {
      fast.observe(static_cast<long>(k), 1e-6 * static_cast<double>(k), 0.0, states[k]);
      general.observe(static_cast<long>(k), 1e-6 * static_cast<double>(k), 0.0, states[k]);
    }
    const std::vector<DamageOnset>& g = general.onsets();
    ASSERT_GE(g.size(), 5U);
    ASSERT_EQ(fast.onsets().size(), g.size());
    for (std::size_t i = 0; i < g.size(); ++i) {
      EXPECT_EQ(fast.onsets()[i].criterion, g[i].criterion);
      EXPECT_EQ(fast.onsets()[i].element, g[i].element);
      EXPECT_EQ(fast.onsets()[i].ipgs, g[i].ipgs);
      EXPECT_EQ(fast.onsets()[i].jpgs, g[i].jpgs);
      EXPECT_EQ(fast.onsets()[i].ply + fast.onsets()[i].interface, g[i].ply + g[i].interface);
      EXPECT_EQ(fast.onsets()[i].time, g[i].time);
    }
    for (const Criterion c : criteria)
      EXPECT_EQ(fast.peak_index(c), general.peak_index(c));
    std::printf("  %zu criteria: %zu onsets, peak index %.4f\n", criteria.size(), g.size(),
                general.peak_index(criteria.front()));
  }
}

INSTANTIATE_TEST_SUITE_P(Da, SkippingOnRandomStates, testing::Values(1.8, 0.2));

TEST(Threshold, MonotoneWithinToleranceAndDeterministic) {
  const Deck deck = table42_deck(5.0);
  const ImpactCase impact(impact_case_description(deck));
  ThresholdOptions options;
  options.tolerance = 0.02;
  const ThresholdResult r = find_threshold_velocity(impact, Criterion::choi_chang_matrix, options);
  ASSERT_TRUE(r.found);
  EXPECT_LE(r.velocity - r.lower, options.tolerance);
  ASSERT_TRUE(r.first_failure.has_value());
  std::printf("  threshold (7x5 mesh): %.4f m/s after %zu runs; first failure ply %d element %d\n",
              r.velocity, r.trials.size(), r.first_failure->ply, r.first_failure->element);
  // Monotone: every trial at or above the threshold failed, every one below did not.
  for (const auto& t : r.trials)
    EXPECT_EQ(t.failed, t.velocity >= r.velocity) << t.velocity;
  // Independent check of both ends of the bracket.
  const auto fails = [&](double v) {
    DamageTracker tracker(impact.model(), {Criterion::choi_chang_matrix});
    RunRequest run;
    run.impactor = impact.settings().impactor;
    run.impactor->velocity = v;
    run.observers = {&tracker};
    (void)impact.run(run);
    return tracker.any_failure();
  };
  EXPECT_TRUE(fails(r.velocity));
  EXPECT_TRUE(fails(r.velocity + 0.5));
  EXPECT_FALSE(fails(r.lower));
  EXPECT_FALSE(fails(r.lower - 0.5));
  // Deterministic: the same search gives the same velocity, bit for bit.
  EXPECT_EQ(find_threshold_velocity(impact, Criterion::choi_chang_matrix, options).velocity, r.velocity);
}

} // namespace
} // namespace plyimpact::damage_tests
