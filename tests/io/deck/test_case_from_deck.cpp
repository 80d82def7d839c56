// From decks to the engine's descriptions: regions of a deck reach the plate, and a deck whose two
// halves are regions with the plate's own laminate runs the one-region impact bit for bit; the deck's
// one Newton key becomes the case's Newton settings.
#include "plyimpact/io/deck/case_from_deck.hpp"

#include "plyimpact/analysis/impact/capabilities.hpp"
#include "plyimpact/analysis/integrators/newton_settings.hpp"
#include "plyimpact/io/deck/deck.hpp"

#include <gtest/gtest.h>

#include <string>

namespace plyimpact::case_from_deck_tests {
namespace {

const std::string plate_deck = R"(
[materials.m]
E1 = 129.0e9
E2 = 7.5e9
G12 = 3.5e9
nu12 = 0.33
rho = 1540.0
[laminate]
material = "m"
layup = "[45/90/-45/0]3s"
ply_thickness = 0.19375e-3
[plate]
a = 0.127
b = 0.0762
[mesh]
nx = 9
ny = 7
[boundary]
x0 = "ss"
xa = "ss"
y0 = "ss"
yb = "ss"
[impactor]
mass = 0.314
radius = 12.7e-3
E = 207e9
velocity = 2.92
[contact]
k = 0.6e9
[time]
dt = 1e-6
)";

const std::string same_laminate_right_half = R"(
[laminates.same]
material = "m"
layup = "[45/90/-45/0]3s"
ply_thickness = 0.19375e-3
[[region]]
laminate = "same"
x = [0.0635, 0.127]
y = [0.0, 0.0762]
)";

TEST(CaseFromDeck, RegionsGiveEachElementItsLaminate) {
  const DiscretePlate one = plate_model(parse_deck(plate_deck, "one.toml"));
  const DiscretePlate two = plate_model(parse_deck(plate_deck + same_laminate_right_half, "two.toml"));
  EXPECT_TRUE(one.single_section());
  ASSERT_EQ(two.laminates().size(), 2U);
  int right = 0;
  for (int e = 0; e < two.mesh().element_count(); ++e) {
    const bool in_region = two.mesh().map(e, 0.0, 0.0).x() >= 0.0635;
    EXPECT_EQ(two.section_index(e), in_region ? 1 : 0) << e;
    right += in_region ? 1 : 0;
  }
  EXPECT_EQ(right, 5 * 7); // 9 columns; the middle one has its centre on x = a/2 (bounds included)
}

TEST(CaseFromDeck, TwoRegionsWithTheSameLaminateRunTheOneRegionImpactBitForBit) {
  const ImpactResult one = ImpactCase(impact_case_description(parse_deck(plate_deck, "one.toml"))).run();
  const ImpactResult two =
      ImpactCase(impact_case_description(parse_deck(plate_deck + same_laminate_right_half, "two.toml")))
          .run();
  ASSERT_TRUE(one.complete);
  EXPECT_EQ(one.steps, two.steps);
  EXPECT_EQ(one.peak_force, two.peak_force);
  EXPECT_EQ(one.time_of_peak_force, two.time_of_peak_force);
  EXPECT_EQ(one.peak_contact_deflection, two.peak_contact_deflection);
  EXPECT_EQ(one.absorbed_energy, two.absorbed_energy);
  ASSERT_EQ(one.history.size(), two.history.size());
  for (std::size_t i = 0; i < one.history.size(); ++i) {
    EXPECT_EQ(one.history[i].force, two.history[i].force) << i;
    EXPECT_EQ(one.history[i].plate_strain, two.history[i].plate_strain) << i;
  }
}

// [damage] refactor_tolerance is how Newton–Newmark refreshes its matrix, not the plies' law: it reaches
// the case's NewtonSettings over the defaults of its row of the table of what runs, and leaves the law's
// settings as they are; left out, the case takes the row's defaults (newton empty).
TEST(CaseFromDeck, RefactorToleranceIsTheIntegratorsSetting) {
  std::string text = plate_deck;
  text.replace(text.find("rho = 1540.0\n"), 13,
               "rho = 1540.0\nXt = 1.5e9\nXc = 1.2e9\nYt = 55.2e6\nYc = 294.0e6\nS12 = 101.1e6\n"
               "S23 = 32.94e6\nG_ft = 91.6e3\nG_fc = 79.9e3\nG_mt = 277.0\nG_mc = 788.0\n");
  const std::string damage = "[damage]\nmodel = \"progressive\"\n";
  for (const std::string integration : {"implicit", "lagged"}) {
    const std::string keys = damage + "integration = \"" + integration + "\"\n";
    const ImpactCaseDescription given =
        impact_case_description(parse_deck(text + keys + "refactor_tolerance = 0.2\n", "d.toml"));
    const ImpactCaseDescription left_out = impact_case_description(parse_deck(text + keys, "d.toml"));
    ASSERT_TRUE(given.newton.has_value()) << integration;
    NewtonSettings expected = newton_newmark_defaults(model_kind(given), case_integrator(given));
    EXPECT_EQ(expected.refactor_tolerance, 0.05) << integration;
    expected.refactor_tolerance = 0.2;
    EXPECT_EQ(*given.newton, expected) << integration;
    EXPECT_FALSE(left_out.newton.has_value()) << integration;
    EXPECT_EQ(given.progressive_damage, left_out.progressive_damage) << integration;
  }
}

} // namespace
} // namespace plyimpact::case_from_deck_tests
