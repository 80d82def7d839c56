// [delamination] (issue 19, docs/deck.md): the deck's interfaces become split_laminate's cuts (by default
// every change of orientation), the law's keys its parameters in SI whatever the deck's units, the
// penalty stiffness "auto" Turon et al.'s α E3 / t worked out by hand; what cannot run is refused with
// the key named. Run through the command line, the summary, report and CSV carry the interfaces.
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/deck/deck.hpp"
#include "support/cli.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace plyimpact::deck_delamination_tests {
namespace {

using test::small_deck;

/// The interface law of AS4/PEEK (docs/delamination.md: Camanho, Dávila & de Moura 2003, as read in
/// public secondary files), in SI.
const std::string as4_peek_law = R"(G_Ic = 969.0
G_IIc = 1719.0
bk_exponent = 2.284
normal_strength = 80e6
shear_strength = 100e6
)";

Deck deck_with(const std::string& delamination, const std::string& analysis = "impact",
               const std::string& more = "") {
  return parse_deck(small_deck(analysis, more + "[delamination]\n" + delamination), "deck.toml");
}

/// The DeckError message of parsing, or "" when it parses.
std::string error_of(const std::string& delamination, const std::string& more = "") {
  try {
    (void)deck_with(delamination, "impact", more);
  } catch (const DeckError& e) {
    return e.what();
  }
  return "";
}

/// A deck with progressive ply damage (T300/976's data) and the interfaces, `damage` and `interfaces`
/// added to [damage] and [delamination].
std::string plies_and_interfaces(const std::string& damage, const std::string& interfaces) {
  std::string text = small_deck("impact", "[damage]\nmodel = \"progressive\"\n" + damage +
                                              "[delamination]\n" + as4_peek_law + interfaces);
  text.replace(text.find("rho = 1389.2\n"), 13,
               "rho = 1389.2\nXt = 1.5e9\nXc = 1.2e9\nYt = 55.2e6\nYc = 294.0e6\nS12 = 101.1e6\n"
               "S23 = 32.94e6\nG_ft = 91.6e3\nG_fc = 79.9e3\nG_mt = 277.0\nG_mc = 788.0\n");
  return text;
}

TEST(DeckDelamination, ByDefaultTheLaminateIsCutWhereverTheOrientationChanges) {
  // [0_2/90_4/0_2]: the orientation changes after ply 2 and after ply 6 (0-based cuts 1 and 5).
  const Deck d = deck_with(as4_peek_law);
  ASSERT_TRUE(d.delamination);
  EXPECT_EQ(d.delamination->stack.cuts, (std::vector<int>{1, 5}));
  const CohesiveParameters& law = d.delamination->stack.interface;
  EXPECT_EQ(law.G_Ic, 969.0);
  EXPECT_EQ(law.G_IIc, 1719.0);
  EXPECT_EQ(law.bk_exponent, 2.284);
  EXPECT_EQ(law.normal_strength, 80e6);
  EXPECT_EQ(law.shear_strength, 100e6);
  EXPECT_EQ(law.onset, CohesiveOnset::turon_bk);
  // Penalty by hand: α = 50, E3 = E2 = 9.65 GPa of T300/976, and the thinner sub-laminate at either
  // interface is the 2-ply one, 2 × 0.465 mm: K = 50 × 9.65e9 / 0.93e-3 = 5.18817e14 Pa/m.
  EXPECT_NEAR(law.penalty_stiffness, 50.0 * 9.65e9 / 0.93e-3, 1e-6 * law.penalty_stiffness);
  EXPECT_TRUE(d.delamination->supports_on_all);
  EXPECT_EQ(d.time.laws, Integrator::lagged);
  EXPECT_EQ(d.delamination->stack.rule, CohesiveQuadrature::nodal);
  // The case the engine runs carries them unchanged.
  const ImpactCaseDescription c = impact_case_description(deck_with(as4_peek_law, "impact",
                                                                    "[impactor]\nmass = 0.3\nvelocity = 2.0\n"
                                                                    "radius = 6.35e-3\nE = 207e9\n"));
  ASSERT_TRUE(c.delamination);
  EXPECT_EQ(c.delamination->stack.cuts, d.delamination->stack.cuts);
  EXPECT_EQ(c.delamination->stack.interface.penalty_stiffness, law.penalty_stiffness);
}

