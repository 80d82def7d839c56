// Central differences written once for any plate model (analysis/integrators/central_difference_step.cpp over
// fem/mechanical_model.hpp; issue 49): the elastic and the von Kármán plate with [time] integration =
// "explicit" against the implicit Newmark runs of the same semi-discrete equations (two second-order
// schemes: where both are converged in Δt, their peak forces agree), the energy balance that central
// differences close, and the automatic step.
#include "plyimpact/analysis/integrators/step_policy.hpp"
#include "support/impact_decks.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace plyimpact::central_difference_step_tests {
namespace {

const auto with = test::with_key;

/// examples/thesis-3.6-v268(-nonlinear).toml at 2.68 m/s with the given [time] keys.
std::string thesis_3_6(bool nonlinear, const std::string& dt, const std::string& integration) {
  const std::string text =
      test::example_text(nonlinear ? "thesis-3.6-v268-nonlinear.toml" : "thesis-3.6-v268.toml");
  return with(with(text, "dt", dt), "end", "\"auto\"\nintegration = \"" + integration + "\"");
}

/// Central differences at the automatic stable step (0.40 µs) against implicit Newmark at `dt` and at 2 dt:
/// the implicit peak force moves by less than 1e-3 between the two (converged in Δt: measured 1.2e-4 for
/// the elastic plate from 0.5 to 0.25 µs, 1.9e-4 for the von Kármán plate from 1 to 0.5 µs), and the
/// explicit one lies within 0.2 % of the finer (measured 1.2e-4 and 1.3e-4).
void expect_agreement(bool nonlinear, double dt) {
  const ImpactResult implicit_coarse =
      test::run_deck(thesis_3_6(nonlinear, fmt::format("{:g}", 2.0 * dt), "implicit"));
  const ImpactResult implicit_run =
      test::run_deck(thesis_3_6(nonlinear, fmt::format("{:g}", dt), "implicit"));
  const ImpactResult explicit_run = test::run_deck(thesis_3_6(nonlinear, "\"auto\"", "explicit"));
  std::printf("[ measured ] %s plate: peak force %.8g N implicit at %g us, %.8g N at %g us, %.8g N "
              "explicit (%ld steps); balance error %.3g (explicit); contact %.6g us, %.6g us\n",
              nonlinear ? "von Karman" : "elastic", implicit_coarse.peak_force, 2e6 * dt,
              implicit_run.peak_force, 1e6 * dt, explicit_run.peak_force, explicit_run.steps,
              explicit_run.energy_balance_error, 1e6 * implicit_run.contact_duration,
              1e6 * explicit_run.contact_duration);
  EXPECT_NEAR(implicit_coarse.peak_force, implicit_run.peak_force, 1e-3 * implicit_run.peak_force);
  EXPECT_NEAR(explicit_run.peak_force, implicit_run.peak_force, 2e-3 * implicit_run.peak_force);
  EXPECT_NEAR(explicit_run.contact_duration, implicit_run.contact_duration,
              2e-3 * implicit_run.contact_duration);
  EXPECT_NEAR(explicit_run.rebound_velocity.value(), implicit_run.rebound_velocity.value(),
              2e-3 * implicit_run.rebound_velocity.value());
  EXPECT_LT(explicit_run.energy_balance_error, 1e-3);
  ASSERT_TRUE(explicit_run.newton.has_value());
  EXPECT_EQ(explicit_run.newton->factorizations, 0); // nothing factored, nothing solved
}

TEST(CentralDifferenceStep, ElasticPlateAgreesWithImplicitNewmarkOnThe36Plate) {
  expect_agreement(false, 0.25e-6);
}

TEST(CentralDifferenceStep, VonKarmanPlateAgreesWithNewtonNewmarkOnThe36Plate) {
  expect_agreement(true, 0.5e-6);
}

TEST(CentralDifferenceStep, AutomaticStepIsTheStableStepOfTheMovedEquations) {
  // The elastic symmetric laminate moves its bending equations alone (in-plane DOFs exactly decoupled,
  // 1927 of 3245); the von Kármán plate moves all. The highest frequency of both is that of the
  // rotations on their lumped rotary inertia ρh³/12 (thickness shear), not of the in-plane waves: the two
  // stable steps are equal (0.40 µs measured; each ω_max an upper bound within 5e-4 of the exact one,
  // highest_frequency_tolerance), and dt = "auto" is that step.
  const ImpactCase elastic(
      impact_case_description(parse_deck(thesis_3_6(false, "\"auto\"", "explicit"), "e.toml")));
  const ImpactCase karman(
      impact_case_description(parse_deck(thesis_3_6(true, "\"auto\"", "explicit"), "k.toml")));
  ASSERT_TRUE(elastic.explicit_omega_max() && karman.explicit_omega_max());
  std::printf("[ measured ] stable steps: elastic %.6g s (%d equations), von Karman %.6g s (%d equations)\n",
              elastic.settings().dt, elastic.equations(), karman.settings().dt, karman.equations());
  EXPECT_DOUBLE_EQ(elastic.settings().dt, stable_time_step(*elastic.explicit_omega_max()));
  EXPECT_DOUBLE_EQ(karman.settings().dt, stable_time_step(*karman.explicit_omega_max()));
  EXPECT_LT(elastic.equations(), karman.equations());
  EXPECT_NEAR(karman.settings().dt, elastic.settings().dt, 5e-4 * elastic.settings().dt);
  // Both name a rotation as the DOF where the highest mode is largest (step_policy.hpp, StableStepSource).
  ASSERT_TRUE(elastic.settings().stable_step && karman.settings().stable_step);
  EXPECT_GE(elastic.settings().stable_step->place.dof, 3);
  EXPECT_GE(karman.settings().stable_step->place.dof, 3);
  EXPECT_NEAR(elastic.settings().dt, 4.0e-7, 0.01e-7);
}

TEST(CentralDifferenceStep, RefusesAStepAboveTheStableStepNamingTheKey) {
  try {
    (void)test::run_deck(thesis_3_6(false, "1.0e-6", "explicit"));
    ADD_FAILURE() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("[time] integration = \"explicit\""), std::string::npos) << what;
    EXPECT_NE(what.find("set time.dt <="), std::string::npos) << what;
  }
}

} // namespace
} // namespace plyimpact::central_difference_step_tests
