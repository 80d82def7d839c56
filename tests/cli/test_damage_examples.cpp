// Issue 50's last "Must show": every shipped example with progressive ply damage or delamination runs to the
// end of its event with an energy balance error of at most 1 % of the impact energy, or says in its own
// header that it stops earlier on purpose. Read from the reference summaries of tests/reference/examples/,
// which Examples/ExampleUnchanged keeps equal to what the program gives for each deck: an example whose
// physics moves must update its reference, and then meet these bounds again.
#include "plyimpact/io/deck/deck.hpp"
#include "support/cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace damage_examples_tests {

namespace {

using namespace plyimpact::test;

const fs::path examples_dir = fs::path(PLYIMPACT_SOURCE_DIR) / "examples";
const fs::path reference_dir = fs::path(PLYIMPACT_SOURCE_DIR) / "tests" / "reference" / "examples";

/// The deck's lines without their comments and surrounding blanks.
std::vector<std::string> statements(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string line = text.substr(start, end - start);
    line = line.substr(0, line.find('#'));
    const std::size_t first = line.find_first_not_of(" \t\r");
    const std::size_t last = line.find_last_not_of(" \t\r");
    lines.push_back(first == std::string::npos ? std::string() : line.substr(first, last - first + 1));
    start = end + 1;
  }
  return lines;
}

/// An impact deck (not a sweep, not a threshold search) that asks for progressive ply damage or delamination.
bool damage_impact_deck(const std::string& text) {
  bool damage = false, impact = false, sweep = false;
  for (const std::string& line : statements(text)) {
    impact = impact || line == "analysis = \"impact\"";
    sweep = sweep || line.starts_with("[sweep");
    damage = damage || line == "[delamination]" || line == "model = \"progressive\"";
  }
  return damage && impact && !sweep;
}

/// The names (without .toml) of the shipped damage and delamination impact decks.
std::vector<std::string> damage_examples() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(examples_dir))
    if (entry.path().extension() == ".toml" && damage_impact_deck(read_text(entry.path())))
      names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(ShippedDamageExamples, ThereAreSomeToCheck) {
  // The progressive examples (damage-progressive*), the stacks (impact-delamination*), ...: at least the
  // nine decks of 2026-12-01, so that a change of the deck syntax cannot empty the list below unseen.
  EXPECT_GE(damage_examples().size(), 9U);
}

TEST(ShippedDamageExamples, EachHasAReferenceThatTheExampleTestsCompare) {
  for (const std::string& name : damage_examples())
    EXPECT_TRUE(fs::exists(reference_dir / (name + ".summary.json")))
        << name << ": no tests/reference/examples/" << name
        << ".summary.json (scripts/run-examples captures it), so nothing checks what it gives";
}

TEST(ShippedDamageExamples, EachEndsItsEventWithinOnePercentOrSaysWhyItStops) {
  for (const std::string& name : damage_examples()) {
    const fs::path reference = reference_dir / (name + ".summary.json");
    if (!fs::exists(reference)) continue; // the test above names it
    const nlohmann::json s = read_json(reference);
    const double error = s.at("energy_balance_error").get<double>();
    EXPECT_LE(error, 0.01) << name << ": energy balance error " << error << " of the impact energy";
    if (s.at("complete").get<bool>()) {
      EXPECT_FALSE(s.at("absorbed_energy").is_null()) << name << ": complete, but no absorbed energy";
      continue;
    }
    // A deliberate short example says so in its header, with the reason (the time it would take).
    EXPECT_NE(read_text(examples_dir / (name + ".toml")).find("incomplete on purpose"), std::string::npos)
        << name << " stops before the end of its event (" << s.at("incomplete_reason").get<std::string>()
        << ") and its header does not say why (\"... reported incomplete on purpose\")";
  }
}

// Issue 79's four Rivallant tests (examples/rivallant-*.toml), shipped with a 1 us end (their whole events
// take hours today, issue 80): each takes its ply card by name — T700/M21, and T700GC/M21 for the 25 J panel
// (nu12 0.33, G_mt 0.6 N/mm) — cuts the six interfaces between the ply groups of [0_2/45_2/90_2/-45_2]s, and
// on the rig's default damage mesh lowers no strength: the rig sizes the elements from the smallest band
// limit of the fracture-plane law, in-plane shear 2 G12 G_ms / S12^2 (1.27 mm, 1.67 mm on the T700GC card),
// which the rig line of each reference states.
TEST(RivallantExamples, EachTakesItsCardCutsTheSixInterfacesAndLowersNoStrength) {
  for (const std::string energy : {"6.5", "17", "25", "29.5"}) {
    const std::string name = "rivallant-" + energy + "J";
    const plyimpact::Deck deck =
        plyimpact::parse_deck(read_text(examples_dir / (name + ".toml")), name + ".toml");
    ASSERT_EQ(deck.materials.size(), 1U) << name;
    const plyimpact::Material& m = deck.materials.front();
    const bool gc = energy == "25";
    EXPECT_EQ(deck.material_cards.front().second, gc ? "T700GC-M21" : "T700-M21") << name;
    EXPECT_EQ(m.nu12, gc ? 0.33 : 0.3) << name;
    EXPECT_EQ(*m.toughness.G_mt, gc ? 600.0 : 500.0) << name;
    const double band_limit = 2.0 * m.G12 * *m.toughness.G_ms / (*m.strength.S12 * *m.strength.S12);
    EXPECT_NEAR(band_limit, gc ? 1.667e-3 : 1.269e-3, 1e-6) << name;

    const nlohmann::json s = read_json(reference_dir / (name + ".summary.json"));
    EXPECT_EQ(s.at("delamination").at("interfaces_after_ply"), nlohmann::json({2, 4, 6, 10, 12, 14})) << name;
    EXPECT_EQ(s.at("damage").at("strength_reduction").at("elements_lowered").get<int>(), 0) << name;
    const std::string rig = s.at("rig").get<std::string>();
    char limit[32];
    std::snprintf(limit, sizeof limit, "(%.2f mm), less 10 %%", band_limit * 1e3);
    EXPECT_NE(rig.find(limit), std::string::npos) << name << ": " << rig;
  }
}

} // namespace

} // namespace damage_examples_tests
