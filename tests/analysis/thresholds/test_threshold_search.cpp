// The threshold search's progress measure: the bracket [no failure, failure] narrows from its first
// width w0 to the tolerance; progress is log(w0 / w) / log(w0 / tolerance), 0 before any failure.
// Damage thresholds on a progressive-damage plate (examples/damage-progressive.toml): the bracket holds
// the transition (a stand-alone run at `lower` has no damage of the kind, one at `velocity` has), an
// area above 0+ is the first damage, and the matrix cracks at a lower velocity than the fibres break.
#include "plyimpact/analysis/thresholds/threshold_search.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/deck/deck.hpp"
#include "test_paths.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace threshold_search_tests {

namespace {

using namespace plyimpact;

TEST(ThresholdSearch, BracketProgressIsTheLogOfTheBracketsNarrowing) {
  std::vector<ThresholdTrial> trials{{5.0, false, 0.7}};
  EXPECT_EQ(bracket_progress(trials, 0.01), 0.0); // no failure yet: no bracket
  trials.push_back({10.0, true, 1.2});
  EXPECT_EQ(bracket_progress(trials, 0.01), 0.0); // the first bracket [5, 10]
  trials.push_back({7.5, true, 1.1});             // [5, 7.5]: halved
  EXPECT_NEAR(bracket_progress(trials, 0.01), std::log(2.0) / std::log(500.0), 1e-15);
  trials.push_back({7.49, false, 0.99}); // [7.49, 7.5]: the tolerance reached
  EXPECT_NEAR(bracket_progress(trials, 0.01), 1.0, 1e-12);
}

TEST(ThresholdSearch, BracketProgressIsCompleteWhenTheFirstBracketIsAlreadyNarrowEnough) {
  EXPECT_EQ(bracket_progress({{1.0, false, 0.9}, {1.005, true, 1.0}}, 0.01), 1.0);
}

std::string example_text() {
  std::ifstream in(std::string(PLYIMPACT_SOURCE_DIR) + "/examples/damage-progressive.toml");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

ImpactCaseDescription example_case(const std::string& text, double first_trial) {
  ImpactCaseDescription d = impact_case_description(parse_deck(text, "damage-progressive.toml"));
  d.impactor.velocity = first_trial;
  return d;
}

ThresholdOptions tolerance(double tol) {
  ThresholdOptions o;
  o.tolerance = tol;
  return o;
}

/// The largest damage variable of the fibre (or matrix) modes anywhere in the plate at the end of a
/// stand-alone run at velocity v (a case of its own: nothing shared with the search).
double largest_damage(const std::string& text, double v, DamageCriterion::Kind kind) {
  const ImpactCase alone(example_case(text, v));
  const ImpactResult r = alone.run();
  double d = 0.0;
  for (const ElementPlyDamage& e : r.progressive.value().element_ply_damage)
    for (const DamageMode m : all_damage_modes)
      if (counts_for(kind, m)) d = std::max(d, e.damage[m]);
  return d;
}

TEST(DamageThreshold, NamesReadBack) {
  for (const auto k : {DamageCriterion::Kind::fibre_damage, DamageCriterion::Kind::matrix_damage,
                       DamageCriterion::Kind::damage_area})
    EXPECT_EQ(parse_damage_criterion(to_string(k)), k);
  EXPECT_FALSE(parse_damage_criterion("hashin"));
  EXPECT_TRUE(counts_for(DamageCriterion::Kind::fibre_damage, DamageMode::fibre_compression));
  EXPECT_FALSE(counts_for(DamageCriterion::Kind::fibre_damage, DamageMode::matrix_tension));
  EXPECT_TRUE(counts_for(DamageCriterion::Kind::matrix_damage, DamageMode::matrix_compression));
  EXPECT_FALSE(counts_for(DamageCriterion::Kind::matrix_damage, DamageMode::fibre_tension));
}

TEST(DamageThreshold, MatrixThresholdBracketsTheTransitionOfStandAloneRuns) {
  // Bisection from 1 m/s to 0.01 m/s on the example plate. Stand-alone runs (fresh cases) at both ends
  // of the final bracket: no matrix damage at `lower`, matrix damage at `velocity`, and the damage the
  // search saw at `velocity` is the stand-alone run's first damage (same time, mode and ply): the trials
  // are whole progressive runs from the virgin plate, nothing carried from one to the next.
  const std::string text = example_text();
  const ImpactCase impact(example_case(text, 1.0));
  const DamageCriterion matrix{DamageCriterion::Kind::matrix_damage, 0.0};
  const ThresholdResult r = find_threshold_velocity(impact, matrix, tolerance(0.01));
  ASSERT_TRUE(r.found);
  ASSERT_TRUE(r.damage.has_value());
  std::printf("[ measured ] matrix-damage threshold %.6f m/s (holds at %.6f), %zu trials\n", r.velocity,
              r.lower, r.trials.size());
  EXPECT_LE(r.velocity - r.lower, 0.01);
  EXPECT_EQ(largest_damage(text, r.lower, DamageCriterion::Kind::matrix_damage), 0.0);
  EXPECT_GT(largest_damage(text, r.velocity, DamageCriterion::Kind::matrix_damage), 0.0);
  const ImpactResult alone = ImpactCase(example_case(text, r.velocity)).run();
  ASSERT_TRUE(alone.progressive->first_mode.has_value());
  EXPECT_EQ(*alone.progressive->first_mode, r.damage->mode);
  EXPECT_EQ(alone.progressive->first()->ply, r.damage->ply);
  EXPECT_EQ(alone.progressive->first()->time, r.damage->time);
  EXPECT_EQ(r.damage->mode, DamageMode::matrix_tension); // the bottom 0° ply, as at 2 m/s
  EXPECT_EQ(r.damage->ply, 4);
  // The same search again on the same case: the same trials, bit for bit.
  const ThresholdResult again = find_threshold_velocity(impact, matrix, tolerance(0.01));
  EXPECT_EQ(again.velocity, r.velocity);
  EXPECT_EQ(again.trials.size(), r.trials.size());
}

TEST(DamageThreshold, AnAreaAboveZeroPlusIsTheFirstDamage) {
  // The damaged area counts points with d >= [damage] area_threshold; with area_threshold -> 0+ and a
  // limit X -> 0+, "area > X" is "some d > 0 in any mode": the first damage, which on this plate is
  // matrix damage (MatrixCracksBeforeFibresBreak). Same bisection, same trials, same bracket.
  std::string text = example_text();
  text.replace(text.find("model = \"progressive\""), 21, "model = \"progressive\"\narea_threshold = 1e-12");
  const ImpactCase impact(example_case(text, 1.0));
  const ThresholdResult area = find_threshold_velocity(
      impact, DamageCriterion{DamageCriterion::Kind::damage_area, 1e-30}, tolerance(0.02));
  const ThresholdResult matrix = find_threshold_velocity(
      impact, DamageCriterion{DamageCriterion::Kind::matrix_damage, 0.0}, tolerance(0.02));
  ASSERT_TRUE(area.found && matrix.found);
  std::printf("[ measured ] area > 0+: %.6f m/s, matrix damage: %.6f m/s\n", area.velocity, matrix.velocity);
  EXPECT_EQ(area.velocity, matrix.velocity);
  EXPECT_EQ(area.lower, matrix.lower);
  EXPECT_GT(area.damage->projected_area, 0.0);
}

TEST(DamageThreshold, MatrixCracksBeforeFibresBreakOnTheExamplePlate) {
  // [0/90]s T300/976 under a 30 g impactor: bending stretches the bottom 0° ply across its fibres, and
  // the transverse tensile strain to failure Yt/E2 = 55.2/9650 = 0.57 % is reached long before the top
  // ply's fibres reach Xc/E1 = 1200/144800 = 0.83 % in compression (the contact pressure adds to it
  // there, but only near the peak force). The fibre search is coarse (0.5 m/s) but its lower end
  // already lies well above the matrix threshold.
  const std::string text = example_text();
  const ThresholdResult matrix =
      find_threshold_velocity(ImpactCase(example_case(text, 1.0)),
                              DamageCriterion{DamageCriterion::Kind::matrix_damage, 0.0}, tolerance(0.05));
  const ThresholdResult fibre =
      find_threshold_velocity(ImpactCase(example_case(text, 2.0)),
                              DamageCriterion{DamageCriterion::Kind::fibre_damage, 0.0}, tolerance(0.5));
  ASSERT_TRUE(matrix.found && fibre.found);
  std::printf("[ measured ] matrix damage from %.4f m/s, fibre damage in [%.4f, %.4f] m/s (%s, ply %d)\n",
              matrix.velocity, fibre.lower, fibre.velocity,
              std::string(to_string(fibre.damage->mode)).c_str(), fibre.damage->ply);
  EXPECT_LT(matrix.velocity, fibre.lower);
  EXPECT_TRUE(counts_for(DamageCriterion::Kind::fibre_damage, fibre.damage->mode));
}

TEST(DamageThreshold, NeedsAProgressiveCaseAndAPositiveArea) {
  std::string text = example_text();
  const ImpactCase progressive(example_case(text, 1.0));
  EXPECT_THROW(
      (void)find_threshold_velocity(progressive, DamageCriterion{DamageCriterion::Kind::damage_area, 0.0}),
      std::invalid_argument);
  text.replace(text.find("model = \"progressive\""), 21, "model = \"onset\"");
  const ImpactCase onset(example_case(text, 1.0));
  EXPECT_THROW(
      (void)find_threshold_velocity(onset, DamageCriterion{DamageCriterion::Kind::matrix_damage, 0.0}),
      std::invalid_argument);
}

} // namespace

} // namespace threshold_search_tests
