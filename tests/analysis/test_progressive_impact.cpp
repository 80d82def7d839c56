// Progressive ply damage in an impact run (issue 18): the energy balance closes with the damage
// dissipation, a plate whose plies cannot crack is the elastic plate, and the plies that crack first
// are the ones plate theory says are most loaded.
#include "plyimpact/analysis/impact_case.hpp"
#include "plyimpact/io/case_from_deck.hpp"
#include "plyimpact/io/deck.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace plyimpact {
namespace {

std::string example_text() {
  std::ifstream in(std::string(PLYIMPACT_SOURCE_DIR) + "/examples/damage-progressive.toml");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

ImpactResult run(const std::string& text) {
  const Deck deck = parse_deck(text, "damage-progressive.toml");
  const ImpactCase impact(impact_case_description(deck));
  return impact.run();
}

/// The line `key = value` replaced (the first occurrence of "key = ").
std::string with(std::string text, const std::string& key, const std::string& value) {
  const std::size_t at = text.find("\n" + key + " = ");
  EXPECT_NE(at, std::string::npos) << key;
  const std::size_t end = text.find('\n', at + 1);
  return text.replace(at + 1, end - at - 1, key + " = " + value);
}

TEST(ProgressiveImpact, EnergyBalanceClosesWithTheDamageDissipation) {
  // ½ m v0² = impactor + plate kinetic + stored strain + damage dissipation + contact work, within 1 %
  // of the impact energy over the whole event (the bar); the damage dissipated is a real share.
  const ImpactResult r = run(example_text());
  ASSERT_TRUE(r.progressive.has_value());
  ASSERT_TRUE(r.complete);
  const double e0 = 0.5 * 0.03 * 2.0 * 2.0;
  const double damage = r.progressive->dissipated.sum();
  std::printf(
      "[ measured ] energy balance error %.3g %% of %.4g J, damage dissipation %.4g J, absorbed %.4g J\n",
      100.0 * r.energy_balance_error, e0, damage, *r.absorbed_energy);
  EXPECT_LT(r.energy_balance_error, 0.01);
  EXPECT_GT(damage, 0.01 * e0);
  // Absorbed = what the impactor lost = contact + damage dissipation + what the plate still holds.
  const ImpactSample& last = r.history.back();
  EXPECT_NEAR(*r.absorbed_energy, r.contact_dissipation + damage + last.plate_kinetic + last.plate_strain,
              0.01 * e0);
  EXPECT_DOUBLE_EQ(last.damage_dissipation, damage);
  EXPECT_GT(r.progressive->projected_damage_area, 0.0);
}

TEST(ProgressiveImpact, TheBottomPlyCracksFirstInMatrixTension) {
  // Bending puts the largest transverse tension in the lowest 0° ply (ply 4 of [0/90]s, z = +h/2): with
  // Yt ≪ Xt the first mode is matrix tension there.
  const ImpactResult r = run(example_text());
  ASSERT_TRUE(r.progressive && r.progressive->first_mode);
  EXPECT_EQ(*r.progressive->first_mode, DamageMode::matrix_tension);
  EXPECT_EQ(r.progressive->first_ply, 4);
  EXPECT_GT(r.progressive->ply_damage_area[3], 0.0);
  EXPECT_EQ(r.progressive->ply_damage_area[0], 0.0); // the top ply is in compression
}

TEST(ProgressiveImpact, UnbreakablePliesGiveTheElasticPlate) {
  // With strengths 1000 times larger nothing initiates: the progressive run is the elastic run (same
  // peak force and time to round-off; the elastic policy leaves the in-plane DOFs out, so not bit for bit).
  std::string strong = example_text();
  for (const auto& [key, value] : {std::pair{"Xt", "1.5e12"},
                                   {"Xc", "1.2e12"},
                                   {"Yt", "55.2e9"},
                                   {"Yc", "294.0e9"},
                                   {"S12", "101.1e9"},
                                   {"S23", "32.94e9"}})
    strong = with(strong, key, value);
  const ImpactResult damaged = run(strong);
  const ImpactResult elastic = run(with(strong, "model", "\"onset\""));
  ASSERT_TRUE(damaged.progressive.has_value());
  EXPECT_FALSE(damaged.progressive->first_mode.has_value());
  EXPECT_EQ(damaged.progressive->dissipated.sum(), 0.0);
  EXPECT_NEAR(damaged.peak_force, elastic.peak_force, 1e-8 * elastic.peak_force);
  EXPECT_EQ(damaged.time_of_peak_force, elastic.time_of_peak_force);
  EXPECT_NEAR(damaged.contact_duration, elastic.contact_duration, 1e-12);
}

TEST(ProgressiveImpact, DamageSoftensThePlate) {
  // Cracked plies carry less: against the elastic plate the peak deflection grows and the impactor
  // rebounds slower (the dissipated energy is not given back).
  const ImpactResult damaged = run(example_text());
  const ImpactResult elastic = run(with(example_text(), "model", "\"onset\""));
  EXPECT_GT(damaged.peak_contact_deflection, elastic.peak_contact_deflection);
  EXPECT_LT(*damaged.rebound_velocity, *elastic.rebound_velocity);
}

} // namespace
} // namespace plyimpact