TEST(DeckDelamination, ValuesTheDeckLeavesOutComeFromThePliesAtTheInterfaces) {
  // The plies' matrix data (IM7/8552-like: Yt 55.2 MPa, G_mt 277, G_mc 788 J/m²) give N, G_Ic and G_IIc;
  // S follows by Turon's relation, by hand 55.2 MPa × √(788/277) = 93.10 MPa; η is the IM7/8552 default.
  // A value the deck gives is the deck's, and only the others are reported as defaults.
  std::string text = plies_and_interfaces("", "");
  text.replace(text.find(as4_peek_law), as4_peek_law.size(), "G_IIc = 1000.0\n");
  const Deck d = parse_deck(text, "deck.toml");
  ASSERT_TRUE(d.delamination);
  const CohesiveParameters& law = d.delamination->stack.interface;
  EXPECT_EQ(law.G_Ic, 277.0);
  EXPECT_EQ(law.G_IIc, 1000.0);
  EXPECT_EQ(law.normal_strength, 55.2e6);
  EXPECT_NEAR(law.shear_strength, 55.2e6 * std::sqrt(1000.0 / 277.0), 1e-9 * law.shear_strength);
  EXPECT_EQ(law.bk_exponent, 1.634);
  std::vector<std::string> keys;
  for (const auto& [key, origin] : d.delamination->law_defaults)
    keys.push_back(key);
  EXPECT_EQ(keys, (std::vector<std::string>{"G_Ic", "bk_exponent", "normal_strength", "shear_strength"}));
  EXPECT_EQ(d.delamination->law_defaults.front().second, "G_mt of the plies at the interfaces");
  EXPECT_TRUE(parse_deck(plies_and_interfaces("", ""), "deck.toml").delamination->law_defaults.empty());
}

TEST(DeckDelamination, ListedInterfacesAndTheOtherChoicesAreRead) {
  const Deck d = deck_with("interfaces = [4]\npenalty_stiffness = 1e15\nonset = \"camanho-quadratic\"\n"
                           "points = \"gauss\"\nsupports = \"bottom\"\nintegration = \"implicit\"\n" +
                           as4_peek_law);
  EXPECT_EQ(d.delamination->stack.cuts, (std::vector<int>{3}));
  EXPECT_EQ(d.delamination->stack.interface.penalty_stiffness, 1e15);
  EXPECT_EQ(d.delamination->stack.interface.onset, CohesiveOnset::camanho_quadratic);
  EXPECT_EQ(d.delamination->stack.rule, CohesiveQuadrature::gauss);
  EXPECT_FALSE(d.delamination->supports_on_all);
  EXPECT_EQ(d.time.laws, Integrator::implicit);
  const Deck e = deck_with("integration = \"explicit\"\n" + as4_peek_law);
  EXPECT_EQ(e.time.laws, Integrator::central_difference);
}

TEST(DeckDelamination, InMillimetreUnitsTheLawBecomesSI) {
  // mm-N-MPa-tonne: toughness in N/mm (= kJ/m²), strengths in MPa, the penalty in N/mm³ (= 1e9 Pa/m).
  std::string text = small_deck("impact", "[delamination]\nG_Ic = 0.969\nG_IIc = 1.719\nbk_exponent = 2.284\n"
                                          "normal_strength = 80.0\nshear_strength = 100.0\n"
                                          "penalty_stiffness = 1e6\n");
  // the small deck is in SI: convert its numbers by hand to the mm system
  for (const auto& [from, to] :
       std::vector<std::pair<std::string, std::string>>{{"E1 = 144.8e9", "E1 = 144.8e3"},
                                                        {"E2 = 9.65e9", "E2 = 9.65e3"},
                                                        {"G12 = 7.10e9", "G12 = 7.10e3"},
                                                        {"G23 = 5.92e9", "G23 = 5.92e3"},
                                                        {"rho = 1389.2", "rho = 1389.2e-12"},
                                                        {"ply_thickness = 0.465e-3", "ply_thickness = 0.465"},
                                                        {"a = 0.127", "a = 127.0"},
                                                        {"b = 0.0762", "b = 76.2"}})
    text.replace(text.find(from), from.size(), to);
  const Deck d = parse_deck("units = \"mm-N-MPa-tonne\"\n" + text, "deck.toml");
  const CohesiveParameters& law = d.delamination->stack.interface;
  EXPECT_NEAR(law.G_Ic, 969.0, 1e-9);
  EXPECT_NEAR(law.G_IIc, 1719.0, 1e-9);
  EXPECT_NEAR(law.normal_strength, 80e6, 1e-6);
  EXPECT_NEAR(law.shear_strength, 100e6, 1e-6);
  EXPECT_NEAR(law.penalty_stiffness, 1e15, 1.0);
}

