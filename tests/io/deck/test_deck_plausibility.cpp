// Plausibility of a deck (io/deck/deck_plausibility.hpp, docs/deck.md): well-formed decks whose numbers are a
// unit slip away from the plausible range (10³, 10⁶ and the like in each quantity family) are read with
// a warning that names the key, the unit the number looks like and the number to write; --strict turns
// them into errors; every shipped example reads without one.
#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/io/deck/deck_plausibility.hpp"
#include "support/cli.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace plyimpact::deck_plausibility_tests {
namespace {

namespace fs = std::filesystem;

using test::read_text;
using test::with_line;

/// examples/thesis-3.6-v268.toml (SI) and its mm-N-MPa-tonne twin: 6.14 kg, R = 12.7 mm, 2.68 m/s on a
/// 127 × 76.2 mm [45/90/-45/0]3s plate, k = 0.6e9 N/m^1.5, dt = 1 µs (Hertz contact time 4.3 ms).
const fs::path examples = fs::path(PLYIMPACT_SOURCE_DIR) / "examples";
const std::string si_deck = read_text(examples / "thesis-3.6-v268.toml");
const std::string mm_deck = read_text(examples / "thesis-3.6-v268-mm.toml");

struct Slip {
  std::string name;     ///< what the case slips
  std::string deck;     ///< the deck
  std::string expected; ///< the start of the warning
};

std::vector<std::string> warnings_of(const std::string& deck) {
  return parse_deck(deck, "deck.toml").warnings;
}

std::string joined(const std::vector<std::string>& warnings) {
  std::string s;
  for (const auto& w : warnings)
    s += w + "\n";
  return s;
}

bool has_warning(const std::vector<std::string>& warnings, const std::string& start) {
  for (const auto& w : warnings)
    if (w.rfind(start, 0) == 0) return true;
  return false;
}

const std::string strengths = "Xt = 1.5e9\nYt = 40e6\nrho = 1540.0";
const std::string graded = "grading = \"auto\"\nsize_at_impact = 1";

/// Unit slips of each quantity family, each with the warning it must give.
std::vector<Slip> slips() {
  const std::string moduli = " (a ply modulus is expected between 500e6 and 1.5e12 Pa)";
  std::string mm_graded = with_line(mm_deck, "nx = 15", "grading = \"auto\"");
  mm_graded = with_line(mm_graded, "ny = 11", "");
  return {
      // moduli (ply and impactor)
      {"E2 in kPa (1e3)", with_line(si_deck, "E2 = ", "E2 = 7.5e6"),
       "materials.thesis_3_6.E2 = 7.5e6: this looks like kPa; decks are in Pa (SI) — write 7.5e9" + moduli},
      {"E2 in MPa (1e6)", with_line(si_deck, "E2 = ", "E2 = 7500"),
       "materials.thesis_3_6.E2 = 7500: this looks like MPa; decks are in Pa (SI) — write 7.5e9, or set "
       "units "
       "= \"mm-N-MPa-tonne\" for the whole deck" +
           moduli},
      {"G12 in MPa (1e6)", with_line(si_deck, "G12 = ", "G12 = 3500"),
       "materials.thesis_3_6.G12 = 3500: this looks like MPa; decks are in Pa (SI) — write 3.5e9"},
      {"G13 in kPa (1e3)", with_line(si_deck, "G13 = ", "G13 = 3.5e6"),
       "materials.thesis_3_6.G13 = 3.5e6: this looks like kPa; decks are in Pa (SI) — write 3.5e9"},
      {"G23 in GPa (1e9)", with_line(si_deck, "G23 = ", "G23 = 3.5"),
       "materials.thesis_3_6.G23 = 3.5: this looks like GPa; decks are in Pa (SI) — write 3.5e9"},
      {"impactor E in MPa (1e6)", with_line(si_deck, "E = ", "E = 207000"),
       "impactor.E = 207000: this looks like MPa; decks are in Pa (SI) — write 207e9"},
      {"G12 in Pa in an mm deck (1e6 too large)", with_line(mm_deck, "G12 = ", "G12 = 3.5e9"),
       "materials.thesis_3_6.G12 = 3.5e9: this looks like Pa; this deck is in MPa (units = "
       "\"mm-N-MPa-tonne\") — write 3500 (a ply shear modulus is expected between 100 and 500000 MPa)"},
      // strengths
      {"Xt in MPa (1e6)", with_line(with_line(si_deck, "rho = ", strengths), "Xt = ", "Xt = 1500"),
       "materials.thesis_3_6.Xt = 1500: this looks like MPa; decks are in Pa (SI) — write 1.5e9"},
      {"Xt in kPa (1e3)", with_line(with_line(si_deck, "rho = ", strengths), "Xt = ", "Xt = 1.5e6"),
       "materials.thesis_3_6.Xt = 1.5e6: this looks like kPa; decks are in Pa (SI) — write 1.5e9"},
      {"Yt in MPa (1e6)", with_line(with_line(si_deck, "rho = ", strengths), "Yt = ", "Yt = 40"),
       "materials.thesis_3_6.Yt = 40: this looks like MPa; decks are in Pa (SI) — write 40e6"},
      {"Yt 1e3 too large", with_line(with_line(si_deck, "rho = ", strengths), "Yt = ", "Yt = 40e9"),
       "materials.thesis_3_6.Yt = 40e9 Pa: implausible (a matrix or shear strength is expected between 1e6 "
       "and 5e9 Pa); check its unit"},
      // densities
      {"rho in g/cm^3 (1e3)", with_line(si_deck, "rho = ", "rho = 1.54"),
       "materials.thesis_3_6.rho = 1.54: this looks like g/cm^3; decks are in kg/m^3 (SI) — write 1540 (a "
       "density is expected between 300 and 25000 kg/m^3)"},
      {"rho in g/mm^3 (1e6)", with_line(si_deck, "rho = ", "rho = 1.54e-3"),
       "materials.thesis_3_6.rho = 0.00154: this looks like g/mm^3; decks are in kg/m^3 (SI) — write 1540"},
      {"rho in tonne/mm^3 in an SI deck", with_line(si_deck, "rho = ", "rho = 1.54e-9"),
       "materials.thesis_3_6.rho = 1.54e-9: this looks like tonne/mm^3; decks are in kg/m^3 (SI) — write "
       "1540, or set units = \"mm-N-MPa-tonne\" for the whole deck"},
      {"rho in kg/m^3 in an mm deck", with_line(mm_deck, "rho = ", "rho = 1540"),
       "materials.thesis_3_6.rho = 1540: this looks like kg/m^3; this deck is in tonne/mm^3 (units = "
       "\"mm-N-MPa-tonne\") — write 1.54e-9"},
      {"impactor density in g/cm^3", with_line(si_deck, "mass = 6.14", "density = 7.8"),
       "impactor.density = 7.8: this looks like g/cm^3; decks are in kg/m^3 (SI) — write 7800"},
      // ply thickness
      {"ply thickness in mm (1e3)", with_line(si_deck, "ply_thickness = ", "ply_thickness = 0.19375"),
       "laminate.ply_thickness = 0.19375: this looks like mm; decks are in m (SI) — write 193.75e-6"},
      {"ply thickness in µm (1e6)", with_line(si_deck, "ply_thickness = ", "ply_thickness = 193.75"),
       "laminate.ply_thickness = 193.75: this looks like µm; decks are in m (SI) — write 193.75e-6"},
      // plate size
      {"plate side in mm (1e3)", with_line(si_deck, "a = ", "a = 127"),
       "plate.a = 127: this looks like mm; decks are in m (SI) — write 0.127, or set units = "
       "\"mm-N-MPa-tonne\" for the whole deck (a plate side is expected between 0.01 and 10 m)"},
      {"plate side in µm (1e6)", with_line(si_deck, "b = ", "b = 76200"),
       "plate.b = 76200: this looks like µm; decks are in m (SI) — write 0.0762"},
      {"plate side in m in an mm deck", with_line(mm_deck, "a = ", "a = 0.127"),
       "plate.a = 0.127: this looks like m; this deck is in mm (units = \"mm-N-MPa-tonne\") — write 127"},
      {"graded-mesh size in mm", with_line(with_line(si_deck, "nx = 15", graded), "ny = 11", ""),
       "mesh.size_at_impact = 1: this looks like mm; decks are in m (SI) — write 0.001"},
      // impactor mass, radius, velocity, energy
      {"mass in g (1e3)", with_line(si_deck, "mass = 6.14", "mass = 6140"),
       "impactor.mass = 6140: this looks like g; decks are in kg (SI) — write 6.14"},
      {"mass in mg (1e6)", with_line(si_deck, "mass = 6.14", "mass = 6.14e6"),
       "impactor.mass = 6.14e6: this looks like mg; decks are in kg (SI) — write 6.14"},
      {"mass in tonne (1e-3)", with_line(si_deck, "mass = 6.14", "mass = 0.314e-3"),
       "impactor.mass = 314e-6: this looks like tonne; decks are in kg (SI) — write 0.314, or set units = "
       "\"mm-N-MPa-tonne\" for the whole deck"},
      {"mass in kg in an mm deck", with_line(mm_deck, "mass = 6.14e-3", "mass = 6.14"),
       "impactor.mass = 6.14: this looks like kg; this deck is in tonne (units = \"mm-N-MPa-tonne\") — write "
       "0.00614"},
      {"radius in mm (1e3)", with_line(si_deck, "radius = ", "radius = 12.7"),
       "impactor.radius = 12.7: this looks like mm; decks are in m (SI) — write 0.0127"},
      {"radius in µm (1e6)", with_line(si_deck, "radius = ", "radius = 12.7e3"),
       "impactor.radius = 12700: this looks like µm; decks are in m (SI) — write 0.0127"},
      {"velocity in mm/s (1e3)", with_line(si_deck, "velocity = ", "velocity = 2680"),
       "impactor.velocity = 2680: this looks like mm/s; decks are in m/s (SI) — write 2.68"},
      {"velocity in m/s in an mm deck (1e3)", with_line(mm_deck, "velocity = ", "velocity = 2.68"),
       "impactor.velocity = 2.68: this looks like m/s; this deck is in mm/s (units = \"mm-N-MPa-tonne\") — "
       "write 2680"},
      {"energy in mJ (1e3)", with_line(si_deck, "velocity = ", "energy = 22050"),
       "impactor.energy = 22050: this looks like mJ; decks are in J (SI) — write 22.05"},
      // contact
      {"k in N/mm^1.5", with_line(si_deck, "k = ", "k = 18973.67"),
       "contact.k = 18973.7: 1.74e-05 times the Hertz stiffness of this impactor on ply 1 (k = \"auto\" "
       "gives "
       "1.09097e9 N/m^1.5); this looks like N/mm^1.5; decks are in N/m^1.5 (SI) — write 600e6"},
      {"k 1e3 too large", with_line(si_deck, "k = ", "k = 0.6e12"),
       "contact.k = 600e9: 550 times the Hertz stiffness of this impactor on ply 1 (k = \"auto\" gives "
       "1.09097e9 N/m^1.5); check its unit"},
      {"k in N/m^1.5 in an mm deck", with_line(mm_deck, "k = ", "k = 0.6e9"),
       "contact.k = 600e6: 1.74e+04 times the Hertz stiffness of this impactor on ply 1 (k = \"auto\" gives "
       "34499.6 N/mm^1.5); this looks like N/m^1.5; this deck is in N/mm^1.5 (units = \"mm-N-MPa-tonne\") — "
       "write 18973.7"},
      {"alpha_cr in mm (1e3)", with_line(si_deck, "load = ", "load = \"point\"\nalpha_cr = 0.17"),
       "contact.alpha_cr = 0.17: this looks like mm; decks are in m (SI) — write 170e-6"},
      // time
      {"dt in ms (1e3)", with_line(si_deck, "dt = ", "dt = 1e-3"),
       "time.dt = 0.001: this looks like ms; decks are in s (SI) — write 1e-6 (a time step of this impact "
       "(Hertz contact time 0.00168258 s) is expected between 16.8258e-9 and 336.515e-6 s)"},
      {"dt in µs (1e6)", with_line(si_deck, "dt = ", "dt = 1"),
       "time.dt = 1: this looks like µs; decks are in s (SI) — write 1e-6"},
      {"end in ms (1e3)", with_line(si_deck, "end = ", "end = 8.6"),
       "time.end = 8.6: this looks like ms; decks are in s (SI) — write 0.0086"},
  };
}

TEST(DeckPlausibility, EveryUnitSlipGivesItsWarning) {
  const std::vector<Slip> cases = slips();
  ASSERT_GE(cases.size(), 20U);
  for (const Slip& s : cases) {
    std::vector<std::string> w;
    try {
      w = warnings_of(s.deck);
    } catch (const DeckError& e) {
      ADD_FAILURE() << s.name << ": " << e.what();
      continue;
    }
    EXPECT_TRUE(has_warning(w, s.expected)) << s.name << "\nexpected: " << s.expected << "\ngot:\n"
                                            << joined(w);
  }
}

TEST(DeckPlausibility, ASlipOfOneQuantityGivesOneWarning) {
  // Quantities that do not enter other checks: each slip is reported once, nothing else.
  for (const auto& [from, to] :
       std::vector<std::pair<std::string, std::string>>{{"E2 = ", "E2 = 7500"},
                                                        {"rho = ", "rho = 1.54"},
                                                        {"a = ", "a = 127"},
                                                        {"mass = 6.14", "mass = 6140"},
                                                        {"velocity = ", "velocity = 2680"},
                                                        {"dt = ", "dt = 1"}})
    EXPECT_EQ(warnings_of(with_line(si_deck, from, to)).size(), 1U)
        << to << "\n"
        << joined(warnings_of(with_line(si_deck, from, to)));
}

TEST(DeckPlausibility, AWholeMaterialInMPaGivesOneWarningPerModulus) {
  std::string deck = si_deck;
  for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{
           {"E1", "129000"}, {"E2", "7500"}, {"G12", "3500"}, {"G13", "3500"}, {"G23", "3500"}})
    deck = with_line(deck, key + " = ", key + " = " + value);
  const auto w = warnings_of(deck);
  ASSERT_EQ(w.size(), 5U) << joined(w);
  EXPECT_TRUE(has_warning(w, "materials.thesis_3_6.E1 = 129000: this looks like MPa")) << joined(w);
}

