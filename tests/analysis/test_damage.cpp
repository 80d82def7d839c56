// Damage tracking and the threshold velocity (SPEC §6–7): irreversibility, consistency of the fast
// path with direct stress recovery, threshold monotonicity, tolerance and determinism.
#include "plyimpact/analysis/damage_tracker.hpp"
#include "plyimpact/analysis/impact_case.hpp"
#include "plyimpact/analysis/threshold_search.hpp"
#include "plyimpact/io/case_from_deck.hpp"
#include "plyimpact/io/deck.hpp"
#include "plyimpact/io/impact_report.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <tuple>

namespace plyimpact {
namespace {

/// Thesis Table 4.2 plate (T300/976, [0_2/90_4/0_2], simply supported), a coarse mesh for speed,
/// steel sphere R = 6.35 mm.
Deck table42_deck(double velocity,
                  const std::string& criteria = R"("choi-chang-matrix", "choi-chang-delamination")") {
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
Da = 1.8
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
end = 80e-6
[damage]
criteria = [)" + criteria +
                        "]\n",
                    "table42.toml");
}

struct DamageRun {
  std::vector<DamageOnset> onsets;
  std::vector<DamageAreaSample> areas;
};

DamageRun run_with_damage(const Deck& deck) {
  const ImpactCase impact(impact_case_description(deck));
  DamageTracker tracker(impact.model(), parse_criteria(deck.damage.criteria));
  RunRequest run;
  run.observers = {&tracker};
  (void)impact.run(run);
  return {tracker.onsets(), tracker.area_history()};
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

TEST(Damage, FastChoiChangPathEqualsTheGeneralPath) {
  // Choi–Chang-only runs use exact index bounds to skip points; adding a face criterion forces the
  // general path. The Choi–Chang onsets must be the same, point for point.
  const DamageRun fast = run_with_damage(table42_deck(20.0));
  const DamageRun general =
      run_with_damage(table42_deck(20.0, R"("choi-chang-matrix", "choi-chang-delamination", "max-stress")"));
  std::vector<DamageOnset> g;
  for (const auto& o : general.onsets)
    if (o.criterion != Criterion::max_stress) g.push_back(o);
  ASSERT_FALSE(g.empty());
  ASSERT_EQ(fast.onsets.size(), g.size());
  for (std::size_t i = 0; i < g.size(); ++i) {
    EXPECT_EQ(fast.onsets[i].element, g[i].element);
    EXPECT_EQ(fast.onsets[i].ply, g[i].ply);
    EXPECT_EQ(fast.onsets[i].interface, g[i].interface);
    EXPECT_EQ(fast.onsets[i].time, g[i].time);
    EXPECT_NEAR(fast.onsets[i].sigma22, g[i].sigma22, 1e-6 * 1e6);
    EXPECT_NEAR(fast.onsets[i].tau23, g[i].tau23, 1e-6 * 1e6);
  }
}

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
} // namespace plyimpact