TEST(DeckDelamination, WhatCannotRunIsRefusedWithTheKeyNamed) {
  // located at the offending entry: its line in the deck, the column of the 8
  const std::string text = small_deck("impact", "[delamination]\ninterfaces = [8]\n" + as4_peek_law);
  const auto line =
      1 + std::count(text.begin(), text.begin() + static_cast<long>(text.find("interfaces")), '\n');
  EXPECT_NE(error_of("interfaces = [8]\n" + as4_peek_law)
                .find(fmt::format("deck.toml:{}:15: error: delamination.interfaces: 8 is not an interface of "
                                  "the 8-ply laminate: an interface lies after ply 1 to 7",
                                  line)),
            std::string::npos)
      << error_of("interfaces = [8]\n" + as4_peek_law);
  EXPECT_NE(error_of("interfaces = [0]\n" + as4_peek_law).find("0 is not an interface"), std::string::npos);
  EXPECT_NE(error_of("interfaces = [6, 2]\n" + as4_peek_law).find("listed once each"), std::string::npos);
  EXPECT_NE(error_of("interfaces = \"all\"\n" + as4_peek_law)
                .find("delamination.interfaces must be \"orientation-changes\" or a list"),
            std::string::npos);
  // Every value of the law that neither the deck nor the plies give, in one message, with its unit,
  // meaning and the ply data that would give it (the small deck's T300/976 has no strengths or
  // toughnesses; the B-K exponent has a default).
  EXPECT_NE(
      error_of("G_Ic = 969.0\n")
          .find("[delamination] needs the interface law's 5 values; 3 unknown: G_IIc (mode II "
                "toughness, J/m^2; or G_mc of every ply at an interface), normal_strength (interlaminar "
                "tensile strength, Pa; or Yt of every ply at an interface), shear_strength (interlaminar "
                "shear strength, Pa; or the three values it follows from)"),
      std::string::npos)
      << error_of("G_Ic = 969.0\n");
  EXPECT_NE(error_of(as4_peek_law + "onset = \"turon_bk\"\n").find("(did you mean \"turon-bk\"?)"),
            std::string::npos);
  EXPECT_NE(error_of(as4_peek_law + "supports = \"top\"\n")
                .find("delamination.supports must be one of all | bottom"),
            std::string::npos);
  // K too soft for the law's triangle to peak before its end: K ≤ N² / (2 G_Ic) = 3.3e12 Pa/m.
  EXPECT_NE(error_of(as4_peek_law + "penalty_stiffness = 1e12\n").find("[delamination]: "),
            std::string::npos);
  // ply damage (its data given) and interfaces whose [damage] and [delamination] integration differ:
  // refused with both keys and what runs
  std::string refused;
  try {
    (void)parse_deck(plies_and_interfaces("integration = \"implicit\"\n", "integration = \"explicit\"\n"),
                     "deck.toml");
  } catch (const DeckError& e) {
    refused = e.what();
  }
  EXPECT_NE(refused.find("[damage] integration = \"implicit\" and [delamination] integration = \"explicit\" "
                         "differ"),
            std::string::npos)
      << refused;
  EXPECT_NE(refused.find(
                "(the elastic plate with ply damage and interfaces runs with: implicit, lagged, explicit)"),
            std::string::npos)
      << refused;
  // and without the data, the data is what is missing
  EXPECT_NE(error_of(as4_peek_law, "[damage]\nmodel = \"progressive\"\n").find("needs positive Xt"),
            std::string::npos);
  EXPECT_NE(error_of(as4_peek_law + "typo = 1\n").find("typo"), std::string::npos);
}

// The plate steps with one integrator: a deck that names ply damage and delamination and no integration
// runs both lagged (the step that runs a whole event, docs/delamination.md); one that names it in one
// table has it for both (one value: Deck::time.laws).
TEST(DeckDelamination, PliesAndInterfacesStepWithTheIntegrationOneOfThemGives) {
  const auto integrations = [](const std::string& damage, const std::string& interfaces) {
    const Deck d = parse_deck(plies_and_interfaces(damage, interfaces), "deck.toml");
    return d.time.laws;
  };
  using enum Integrator;
  EXPECT_EQ(integrations("", ""), lagged);
  EXPECT_EQ(integrations("integration = \"implicit\"\n", ""), implicit);
  EXPECT_EQ(integrations("", "integration = \"implicit\"\n"), implicit);
  EXPECT_EQ(integrations("", "integration = \"explicit\"\n"), central_difference);
}