TEST(DeckPlausibility, ALaminateThickerThanAFifthOfTheSpanIsNoLongerAPlate) {
  // [45/90/-45/0]30s: 240 plies of 0.19375 mm = 46.5 mm on a 76.2 mm wide plate (limit 15.24 mm).
  const auto w = warnings_of(with_line(si_deck, "layup = ", "layup = \"[45/90/-45/0]30s\""));
  ASSERT_EQ(w.size(), 1U) << joined(w);
  EXPECT_EQ(w[0], "[laminate] is 0.0465 m thick, more than a fifth of the plate's shorter side (0.0762 m): "
                  "plate theory no longer applies (a thick plate or a solid needs a 3-D model); check "
                  "laminate.ply_thickness and the layup");
  const auto mm = warnings_of(with_line(mm_deck, "layup = ", "layup = \"[45/90/-45/0]30s\""));
  ASSERT_EQ(mm.size(), 1U) << joined(mm);
  EXPECT_EQ(
      mm[0].rfind("[laminate] is 46.5 mm thick, more than a fifth of the plate's shorter side (76.2 mm)", 0),
      0U)
      << mm[0];
  // 24 plies (4.65 mm) are well inside the limit.
  EXPECT_TRUE(warnings_of(si_deck).empty());
}

TEST(DeckPlausibility, AValueNoUnitExplainsIsReportedWithItsRange) {
  EXPECT_EQ(plausibility_warning({"plate.a", 1e-9, "m", 0.01, 10.0, "a plate side"}, UnitSystem::si),
            "plate.a = 1e-9 m: implausible (a plate side is expected between 0.01 and 10 m); check its unit");
  EXPECT_FALSE(plausibility_warning({"plate.a", 0.127, "m", 0.01, 10.0, "a plate side"}, UnitSystem::si));
}

