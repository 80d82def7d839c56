// The one table of plate models × time integrators (analysis/impact/capabilities.hpp; issue 49): the facade
// and the deck refuse exactly the pairs the table refuses, with its reason; one integrator for the whole
// plate; [time] integration = "explicit" makes the laws' steps explicit; docs/deck.md lists the table
// as the code has it.
#include "plyimpact/analysis/impact/capabilities.hpp"
#include "support/impact_decks.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace plyimpact::capabilities_tests {
namespace {

const auto with = test::with_key;

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The message of the std::invalid_argument or DeckError that `f` throws ("" when it does not throw).
template <class F>
std::string refusal_of(F f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(Capabilities, DeckMdListsTheTableAsTheCodeHasIt) {
  const std::string doc = read(std::string(PLYIMPACT_SOURCE_DIR) + "/docs/deck.md");
  const std::string table = capability_table_markdown();
  EXPECT_NE(doc.find(table), std::string::npos) << "docs/deck.md must hold, verbatim:\n" << table;
}

TEST(Capabilities, ArchitectureMdShowsTheTableAsTheCodeHasIt) {
  const std::string doc = read(std::string(PLYIMPACT_SOURCE_DIR) + "/docs/architecture.md");
  std::string indented; // the table as a list item's block: each line indented by two spaces
  const std::string table = capability_table_markdown();
  for (std::size_t at = 0; at < table.size();) {
    const std::size_t end = table.find('\n', at);
    indented += "  " + table.substr(at, end == std::string::npos ? std::string::npos : end + 1 - at);
    at = end == std::string::npos ? table.size() : end + 1;
  }
  EXPECT_NE(doc.find(indented), std::string::npos) << "docs/architecture.md must hold, verbatim:\n"
                                                   << indented;
}

TEST(Capabilities, DeckMdListsTheRestrictionsAsTheCodeHasThem) {
  const std::string doc = read(std::string(PLYIMPACT_SOURCE_DIR) + "/docs/deck.md");
  EXPECT_NE(doc.find(restrictions_markdown()), std::string::npos) << "docs/deck.md must hold, verbatim:\n"
                                                                  << restrictions_markdown();
}

TEST(Capabilities, EveryModelRunsWithSomeIntegratorOrSaysWhyNot) {
  for (const bool karman : {false, true})
    for (const bool damage : {false, true})
      for (const bool interfaces : {false, true}) {
        const ModelKind m{false, karman, damage, interfaces};
        for (const Integrator i :
             {Integrator::implicit, Integrator::lagged, Integrator::central_difference}) {
          const Capability c = capability(m, i);
          EXPECT_FALSE(c.detail.empty()) << model_name(m) << " / " << to_string(i);
          EXPECT_EQ(refusal(m, i).has_value(), !c.runs);
        }
      }
  // The pairs this issue opened: explicit steps for the elastic and the von Kármán plate; the von Kármán
  // plate with interfaces, and with ply damage too, lagged and explicit; every stack, implicit.
  EXPECT_TRUE(capability({false, false, false, false}, Integrator::central_difference).runs);
  EXPECT_TRUE(capability({false, true, false, false}, Integrator::central_difference).runs);
  for (const bool plies : {false, true})
    for (const Integrator i : {Integrator::lagged, Integrator::central_difference})
      EXPECT_TRUE(capability({false, true, plies, true}, i).runs);
  for (const bool karman : {false, true}) // and every stacked plate with implicit steps
    for (const bool plies : {false, true})
      EXPECT_TRUE(capability({false, karman, plies, true}, Integrator::implicit).runs);
  // A rigid target refuses what needs a plate, with the physical reason, whatever the integrator.
  EXPECT_NE(refusal({true, false, true, false}, Integrator::implicit).value_or("").find("no plies to crack"),
            std::string::npos);
}

TEST(Capabilities, TheFacadeRefusesWhatTheTableRefusesWithItsReason) {
  // A rigid target with plies to crack: refused with the physical reason the table gives.
  ImpactCaseDescription d =
      impact_case_description(parse_deck(test::example_text("damage-progressive.toml"), "d.toml"));
  ASSERT_TRUE(d.progressive_damage);
  d.plate.rigid = true;
  const std::string why = refusal_of([&] { const ImpactCase c(d); });
  EXPECT_NE(why.find(std::string(*refusal({true, false, true, false}, Integrator::implicit))),
            std::string::npos)
      << why;
  EXPECT_NE(why.find("no plies to crack"), std::string::npos) << why;
}

TEST(Capabilities, ThePlateStepsWithOneIntegrator) {
  // [time] integration = "explicit" with the plies' own step set to another: refused at the deck's key.
  const std::string damage = test::example_text("damage-progressive.toml");
  const std::string conflict = with(damage, "end", "1.5e-4\nintegration = \"explicit\"") +
                               "integration = \"lagged\"\n"; // appended to [damage], the last table
  const std::string why = refusal_of([&] { (void)parse_deck(conflict, "c.toml"); });
  EXPECT_NE(why.find("[time] integration = \"explicit\" and [damage] integration = \"lagged\" differ"),
            std::string::npos)
      << why;
  // Left out, the plies' step follows [time]: explicit.
  const Deck deck = parse_deck(with(damage, "end", "1.5e-4\nintegration = \"explicit\""), "e.toml");
  ASSERT_TRUE(deck.damage.progressive.has_value());
  EXPECT_EQ(deck.time.laws, Integrator::central_difference);
  // The same conflict built in code (Python, sweeps) is refused by the facade.
  ImpactCaseDescription d = impact_case_description(parse_deck(damage, "d.toml"));
  d.time.integration = TimeScheme::central_difference;
  EXPECT_NE(refusal_of([&] { const ImpactCase c(d); }).find("differ"), std::string::npos);
}

TEST(Capabilities, ExplicitStepsRefuseErrorControlledSteps) {
  const std::string deck =
      with(test::example_text("impact-adaptive-steps.toml"), "adaptive", "true\nintegration = \"explicit\"");
  const std::string why = refusal_of([&] { (void)parse_deck(deck, "a.toml"); });
  EXPECT_NE(why.find("remove adaptive = true"), std::string::npos) << why;
}

/// The restriction whose rule is `rule`.
const Restriction& restriction(std::string_view rule) {
  for (const Restriction& r : restrictions())
    if (r.rule == rule) return r;
  throw std::logic_error("no restriction " + std::string(rule));
}

/// "c.toml:LINE:" of the first line of `text` that starts with `key_line`.
std::string place_of(const std::string& text, const std::string& key_line) {
  const std::size_t at = text.find("\n" + key_line);
  EXPECT_NE(at, std::string::npos) << key_line;
  return fmt::format("c.toml:{}:",
                     std::count(text.begin(), text.begin() + static_cast<long>(at) + 1, '\n') + 1);
}

/// A deck that breaks one restriction, the line of its key, and the same case built in code.
struct Broken {
  std::string rule;
  std::string deck;
  std::string key_line;
  std::function<void(ImpactCaseDescription&)> break_case; ///< applied to the unbroken deck's case
  std::string unbroken;
};

// Each restriction a deck breaks (issue 78): the deck refuses it at the key that makes the choice, the
// facade refuses the same case built in code with the same message, and the message is the table's. The
// non-linear plate with error-controlled steps, the Green–Lagrange strains on MITC9 and the consistent
// mass under explicit steps were refused only once a run had started building its model.
TEST(Capabilities, TheDeckRefusesEachRestrictionAtItsKeyAndTheFacadeWithTheSameMessage) {
  const std::string damage = test::example_text("damage-progressive.toml");
  const std::string expl = test::example_text("thesis-3.6-v268-explicit.toml");
  const std::string adaptive = test::example_text("impact-adaptive-steps.toml");
  const std::vector<Broken> cases{
      {"ply damage needs the MITC9 element", with(damage, "element", "\"q9\""), "element = \"q9\"",
       [](ImpactCaseDescription& d) { d.mesh.element = ElementFormulation::q9; }, damage},
      {"Green–Lagrange strains need the q9 element",
       with(with(expl, "strain_measure", "\"green-lagrange\""), "element", "\"mitc9\""), "strain_measure",
       [](ImpactCaseDescription& d) {
         d.nonlinear->measure = StrainMeasure::green_lagrange;
         d.mesh.element = ElementFormulation::mitc9;
       },
       expl},
      {"explicit steps need the lumped mass", with(expl, "mass", "\"consistent\""), "mass = \"consistent\"",
       [](ImpactCaseDescription& d) { d.mesh.mass = MassMatrix::consistent; }, expl},
      {"error-controlled steps: the elastic plate and the rigid target only",
       with(adaptive, "analysis", "\"impact\"\nnonlinear = true"), "adaptive",
       [](ImpactCaseDescription& d) { d.nonlinear = NonlinearImpactSettings{}; }, adaptive},
      {"selective mass scaling: a stack only", with(expl, "end", "\"auto\"\nmass_scaling = \"selective\""),
       "mass_scaling",
       [](ImpactCaseDescription& d) { d.time.mass_scaling.kind = MassScalingKind::selective; }, expl},
  };
  for (const Broken& c : cases) {
    SCOPED_TRACE(c.rule);
    const std::string message(restriction(c.rule).message);
    const std::string deck_error = refusal_of([&] { (void)parse_deck(c.deck, "c.toml"); });
    EXPECT_TRUE(deck_error.starts_with(place_of(c.deck, c.key_line))) << deck_error;
    EXPECT_NE(deck_error.find("error: " + message), std::string::npos) << deck_error;
    ImpactCaseDescription d = impact_case_description(parse_deck(c.unbroken, "u.toml"));
    c.break_case(d);
    EXPECT_EQ(refusal_of([&] { const ImpactCase built(d); }), message);
  }
}

} // namespace
} // namespace plyimpact::capabilities_tests
