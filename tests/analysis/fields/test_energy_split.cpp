// The absorbed energy split by mechanism (analysis/fields/energy_split.hpp, ES1): the parts add up to the
// absorbed energy within the run's energy balance error, each is the quantity the run reports on its own, and
// a plate that neither cracks nor delaminates absorbs only what its contact law dissipates and what it still
// holds when the impactor has left.
#include "plyimpact/analysis/fields/energy_split.hpp"
#include "support/impact_decks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace plyimpact::energy_split_tests {
namespace {

double impact_energy(const std::string& text) {
  const ImpactCase c(impact_case_description(parse_deck(text, "split.toml")));
  return 0.5 * c.settings().impactor.mass * std::pow(c.settings().impactor.velocity, 2);
}

void expect_closes(const AbsorbedEnergySplit& s, const ImpactResult& r, double e0) {
  std::printf("[ measured ] absorbed %.6g J: contact %.6g, plies %.6g, interfaces %.6g, plate %.6g, "
              "unaccounted %.3g J (balance error %.3g of %.4g J)\n",
              *r.absorbed_energy, s.contact, s.ply_damage, s.delamination, s.plate_vibration, s.unaccounted,
              r.energy_balance_error, e0);
  EXPECT_DOUBLE_EQ(s.contact + s.ply_damage + s.delamination + s.plate_vibration + s.unaccounted,
                   *r.absorbed_energy);
  // ES1's ε is the energy balance's error: within its reported value (rounded to three digits).
  EXPECT_LE(std::abs(s.unaccounted), r.energy_balance_error * e0 * 1.01 + 1e-12 * e0);
}

TEST(EnergySplit, AnElasticPlateAbsorbsWhatItsContactDissipatesAndWhatItStillHolds) {
  const std::string text = test::example_text("thesis-3.6-v268.toml");
  const ImpactResult r = test::run_deck(text);
  ASSERT_TRUE(r.absorbed_energy.has_value());
  const std::optional<AbsorbedEnergySplit> s = absorbed_energy_split(r);
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->ply_damage, 0.0);
  EXPECT_EQ(s->delamination, 0.0);
  EXPECT_EQ(s->contact, r.contact_dissipation);
  EXPECT_GT(s->plate_vibration, 0.0);
  expect_closes(*s, r, impact_energy(text));
}

TEST(EnergySplit, TheInterfacesPartIsWhatTheyDissipated) {
  // The stacked example on 5 × 5 elements, selectively scaled (docs/mass_scaling.md), to the end of its
  // event: its interfaces soften and crack under the impactor.
  std::string text = test::example_text("impact-delamination-explicit-selective.toml");
  text = test::with_key(test::with_key(text, "nx", "5"), "ny", "5");
  const ImpactResult r = test::run_deck(text);
  ASSERT_TRUE(r.absorbed_energy.has_value());
  ASSERT_TRUE(r.delamination.has_value());
  const std::optional<AbsorbedEnergySplit> s = absorbed_energy_split(r);
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->delamination, r.delamination->dissipated);
  EXPECT_GT(s->delamination, 0.0);
  expect_closes(*s, r, impact_energy(text));
}

TEST(EnergySplit, NoneWhileTheImpactorHasNotLeft) {
  ImpactResult r;
  r.final_plate_energy = 0.0;
  EXPECT_FALSE(absorbed_energy_split(r).has_value());
}

TEST(EnergySplit, ARunThatKeepsNoHistoryStillSplitsItsAbsorbedEnergy) {
  // The command streams history.csv instead of keeping it (io/run/impact_run.cpp): the split must not
  // depend on the samples kept in memory. Same run with and without a history: the same split.
  const std::string text = test::example_text("thesis-3.6-v268.toml");
  const ImpactCase c(impact_case_description(parse_deck(text, "split.toml")));
  RunRequest with;
  RunRequest without;
  without.history_every = 0;
  const ImpactResult a = c.run(with);
  const ImpactResult b = c.run(without);
  ASSERT_TRUE(b.history.empty());
  const std::optional<AbsorbedEnergySplit> sa = absorbed_energy_split(a);
  const std::optional<AbsorbedEnergySplit> sb = absorbed_energy_split(b);
  ASSERT_TRUE(sa.has_value());
  ASSERT_TRUE(sb.has_value());
  EXPECT_EQ(sb->plate_vibration, sa->plate_vibration);
  EXPECT_EQ(sa->plate_vibration, a.history.back().plate_kinetic + a.history.back().plate_strain);
}

} // namespace
} // namespace plyimpact::energy_split_tests