TEST(DeckPlausibility, NoShippedExampleGivesAWarning) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(examples)) {
    if (entry.path().extension() != ".toml") continue;
    ++count;
    const Deck d = parse_deck(read_text(entry.path()), entry.path().string());
    EXPECT_TRUE(d.warnings.empty()) << entry.path() << "\n" << joined(d.warnings);
  }
  EXPECT_GE(count, 40);
}

// The command line: warnings on stderr and in summary.json, errors with --strict.

using test::run;
using test::scratch;

TEST(DeckPlausibilityCli, StrictRefusesEachSlipWithItsMessage) {
  const fs::path dir = scratch("plausibility-strict");
  const std::vector<Slip> cases = slips();
  for (const std::size_t i : {1UL, 11UL, 18UL, 23UL, 29UL, 35UL}) { // E2, rho, a, mass, velocity, dt
    const Slip& s = cases.at(i);
    const fs::path deck = dir / ("slip" + std::to_string(i) + ".toml");
    std::ofstream(deck) << s.deck;
    const auto r = run("laminate --strict " + deck.string());
    EXPECT_EQ(r.status, 2) << s.name << "\n" << r.out;
    EXPECT_NE(r.out.find(deck.string() + ": error: " + s.expected), std::string::npos) << s.name << "\n"
                                                                                       << r.out;
    EXPECT_NE(r.out.find(deck.string() + ": error: 1 implausible value refused by --strict"),
              std::string::npos)
        << r.out;
    const auto lenient = run("laminate " + deck.string());
    EXPECT_EQ(lenient.status, 0) << s.name << "\n" << lenient.out;
    EXPECT_NE(lenient.out.find(deck.string() + ": warning: " + s.expected), std::string::npos) << lenient.out;
  }
}

