// Newton–Newmark written once (issue 49): the von Kármán plate whose plies crack is a composition of the
// von Kármán kinematics and the layered damaging section, driven by the one Newton–Newmark step.
//   - Plies that cannot crack leave the von Kármán plate: the same Newton settings give the same run.
//   - Where the deflection is a small fraction of the thickness (w/h < 0.05) the membrane terms are of
//     order (w/h)² and the composition is the linear plate whose plies crack.
//   - On the damage example made non-linear (w/h ≈ 0.23) the energy balance closes with the dissipation.
#include "support/impact_decks.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <limits>
#include <string>

namespace plyimpact::newton_newmark_step_tests {
namespace {

const auto with = test::with_key;

std::string damage_example() {
  return test::example_text("damage-progressive.toml");
}

/// The deck text with the von Kármán plate (top-level `nonlinear = true`).
std::string non_linear(const std::string& text) {
  return with(text, "analysis", "\"impact\"\nnonlinear = true");
}

ImpactResult run(const ImpactCaseDescription& d) {
  return ImpactCase(d).run();
}

TEST(NewtonNewmarkStep, VonKarmanPliesThatCannotCrackAreTheVonKarmanPlate) {
  // Strengths × 1000: no element reaches the screen, the composed force is f_vK(u) and its matrix K_T(u).
  // The von Kármán run is given the damage's Newton settings (tolerances, contraction rule, no refresh
  // after a count of solves), so that the two runs take the same iterations.
  const std::string strong = non_linear(test::unbreakable_t300_976(damage_example()));
  const ImpactCaseDescription damaged = impact_case_description(parse_deck(strong, "d.toml"));
  ImpactCaseDescription elastic =
      impact_case_description(parse_deck(with(strong, "model", "\"onset\""), "e.toml"));
  ASSERT_TRUE(damaged.progressive_damage && damaged.nonlinear);
  ASSERT_FALSE(elastic.progressive_damage);
  elastic.newton = newton_newmark_defaults(model_kind(damaged), case_integrator(damaged));
  const ImpactResult d = run(damaged), e = run(elastic);
  ASSERT_TRUE(d.complete && e.complete);
  ASSERT_TRUE(d.progressive.has_value());
  EXPECT_EQ(d.progressive->dissipated.sum(), 0.0);
  EXPECT_EQ(d.progressive->active_elements, 0);
  std::printf("[ measured ] peak force %.12g N (plies that cannot crack), %.12g N (von Kármán)\n",
              d.peak_force, e.peak_force);
  EXPECT_NEAR(d.peak_force, e.peak_force, 1e-8 * e.peak_force);
  EXPECT_NEAR(d.peak_contact_deflection, e.peak_contact_deflection, 1e-8 * e.peak_contact_deflection);
  ASSERT_EQ(d.history.size(), e.history.size());
  for (std::size_t i = 0; i < d.history.size(); ++i) {
    EXPECT_NEAR(d.history[i].force, e.history[i].force, 1e-8 * e.peak_force) << i;
    EXPECT_NEAR(d.history[i].plate_strain, e.history[i].plate_strain, 1e-8 * 0.06) << i;
  }
}

/// The damage example at 0.3 m/s with matrix strengths low enough to crack there (Yt 5 MPa, S12 60 MPa):
/// a peak deflection of 0.034 mm on the 1 mm plate, 1.6 % of the impact energy dissipated by the plies.
std::string gentle_impact() {
  return with(with(with(damage_example(), "velocity", "0.3"), "Yt", "5e6"), "S12", "60e6");
}

TEST(NewtonNewmarkStep, VonKarmanPliesThatCrackAtSmallDeflectionAreTheLinearPlatesPlies) {
  const ImpactResult linear = test::run_deck(gentle_impact());
  const ImpactResult large = test::run_deck(non_linear(gentle_impact()));
  ASSERT_TRUE(linear.complete && large.complete);
  ASSERT_TRUE(linear.progressive && large.progressive);
  const double h = 1e-3;
  const double d_lin = linear.progressive->dissipated.sum(), d_vk = large.progressive->dissipated.sum();
  std::printf("[ measured ] w/h %.4f; peak force %.6g N linear, %.6g N von Kármán; dissipation %.6g J, "
              "%.6g J\n",
              large.peak_contact_deflection / h, linear.peak_force, large.peak_force, d_lin, d_vk);
  EXPECT_LT(large.peak_contact_deflection / h, 0.05);
  EXPECT_GT(d_lin, 0.01 * 0.5 * 0.03 * 0.3 * 0.3); // the plies do crack: a real share of the energy
  EXPECT_NEAR(large.peak_force, linear.peak_force, 0.005 * linear.peak_force);
  EXPECT_NEAR(d_vk, d_lin, 0.005 * d_lin);
  // …and not bit for bit: the membrane terms are in.
  EXPECT_NE(large.peak_force, linear.peak_force);
}

TEST(NewtonNewmarkStep, VonKarmanPliesThatCrackCloseTheEnergyBalance) {
  // examples/damage-progressive.toml made non-linear: ½ m v0² = impactor + plate kinetic + stored +
  // damage dissipation + contact work within 1 % over the event; the plate is stiffer than the linear
  // one (membrane tension at w/h ≈ 0.23), so the peak force is higher.
  const ImpactResult large = test::run_deck(non_linear(damage_example()));
  const ImpactResult linear = test::run_deck(damage_example());
  ASSERT_TRUE(large.complete);
  ASSERT_TRUE(large.progressive.has_value());
  const double e0 = 0.5 * 0.03 * 2.0 * 2.0;
  const double damage = large.progressive->dissipated.sum();
  std::printf("[ measured ] energy balance error %.3g %%, dissipation %.5g J (linear %.5g J), peak force "
              "%.6g N (linear %.6g N)\n",
              100.0 * large.energy_balance_error, damage, linear.progressive->dissipated.sum(),
              large.peak_force, linear.peak_force);
  EXPECT_LT(large.energy_balance_error, 0.01);
  EXPECT_GT(damage, 0.01 * e0);
  EXPECT_GT(large.peak_force, linear.peak_force);
  const ImpactSample& last = large.history.back();
  EXPECT_NEAR(*large.absorbed_energy,
              large.contact_dissipation + damage + last.plate_kinetic + last.plate_strain, 0.01 * e0);
}

TEST(NewtonNewmarkStep, VonKarmanPliesThatCrackRunExplicitlyToo) {
  // The same composition under central differences: within 1 % of the implicit run's peak force on the
  // damage example made non-linear, at the explicit example's stable step.
  const std::string deck = non_linear(damage_example());
  const ImpactResult implicit_run = test::run_deck(deck);
  const ImpactResult explicit_run = test::run_deck(
      with(with(deck, "dt", "\"auto\""), "model", "\"progressive\"\nintegration = \"explicit\""));
  ASSERT_TRUE(explicit_run.complete);
  std::printf("[ measured ] peak force %.6g N implicit, %.6g N explicit; balance %.3g %%\n",
              implicit_run.peak_force, explicit_run.peak_force, 100.0 * explicit_run.energy_balance_error);
  EXPECT_NEAR(explicit_run.peak_force, implicit_run.peak_force, 0.01 * implicit_run.peak_force);
  EXPECT_LT(explicit_run.energy_balance_error, 0.01);
}

} // namespace
} // namespace plyimpact::newton_newmark_step_tests

