// The stacked plate with explicit central differences (central differences on fem/stacked_model.cpp):
// the shipped delamination example (a [0_2/90_2]s AS4/PEEK plate, two interfaces, 30 g at 3 m/s) on 5 x 5
// elements with the lumped mass. The step is the stack's stable step; the run follows the lagged implicit
// step while the interfaces soften and crack, keeps the energy to round-off, and runs past the impactor's
// departure, where the Newton policy's steps cost ~15 times more (docs/delamination.md).
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/analysis/integrators/step_policy.hpp"
#include "plyimpact/fem/stacked_plate.hpp"
#include "support/impact_decks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace plyimpact::explicit_delamination_step_tests {
namespace {

/// The example on 5 x 5 elements with the lumped mass, its interfaces integrated as `integration`, to `end`.
std::string example_5x5(const std::string& integration, const std::string& end) {
  std::string text = test::example_text("impact-delamination.toml");
  text = test::with_key(text, "nx", "5");
  text = test::with_key(text, "ny", "5\nmass = \"lumped\"");
  text = test::with_key(text, "end", end);
  return test::with_key(text, "shear_strength", "98.2e6\nintegration = \"" + integration + "\"");
}

ImpactCaseDescription description(const std::string& text) {
  return impact_case_description(parse_deck(text, "test.toml"));
}

// The shear penalty between two sub-laminates of masses per area m_u, m_l (ρ h) moves each face by its
// translation and its rotation times half its thickness; with the rotary inertia ρ h³/12 of a Mindlin
// plate, h²/4 over it is 3/(ρ h), and the mode ω² = K (1/m_u + 3/m_u + 1/m_l + 3/m_l) = 4 K (1/m_u + 1/m_l)
// is a Rayleigh quotient of the stack (lumped mass and nodal interface points carry the same nodal
// weights): ω_max is at least that, and the plates' own stiffness adds to it.
TEST(ExplicitDelamination, TheStepIsBelowTheShearPenaltysStableStepAndAutoTakesIt) {
  const ImpactCaseDescription d = description(example_5x5("explicit", "0.3e-3"));
  const DiscretePlate model = impact_plate_model(d);
  const double dt = stable_time_step(*explicit_highest_frequency(d, model));
  const double K = d.delamination->stack.interface.penalty_stiffness;
  const double m_outer = 1590.0 * 2 * 0.13e-3, m_middle = 1590.0 * 4 * 0.13e-3; // [0_2], [90_4]
  const double omega = std::sqrt(4.0 * K * (1.0 / m_outer + 1.0 / m_middle));
  std::printf("[ measured ] stable step %.4g s, shear-penalty bound 0.9 x 2/omega = %.4g s (ratio %.3f)\n",
              dt, 0.9 * 2.0 / omega, dt / (0.9 * 2.0 / omega));
  EXPECT_LE(dt, 0.9 * 2.0 / omega);
  EXPECT_GT(dt, 0.5 * 0.9 * 2.0 / omega); // the plates do not dominate the interfaces' penalty
  EXPECT_DOUBLE_EQ(resolved_settings(d, model).dt, dt);
  // The stack is [0_2] | [90_4] | [0_2]: the middle sub-laminate's rotation shears both of its interfaces
  // at once, each through (h/2) θ on the rotary inertia ρh³/12, an effective mass ρh/3 = m_m/3 per face,
  // against the outer faces' m_o/4 (translation and rotation together, as above). The mode where the two
  // outer faces move against the middle's rotation is a two-body mode of the middle's m_m/3 against
  // 2 m_o/4 on 2K: ω² = 2K (3/m_m + 2/m_o) = K (6/m_m + 4/m_o), 7/6 of DL9's pair for m_m = 2 m_o. Its
  // mass-weighted amplitudes (momentum: (m_m/3) c = 2 (m_o/4) s) are √(m_m/3) · 3/4 = 0.61 √m_o on the
  // middle's rotation against 0.43 √m_o on an outer rotation: the highest mode is largest on a rotation of
  // the middle sub-laminate (2 of 3, 1-based), and the step lies below this mode's, close to it.
  const double omega_stack = std::sqrt(K * (6.0 / m_middle + 4.0 / m_outer));
  std::printf("[ measured ] stable step %.4g s against the stack's interface mode 0.9 x 2/omega = %.4g s\n",
              dt, 0.9 * 2.0 / omega_stack);
  EXPECT_LE(dt, 0.9 * 2.0 / omega_stack);
  EXPECT_GT(dt, 0.95 * 0.9 * 2.0 / omega_stack);
  const ImpactCase stacked(d);
  ASSERT_TRUE(stacked.settings().stable_step.has_value());
  const StableStepSource& source = *stacked.settings().stable_step;
  std::printf("[ measured ] highest mode largest at %s\n", stable_step_place_text(source, true).c_str());
  EXPECT_DOUBLE_EQ(source.omega_max, *stacked.explicit_omega_max());
  EXPECT_EQ(source.place.sublaminate, 1); // 0-based: the middle [90_4]
  EXPECT_GE(source.place.dof, 3);         // θx or θy

  ImpactCaseDescription too_long = d;
  too_long.time.dt = 1.1 * dt;
  try {
    const ImpactCase c(too_long);
    ADD_FAILURE() << "a step above the stable step was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("[delamination] integration = \"explicit\": time.dt"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("set time.dt <="), std::string::npos) << e.what();
  }
  ImpactCaseDescription consistent = d;
  consistent.mesh.mass = MassMatrix::consistent;
  try {
    const ImpactCase c(consistent);
    ADD_FAILURE() << "the consistent mass was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("need a diagonal mass: set [mesh] mass = \"lumped\""),
              std::string::npos)
        << e.what(); // the capability table's restriction (analysis/impact/capabilities.cpp)
  }
}