TEST(DeckDelamination, ALayupOfOneOrientationNeedsItsInterfacesListed) {
  std::string text = small_deck("impact", "[delamination]\n" + as4_peek_law);
  const std::string layup = "layup = \"[0_2/90_4/0_2]\"";
  text.replace(text.find(layup), layup.size(), "layup = \"[0_8]\"");
  try {
    (void)parse_deck(text, "deck.toml");
    FAIL() << "a unidirectional laminate has no change of orientation to cut";
  } catch (const DeckError& e) {
    EXPECT_NE(std::string(e.what()).find("every ply of the layup has the same orientation"),
              std::string::npos)
        << e.what();
  }
  text.replace(text.find("[delamination]\n"), 15, "[delamination]\ninterfaces = [4]\n");
  EXPECT_EQ(parse_deck(text, "deck.toml").delamination->stack.cuts, (std::vector<int>{3}));
}

TEST(DeckDelamination, OnlyTheImpactAnalysisRunsTheStackedPlate) {
  const Deck d = deck_with(as4_peek_law, "static", "[load]\npressure = 1e5\n");
  try {
    require_sections(d, AnalysisKind::static_);
    FAIL() << "a static analysis of the single laminate would silently ignore [delamination]";
  } catch (const DeckError& e) {
    EXPECT_NE(std::string(e.what()).find("[delamination] is read by the impact analysis only"),
              std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(require_sections(d, AnalysisKind::laminate));
}

TEST(DeckDelamination, AnImpactRunReportsItsInterfacesInTheSummaryReportAndCsv) {
  // 0.3 kg at 2 m/s on the 6 × 4 plate, the first 100 µs: the interfaces hold, so the areas are 0; what is
  // checked is that every output names the two interfaces of the layup.
  const test::fs::path dir = test::scratch("delamination");
  const test::fs::path deck = test::write(
      dir, small_deck("impact", "[impactor]\nmass = 0.3\nvelocity = 2.0\nradius = 6.35e-3\nE = 207e9\n"
                                "[time]\nend = 100e-6\n[delamination]\n" +
                                    as4_peek_law));
  const test::CommandResult r = test::run("impact " + deck.string() + " -o " + (dir / "out").string());
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(
      r.out.find("  delamination                       2 interface(s), after plies 2, 6; K = 5.19e+14 Pa/m"),
      std::string::npos)
      << r.out;
  const nlohmann::json j = test::read_json(dir / "out" / "summary.json");
  ASSERT_TRUE(j.contains("delamination")) << j.dump(1);
  const nlohmann::json& dl = j["delamination"];
  EXPECT_EQ(dl["interfaces_after_ply"], (std::vector<int>{2, 6}));
  EXPECT_EQ(dl["delaminated_area_m2"], (std::vector<double>{0.0, 0.0}));
  EXPECT_EQ(dl["projected_delaminated_area_m2"].get<double>(), 0.0);
  EXPECT_EQ(dl["G_IIc_J_per_m2"].get<double>(), 1719.0);
  // E2 G_Ic / N² = 9.65e9 × 969 / 80e6² = 1.4611 mm (mode I, the shorter); the 6 × 4 mesh's elements are
  // 127/6 = 21.2 mm long, their nodal points 10.6 mm apart.
  EXPECT_NEAR(dl["cohesive_zone_length_m"].get<double>(), 9.65e9 * 969.0 / (80e6 * 80e6), 1e-12);
  EXPECT_NEAR(dl["interface_point_spacing_m"].get<double>(), 0.127 / 12.0, 1e-12);
  bool zone_warned = false;
  for (const auto& w : j["warnings"])
    zone_warned = zone_warned || w.get<std::string>().find("cohesive zone") != std::string::npos;
  EXPECT_TRUE(zone_warned) << j["warnings"].dump(1);
  const std::string csv = test::read_text(dir / "out" / "delamination_elements.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "element,x_m,y_m,d_after_ply_2,d_after_ply_6");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 24); // header + one row per element
}

} // namespace
} // namespace plyimpact::deck_delamination_tests