namespace plyimpact::newton_newmark_step_tests {
namespace {

/// examples/impact-delamination-damage.toml to t = 0.1 ms (past the peak force at 91 µs and the lower
/// interface's opening), with both laws' integration `integration` and the time step `dt`.
std::string plies_and_interfaces(const std::string& integration, const std::string& dt) {
  std::string deck =
      with(with(test::example_text("impact-delamination-damage.toml"), "end", "1.0e-4"), "dt", dt);
  for (std::size_t at = deck.find("\nintegration = "); at != std::string::npos;
       at = deck.find("\nintegration = ", at + 1))
    deck = deck.replace(at + 1, deck.find('\n', at + 1) - at - 1, "integration = \"" + integration + "\"");
  return deck;
}

TEST(NewtonNewmarkStep, LaggedPliesAndInterfacesFollowTheExplicitRun) {
  // The stack whose plies crack under Newton–Newmark with both laws of the step before held, in the
  // trapezoidal rule's two-point form (DL7), at 80 ns (the contact time is ~170 µs), against central
  // differences at half the stable step (4.5 ns): peak force within 2 %, total dissipation within 5 %.
  const ImpactResult explicit_run = test::run_deck(plies_and_interfaces("explicit", "\"auto\""));
  const ImpactResult lagged = test::run_deck(plies_and_interfaces("lagged", "8e-8"));
  ASSERT_TRUE(explicit_run.progressive && explicit_run.delamination);
  ASSERT_TRUE(lagged.progressive && lagged.delamination);
  const auto dissipated = [](const ImpactResult& r) {
    return r.progressive->dissipated.sum() + r.delamination->dissipated;
  };
  std::printf("[ measured ] peak force %.6g N lagged, %.6g N explicit; plies %.5g J, %.5g J; interfaces "
              "%.5g J, %.5g J; balance %.3g %%\n",
              lagged.peak_force, explicit_run.peak_force, lagged.progressive->dissipated.sum(),
              explicit_run.progressive->dissipated.sum(), lagged.delamination->dissipated,
              explicit_run.delamination->dissipated, 100.0 * lagged.energy_balance_error);
  EXPECT_NEAR(lagged.peak_force, explicit_run.peak_force, 0.02 * explicit_run.peak_force);
  EXPECT_NEAR(dissipated(lagged), dissipated(explicit_run), 0.05 * dissipated(explicit_run));
  EXPECT_GT(lagged.delamination->dissipated, 0.0);
  EXPECT_LT(lagged.energy_balance_error, 0.01);
}

TEST(NewtonNewmarkStep, IteratedPliesAndInterfacesFollowTheExplicitRunUntilTheInterfacesSoften) {
  // Both laws iterated within the step (implicit: the plies' law at every iterate, an element that reaches
  // a Hashin surface joining before the step is accepted; the interfaces' mixed-mode tangent by LU) at
  // 80 ns against central differences, to 60 µs: the plies crack from 23 µs (matrix tension, 8.1 mm²),
  // the interfaces have not begun to soften. Peak force within 0.1 %, the plies' dissipation within 2 %,
  // the same projected damage area. (Beyond, where the interfaces soften, the iterated interface law stops
  // converging on this mesh, with or without the plies: docs/delamination.md.)
  const auto to_60us = [](const std::string& deck) { return with(deck, "end", "6.0e-5"); };
  const ImpactResult explicit_run = test::run_deck(to_60us(plies_and_interfaces("explicit", "\"auto\"")));
  const ImpactResult implicit = test::run_deck(to_60us(plies_and_interfaces("implicit", "8e-8")));
  ASSERT_TRUE(explicit_run.progressive && implicit.progressive && implicit.delamination);
  std::printf("[ measured ] peak force %.6g N implicit, %.6g N explicit; plies %.5g J, %.5g J; projected "
              "damage %.4g mm2, %.4g mm2; balance %.3g %%\n",
              implicit.peak_force, explicit_run.peak_force, implicit.progressive->dissipated.sum(),
              explicit_run.progressive->dissipated.sum(), implicit.progressive->projected_damage_area * 1e6,
              explicit_run.progressive->projected_damage_area * 1e6, 100.0 * implicit.energy_balance_error);
  EXPECT_GT(explicit_run.progressive->dissipated.sum(), 0.0); // the plies did crack
  EXPECT_NEAR(implicit.peak_force, explicit_run.peak_force, 1e-3 * explicit_run.peak_force);
  EXPECT_NEAR(implicit.progressive->dissipated.sum(), explicit_run.progressive->dissipated.sum(),
              0.02 * explicit_run.progressive->dissipated.sum());
  EXPECT_DOUBLE_EQ(implicit.progressive->projected_damage_area,
                   explicit_run.progressive->projected_damage_area);
  EXPECT_LT(implicit.energy_balance_error, 0.01);
}

} // namespace
} // namespace plyimpact::newton_newmark_step_tests