// To 0.3 ms the interfaces soften from ~120 µs and crack over 3.1 mm² (docs/delamination.md): the lagged
// implicit step at 0.16 µs and the explicit step at its stable step (~10 ns) solve the same equations, the
// lagged one with the first-order error of its held damage (its balance error, 0.25 %, measures it). The
// explicit one keeps the energy to the round-off of central differences (the law's dissipation is exact
// for each step's separation).
TEST(ExplicitDelamination, FollowsTheLaggedStepAndKeepsTheEnergy) {
  const ImpactResult lagged = test::run_deck(example_5x5("lagged", "0.3e-3"));
  const ImpactResult expl = test::run_deck(example_5x5("explicit", "0.3e-3"));
  ASSERT_TRUE(lagged.delamination && expl.delamination);
  std::printf(
      "[ measured ] explicit / lagged: peak %.3f / %.3f N, dissipated %.5f / %.5f J, projected %.3f / "
      "%.3f mm2, balance error %.2e / %.2e, %ld / %ld steps\n",
      expl.peak_force, lagged.peak_force, expl.delamination->dissipated, lagged.delamination->dissipated,
      expl.delamination->projected_area * 1e6, lagged.delamination->projected_area * 1e6,
      expl.energy_balance_error, lagged.energy_balance_error, expl.steps, lagged.steps);
  EXPECT_EQ(expl.newton->iterations, 0);
  EXPECT_EQ(expl.newton->factorizations, 0);
  EXPECT_LT(expl.energy_balance_error, 1e-6);
  EXPECT_GT(expl.delamination->dissipated, 0.01);
  // Within the lagged step's own balance error, as a share of the impact energy (0.135 J).
  const double e0 = 0.5 * 0.03 * 3.0 * 3.0;
  EXPECT_NEAR(expl.delamination->dissipated, lagged.delamination->dissipated,
              lagged.energy_balance_error * e0);
  EXPECT_NEAR(expl.peak_force / lagged.peak_force, 1.0, 5e-3);
  EXPECT_NEAR(expl.delamination->projected_area, lagged.delamination->projected_area, 1e-9);
}

