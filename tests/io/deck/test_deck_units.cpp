// Deck-wide units (units = "mm-N-MPa-tonne", converted to SI where the deck is read), the impact energy
// as an alternative to the velocity, and "did you mean" for misspelt names (docs/deck.md).
#include "plyimpact/io/deck/deck.hpp"
#include "support/cli.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

namespace plyimpact::deck_units_tests {
namespace {

namespace fs = std::filesystem;

using test::read_text;
using test::with_line;

const fs::path examples = fs::path(PLYIMPACT_SOURCE_DIR) / "examples";
const std::string si_deck = read_text(examples / "thesis-3.6-v268.toml");
const std::string mm_deck = read_text(examples / "thesis-3.6-v268-mm.toml");

std::string error_of(const std::string& text) {
  try {
    (void)parse_deck(text, "deck.toml");
  } catch (const DeckError& e) {
    return e.what();
  }
  return "no error";
}

TEST(DeckUnits, TheMmDeckReadsAsTheSameSiNumbers) {
  // Every conversion of this deck is exact: the mm deck's numbers divided by 1e3 (or multiplied by
  // 1e6, 1e3, 1e12) round to the same doubles as the SI deck's literals. Multiplying by 1e-3 would
  // not: 0.19375 * 1e-3 = 0.00019375000000000002, one ulp above 0.19375e-3.
  const Deck si = parse_deck(si_deck, "si.toml");
  const Deck mm = parse_deck(mm_deck, "mm.toml");
  EXPECT_EQ(si.units, UnitSystem::si);
  EXPECT_EQ(mm.units, UnitSystem::mm_n_mpa_tonne);
  const Material& a = si.materials.at(0);
  const Material& b = mm.materials.at(0);
  EXPECT_EQ(a.E1, b.E1);
  EXPECT_EQ(a.E2, b.E2);
  EXPECT_EQ(a.G12, b.G12);
  EXPECT_EQ(a.G23, b.G23);
  EXPECT_EQ(a.rho, b.rho);
  EXPECT_EQ(si.laminate_spec->ply_thickness, mm.laminate_spec->ply_thickness);
  EXPECT_EQ(si.laminate->thickness(), mm.laminate->thickness());
  EXPECT_EQ(si.plate->a, mm.plate->a);
  EXPECT_EQ(si.plate->b, mm.plate->b);
  EXPECT_EQ(si.impactor->mass, mm.impactor->mass);
  EXPECT_EQ(si.impactor->radius, mm.impactor->radius);
  EXPECT_EQ(si.impactor->E, mm.impactor->E);
  EXPECT_EQ(si.impactor->velocity, mm.impactor->velocity);
  EXPECT_EQ(si.impactor->x, mm.impactor->x);
  // 18973.665961010276 N/mm^1.5 × 1e3·√1e3: the one factor that is not a power of ten.
  EXPECT_NEAR(*mm.contact.k, 0.6e9, 0.6e9 * 1e-15);
  EXPECT_EQ(si.time.dt, mm.time.dt);
  EXPECT_EQ(si.contact.alpha_cr, mm.contact.alpha_cr); // a default is SI whatever the deck's units
  EXPECT_EQ(0.19375 / 1e3, 0.19375e-3);
  EXPECT_NE(0.19375 * 1e-3, 0.19375e-3);
}

TEST(DeckUnits, EachQuantityConvertsWithItsFactor) {
  const Deck d =
      parse_deck(with_line(with_line(with_line(mm_deck, "k = ", "k = 1.0"), "end = ", "end = 0.004"),
                           "load = ", "load = \"point\"\nalpha_cr = 0.17"),
                 "mm.toml");
  EXPECT_DOUBLE_EQ(*d.contact.k, 1e3 * std::sqrt(1e3)); // 1 N/mm^1.5 = 31622.8 N/m^1.5
  EXPECT_DOUBLE_EQ(d.contact.alpha_cr, 0.17e-3);        // mm
  EXPECT_EQ(*d.time.end, 0.004);                        // s in both systems
  const Deck b = parse_deck(R"(units = "mm-N-MPa-tonne"
[buckling]
Nx = -100.0
)",
                            "b.toml");
  EXPECT_EQ(b.buckling->Nx, -1e5); // N/mm -> N/m
  const Deck e = parse_deck(with_line(mm_deck, "velocity = ", "energy = 22050.0"), "e.toml");
  EXPECT_EQ(*e.impactor_input.energy, 22.05); // mJ -> J
  EXPECT_DOUBLE_EQ(e.impactor->velocity, std::sqrt(2.0 * 22.05 / 6.14));
}

TEST(DeckUnits, RegionBoundsAndProbesAreConverted) {
  const std::string deck = mm_deck + R"(
[laminates.pad]
material = "thesis_3_6"
layup = "[0/90]s"
ply_thickness = 0.2
[[region]]
laminate = "pad"
x = [10.0, 50.0]
y = [5.0, 20.0]
[[output.probe]]
x = 63.5
y = 38.1
ply = 1
)";
  const Deck d = parse_deck(deck, "mm.toml");
  ASSERT_EQ(d.regions.size(), 1U);
  EXPECT_DOUBLE_EQ(d.regions[0].x_min, 0.010);
  EXPECT_DOUBLE_EQ(d.regions[0].x_max, 0.050);
  EXPECT_DOUBLE_EQ(d.regions[0].y_max, 0.020);
  EXPECT_DOUBLE_EQ(d.laminates[0].spec.ply_thickness, 0.2e-3);
  EXPECT_DOUBLE_EQ(d.probes.at(0).x, 0.0635);
}