TEST(DeckPlausibilityCli, StrictRefusesBeforeAnyAnalysisRuns) {
  const fs::path dir = scratch("plausibility-strict-impact");
  const fs::path deck = dir / "deck.toml";
  std::ofstream(deck) << with_line(si_deck, "a = ", "a = 127");
  const auto r = run("impact --strict " + deck.string() + " -o " + (dir / "out").string());
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_FALSE(fs::exists(dir / "out" / "summary.json"));
  const auto m = run("modal --strict " + deck.string() + " -o " + (dir / "modal").string());
  EXPECT_EQ(m.status, 2) << m.out;
}

TEST(DeckPlausibilityCli, WarningsAreListedInSummaryJson) {
  const fs::path dir = scratch("plausibility-summary");
  // Annex 2's T300/976 with its density written in g/cm^3.
  const fs::path deck = test::write(
      dir, with_line(test::small_deck("modal", "[modal]\ncount = 2\n"), "rho = ", "rho = 1.3892"));
  const auto r = run("modal " + deck.string() + " -o " + (dir / "out").string());
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = test::read_json(dir / "out" / "summary.json");
  ASSERT_TRUE(j.contains("warnings"));
  ASSERT_EQ(j["warnings"].size(), 1U);
  EXPECT_EQ(
      j["warnings"][0].get<std::string>().rfind("materials.T300_976.rho = 1.3892: this looks like g/cm^3", 0),
      0U)
      << j["warnings"].dump();
}

TEST(DeckPlausibilityCli, ImpactSummaryListsDeckWarningsBeforeTheGuards) {
  const fs::path dir = scratch("plausibility-impact");
  const fs::path deck = dir / "deck.toml";
  std::ofstream(deck) << with_line(si_deck, "load = ", "load = \"point\"\nalpha_cr = 0.17");
  const auto r = run("impact " + deck.string() + " -o " + (dir / "out").string());
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = test::read_json(dir / "out" / "summary.json");
  ASSERT_GE(j["warnings"].size(), 1U);
  EXPECT_EQ(j["warnings"][0].get<std::string>().rfind("contact.alpha_cr = 0.17: this looks like mm", 0), 0U)
      << j["warnings"].dump();
}

} // namespace
} // namespace plyimpact::deck_plausibility_tests