// With strengths and toughnesses far above what the event reaches (x 100 and x 10^4) no interface point
// leaves its penalty, and the explicit stack and the lagged implicit one (the trapezoidal rule at 0.16 µs)
// integrate the same linear equations: the same peak force and deflection to the 0.5 % of the stacked
// model's consistency check. (Both are 1.2 % below the single laminate's peak on this thick cross-ply plate,
// a/h = 12.7, where the sub-laminates' shear corrections (DL0) differ from the whole section's; the §3.6
// plate's stack is within 0.5 % of its single laminate, test_delamination_impact.cpp.)
TEST(ExplicitDelamination, WithInterfacesThatHoldItIntegratesTheLaggedStacksEquations) {
  std::string text = example_5x5("explicit", "0.25e-3");
  for (const auto& [key, value] : {std::pair{"G_Ic", "969.0e4"},
                                   {"G_IIc", "1719.0e4"},
                                   {"normal_strength", "73.7e8"},
                                   {"shear_strength", "98.2e8"}})
    text = test::with_key(text, key, value);
  const ImpactResult expl = test::run_deck(text);
  const ImpactResult lagged = test::run_deck(test::with_key(text, "integration", "\"lagged\""));
  ASSERT_TRUE(expl.delamination && lagged.delamination);
  std::printf("[ measured ] peak %.3f N (lagged %.3f, %+.3f %%), deflection %.5f mm (lagged %.5f), balance "
              "error %.2e\n",
              expl.peak_force, lagged.peak_force, 100.0 * (expl.peak_force / lagged.peak_force - 1.0),
              expl.peak_contact_deflection * 1e3, lagged.peak_contact_deflection * 1e3,
              expl.energy_balance_error);
  EXPECT_EQ(expl.delamination->dissipated, 0.0);
  EXPECT_NEAR(expl.peak_force / lagged.peak_force, 1.0, 5e-3);
  EXPECT_NEAR(expl.peak_contact_deflection / lagged.peak_contact_deflection, 1.0, 5e-3);
  EXPECT_LT(expl.energy_balance_error, 1e-6);
}

// The whole event (the end-of-event rule: ~810 µs): the impactor leaves at ~405 µs and the delaminated
// faces then open and close on the penalty, at no extra cost per step. What the impactor lost is what the
// contact law and the interfaces dissipated plus what the plate still holds.
TEST(ExplicitDelamination, RunsTheWholeEventAndTheImpactorsLossIsWhatWasDissipated) {
  const ImpactResult r = test::run_deck(example_5x5("explicit", "\"auto\""));
  ASSERT_TRUE(r.complete);
  ASSERT_TRUE(r.delamination && r.absorbed_energy && r.rebound_velocity);
  const double dissipated = r.contact_dissipation + r.delamination->dissipated;
  std::printf("[ measured ] contact %.1f us, run to %.1f us, %ld steps; absorbed %.6f J = contact %.6f + "
              "interfaces %.6f + plate %.2e J; projected %.3f mm2, balance error %.2e\n",
              r.contact_duration * 1e6, r.end_time * 1e6, r.steps, *r.absorbed_energy, r.contact_dissipation,
              r.delamination->dissipated, *r.absorbed_energy - dissipated,
              r.delamination->projected_area * 1e6, r.energy_balance_error);
  EXPECT_GT(r.end_time, r.contact_duration + 100e-6);
  EXPECT_GT(r.delamination->dissipated, 0.01);
  EXPECT_LT(r.energy_balance_error, 1e-5);
  EXPECT_GE(*r.absorbed_energy, dissipated - 1e-5 * 0.135);
}

} // namespace
} // namespace plyimpact::explicit_delamination_step_tests