TEST(DeckUnits, MessagesNameTheDecksUnits) {
  EXPECT_EQ(error_of(with_line(mm_deck, "E2 = ", "E2 = -7500.0")),
            "deck.toml:13:6: error: materials.thesis_3_6.E2 must be positive (in MPa), got -7500");
  EXPECT_NE(error_of(with_line(mm_deck, "velocity = ", "velocity = \"fast\""))
                .find("impactor.velocity must be a number in mm/s"),
            std::string::npos);
}

TEST(DeckUnits, AnUnknownUnitSystemIsRefusedWithTheAcceptedOnes) {
  EXPECT_EQ(
      error_of("units = \"mm-kg-s\"\n"),
      "deck.toml:1:9: error: units = \"mm-kg-s\" is not a unit system: expected \"SI\" (m, N, Pa, kg, s) "
      "or \"mm-N-MPa-tonne\" (mm, N, MPa, tonne, s)");
  EXPECT_EQ(
      error_of("units = \"mm-n-mpa-tonne\"\n"),
      "deck.toml:1:9: error: units = \"mm-n-mpa-tonne\" is not a unit system (did you mean "
      "\"mm-N-MPa-tonne\"?): expected \"SI\" (m, N, Pa, kg, s) or \"mm-N-MPa-tonne\" (mm, N, MPa, tonne, s)");
  EXPECT_EQ(parse_deck("units = \"SI\"\n", "deck.toml").units, UnitSystem::si);
}

TEST(DeckEnergy, TheVelocityFollowsFromTheEnergyAndTheMass) {
  const Deck d = parse_deck(with_line(si_deck, "velocity = ", "energy = 22.05"), "deck.toml");
  // √(2 · 22.05 / 6.14) = 2.6800019446733185: the thesis's 2.68 m/s rounds ½ m v² = 22.049968 J.
  EXPECT_EQ(d.impactor->velocity, std::sqrt(2.0 * 22.05 / 6.14));
  EXPECT_NEAR(d.impactor->velocity, 2.6800019446733185, 1e-15);
  EXPECT_EQ(*d.impactor_input.energy, 22.05);
  EXPECT_FALSE(parse_deck(si_deck, "deck.toml").impactor_input.energy);
}

TEST(DeckEnergy, ExactlyOneOfVelocityAndEnergy) {
  EXPECT_EQ(error_of(with_line(si_deck, "velocity = ", "velocity = 2.68\nenergy = 22.05")),
            "deck.toml:46:10: error: give impactor.velocity (m/s) or impactor.energy (J), not both");
  EXPECT_EQ(
      error_of(with_line(si_deck, "velocity = ", "")),
      "deck.toml:40:1: error: [impactor] needs velocity (m/s, towards the plate) or energy (J, the impact "
      "energy: velocity = sqrt(2 energy / mass))");
  EXPECT_EQ(error_of(with_line(si_deck, "velocity = ", "energy = -1.0")),
            "deck.toml:45:10: error: impactor.energy must be positive (in J), got -1");
}

TEST(DeckDidYouMean, MisspeltCriterionNamesAndChoices) {
  const std::string damage = with_line(si_deck, "[time]", "[damage]\ncriteria = [\"tsai_wu\"]\n[time]");
  EXPECT_NE(
      error_of(damage).find("damage.criteria: unknown criterion \"tsai_wu\" (did you mean \"tsai-wu\"?)"),
      std::string::npos)
      << error_of(damage);
  const std::string threshold = with_line(si_deck, "[time]", "[threshold]\ncriterion = \"hashn\"\n[time]");
  EXPECT_NE(
      error_of(threshold).find("threshold.criterion: unknown criterion \"hashn\" (did you mean \"hashin\"?)"),
      std::string::npos)
      << error_of(threshold);
  EXPECT_NE(error_of(with_line(si_deck, "unloading = ", "unloading = \"tan_sun\""))
                .find("contact.unloading must be one of tan-sun | elastic, got \"tan_sun\" (did you mean "
                      "\"tan-sun\"?)"),
            std::string::npos);
  EXPECT_NE(error_of(with_line(si_deck, "[time]", "[time]\nd_t = 1e-6"))
                .find("unknown key 'd_t' in [time] (did you mean 'dt'?)"),
            std::string::npos);
}

