// Issue 50's last "Must show": every shipped example with progressive ply damage or delamination runs to the
// end of its event with an energy balance error of at most 1 % of the impact energy, or says in its own
// header that it stops earlier on purpose. Read from the reference summaries of tests/reference/examples/,
// which Examples/ExampleUnchanged keeps equal to what the program gives for each deck: an example whose
// physics moves must update its reference, and then meet these bounds again.
#include "support/cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
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

} // namespace

} // namespace damage_examples_tests