// The command line: the same results from the SI deck, its mm twin and the energy deck.

using test::read_json;
using test::run;
using test::scratch;

/// Relative differences above `tolerance` between the numbers of two summaries (program, version,
/// deck and wall time left out), as "path: a vs b" lines.
void compare_numbers(const nlohmann::json& a, const nlohmann::json& b, const std::string& path,
                     double tolerance, std::string& diffs) {
  if (a.is_object()) {
    for (auto it = a.begin(); it != a.end(); ++it) {
      const std::string& k = it.key();
      if (k == "wall_time" || k == "deck" || k == "version" || k == "program") continue;
      if (!b.contains(k)) {
        diffs += path + "/" + k + ": missing\n";
        continue;
      }
      compare_numbers(it.value(), b.at(k), path + "/" + k, tolerance, diffs);
    }
  } else if (a.is_array()) {
    if (a.size() != b.size()) diffs += path + ": sizes differ\n";
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
      compare_numbers(a[i], b[i], path + "/" + std::to_string(i), tolerance, diffs);
  } else if (a.is_number() && b.is_number()) {
    const double x = a.get<double>(), y = b.get<double>();
    if (std::abs(x - y) > tolerance * std::max(std::abs(x), std::abs(y)))
      diffs += path + ": " + a.dump() + " vs " + b.dump() + "\n";
  } else if (a != b) {
    diffs += path + ": " + a.dump() + " vs " + b.dump() + "\n";
  }
}

TEST(DeckUnitsCli, TheMmDeckGivesTheSiDecksSummary) {
  const fs::path dir = scratch("units-mm");
  ASSERT_EQ(
      run("impact " + (examples / "thesis-3.6-v268.toml").string() + " -o " + (dir / "si").string()).status,
      0);
  ASSERT_EQ(run("impact " + (examples / "thesis-3.6-v268-mm.toml").string() + " -o " + (dir / "mm").string())
                .status,
            0);
  const auto si = read_json(dir / "si" / "summary.json");
  const auto mm = read_json(dir / "mm" / "summary.json");
  std::string diffs;
  compare_numbers(si, mm, "", 1e-12, diffs);
  compare_numbers(mm, si, "", 1e-12, diffs);
  EXPECT_EQ(diffs, "");
  EXPECT_EQ(mm["peak_force"].get<double>(), si["peak_force"].get<double>()); // exact: see TheMmDeckReads...
}

TEST(DeckEnergyCli, TheEnergyDeckGivesThe268Result) {
  const fs::path dir = scratch("energy");
  const fs::path energy_deck = dir / "energy.toml";
  const fs::path velocity_deck = dir / "velocity.toml";
  std::ofstream(energy_deck) << with_line(si_deck, "velocity = ", "energy = 22.05");
  std::ofstream(velocity_deck) << with_line(si_deck, "velocity = ", "velocity = 2.6800019446733185");
  for (const auto& [deck, out] : {std::pair{energy_deck, "energy"}, {velocity_deck, "velocity"}})
    ASSERT_EQ(run("impact " + deck.string() + " -o " + (dir / out).string()).status, 0) << deck;
  ASSERT_EQ(
      run("impact " + (examples / "thesis-3.6-v268.toml").string() + " -o " + (dir / "v268").string()).status,
      0);
  const auto e = read_json(dir / "energy" / "summary.json");
  const auto v = read_json(dir / "velocity" / "summary.json");
  const auto ref = read_json(dir / "v268" / "summary.json");
  // The energy deck is the velocity deck at √(2E/m): the same run.
  std::string diffs;
  compare_numbers(e, v, "", 0.0, diffs);
  EXPECT_EQ(diffs, "");
  EXPECT_EQ(e["impact_velocity"].get<double>(), 2.6800019446733185);
  EXPECT_NEAR(e["initial_energy"].get<double>(), 22.05, 1e-13);
  // Against 2.68 m/s: v is higher by dv/v = 7.256e-7. The peak force of a mass on a linear spring
  // grows like v, on a rigid Hertz contact like v^1.2; the plate lies between: 1 <= (dF/F)/(dv/v) <= 1.2
  // (measured: 1.044, F = 12661.711 N against 12661.702 N).
  const double dv = 2.6800019446733185 / 2.68 - 1.0;
  const double dF = e["peak_force"].get<double>() / ref["peak_force"].get<double>() - 1.0;
  EXPECT_NEAR(dv, 7.256e-7, 1e-10);
  EXPECT_GE(dF, 1.0 * dv);
  EXPECT_LE(dF, 1.2 * dv);
  EXPECT_EQ(e["steps"], ref["steps"]);
  EXPECT_EQ(e["contact_duration"], ref["contact_duration"]);
}

} // namespace
} // namespace plyimpact::deck_units_tests
