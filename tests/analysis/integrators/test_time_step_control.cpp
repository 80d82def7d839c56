// Error-controlled time steps (issue 22, analysis/integrators/time_step_control.hpp): the controller's
// arithmetic, the convergence of an adaptive impact with its tolerance against the Hertz closed form, energy
// conservation with changing steps, and the plate cases that the fixed step also solves.
#include "plyimpact/analysis/contact/contact_rules.hpp"
#include "plyimpact/analysis/impact/guards.hpp"
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/analysis/integrators/time_step_control.hpp"
#include "plyimpact/fem/equation_subset.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/io/deck/deck_error.hpp"
#include "support/impact_decks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace plyimpact::time_step_control_tests {
namespace {

using Errors = TimeStepControl::StepErrors;

TEST(TimeStepControl, TheErrorsAreZienkiewiczXieAndTheInterpolationOfTheIndentation) {
  // α̈ = ẅi − ẅs: −150 m/s² at the start, −420 at the end of a 64 µs step, β = 1/4:
  // (TS1) Δt²/12 · 270, (TS2) Δt² · 420/8.
  const TimeStepControl c(NewmarkCoefficients(64e-6, 0.25, 0.5), AdaptiveTimeStep{1e-3, 6}, 1e-4);
  const Errors e = c.indentation_errors(-100.0, -400.0, 50.0, 20.0);
  EXPECT_NEAR(e.integration, 64e-6 * 64e-6 / 12.0 * 270.0, 1e-20);
  EXPECT_NEAR(e.sampling, 64e-6 * 64e-6 * 420.0 / 8.0, 1e-20);
}

TEST(TimeStepControl, ARejectedStepGoesDownAsManyLevelsAsItsErrorsOrderAsks) {
  // e_i ∝ Δt³: 27 times the bound needs Δt/3, two halvings; e_s ∝ Δt²: 16 times needs Δt/4, two halvings;
  // 1.5 times either needs one.
  const double bound = 1e-3 * 1e-4;
  TimeStepControl c(NewmarkCoefficients(64e-6, 0.25, 0.5), AdaptiveTimeStep{1e-3, 8}, 1e-4);
  EXPECT_FALSE(c.accept({27.0 * bound, 0.0}));
  EXPECT_EQ(c.level(), 2);
  EXPECT_FALSE(c.accept({0.0, 16.0 * bound}));
  EXPECT_EQ(c.level(), 4);
  EXPECT_FALSE(c.accept({0.0, 1.5 * bound}));
  EXPECT_EQ(c.level(), 5);
  EXPECT_FALSE(c.accept({1e6 * bound, 0.0})); // never below the finest level
  EXPECT_EQ(c.level(), 7);
  // Accepted, and small enough to double, but right after a redone step: no growth yet.
  EXPECT_TRUE(c.accept({0.01 * bound, 0.01 * bound}));
  EXPECT_EQ(c.level(), 7);
  EXPECT_TRUE(c.accept({0.01 * bound, 0.01 * bound})); // now it grows by one level
  EXPECT_EQ(c.level(), 6);
  EXPECT_TRUE(c.accept({0.07 * bound, 0.0})); // 8 e_i = 0.56 bound after doubling: stays
  EXPECT_EQ(c.level(), 6);
  EXPECT_TRUE(c.accept({0.0, 0.13 * bound})); // 4 e_s = 0.52 bound: stays
  EXPECT_EQ(c.level(), 6);
  EXPECT_TRUE(c.accept({0.06 * bound, 0.12 * bound})); // both below half the bound after doubling
  EXPECT_EQ(c.level(), 5);
}

TEST(TimeStepControl, TimeIsTheExactSumOfTheStepsTaken) {
  // Steps of 8, 8, 16, 32 µs (levels 2, 2, 1, 0 of 32 µs): every time is a whole number of the smallest
  // step, so the sum carries no round-off.
  const double bound = 1e-3 * 1e-4;
  TimeStepControl c(NewmarkCoefficients(32e-6, 0.25, 0.5), AdaptiveTimeStep{1e-3, 4}, 1e-4);
  EXPECT_FALSE(c.accept({20.0 * bound, 0.0})); // ∛20 = 2.7: two levels
  EXPECT_EQ(c.level(), 2);
  EXPECT_DOUBLE_EQ(c.step_end_time(), 8e-6);
  EXPECT_TRUE(c.accept({})); // no growth right after the redone step
  EXPECT_DOUBLE_EQ(c.step_end_time(), 16e-6);
  EXPECT_TRUE(c.accept({}));
  EXPECT_EQ(c.step_end_time(), 16e-6 + 16e-6);
  EXPECT_TRUE(c.accept({}));
  EXPECT_EQ(c.step_end_time(), 32e-6 + 32e-6);
  const AdaptiveStepResult r = c.result(3);
  EXPECT_EQ(r.rejected_steps, 1);
  EXPECT_DOUBLE_EQ(r.smallest_used_dt, 8e-6);
  EXPECT_DOUBLE_EQ(r.smallest_allowed_dt, 4e-6);
}

TEST(TimeStepControl, TheFinestLevelAcceptsEveryStepAndCountsTheOnesAboveTheBound) {
  TimeStepControl c(NewmarkCoefficients(2e-6, 0.25, 0.5), AdaptiveTimeStep{1e-3, 2}, 1e-4);
  EXPECT_FALSE(c.accept({1.0, 0.0}));
  EXPECT_EQ(c.level(), 1);
  EXPECT_TRUE(c.accept({1.0, 0.0}));
  const AdaptiveStepResult r = c.result(2);
  EXPECT_EQ(r.steps_above_tolerance, 1);
  EXPECT_GT(r.largest_error_ratio, 1.0);
}

TEST(TimeStepControl, TheLinearAccelerationMethodHasNoEstimateAndIsRefused) {
  EXPECT_THROW(TimeStepControl(NewmarkCoefficients(1e-6, 1.0 / 6.0, 0.5), AdaptiveTimeStep{}, 1e-4),
               std::invalid_argument);
}

using test::rigid_target_deck;
using test::run_deck;

TEST(AdaptiveImpact, RigidTargetPeakForceConvergesWithTheToleranceAsTheErrorsOrdersPredict) {
  // Elastic Hertz impact on a rigid half-space: F_max = k^(2/5) (5 m v0²/4)^(3/5), T = 2.94328 α_m/v0.
  // Held at the tolerance, the integration error e_i ∝ Δt³ gives Δt ∝ tol^(1/3), the sampling error
  // e_s ∝ Δt² gives Δt ∝ tol^(1/2); the second-order global error goes as Δt². A tolerance 100 times
  // smaller therefore divides the peak force's error by 21.5 (e_i governs) to 100 (e_s governs), and
  // multiplies the steps by 4.6 to 10.
  const double m = 0.314, v0 = 2.92, k = 0.6e9;
  const double F_max = std::pow(k, 0.4) * std::pow(1.25 * m * v0 * v0, 0.6);
  const double T = hertz_contact_time(m, v0, k);
  double errors[2] = {}, rebound_errors[2] = {};
  long steps[2] = {};
  int i = 0;
  for (const char* tol : {"1e-3", "1e-5"}) {
    const ImpactResult r = run_deck(
        rigid_target_deck(std::string("dt = 100e-6\nadaptive = true\nlevels = 16\ntolerance = ") + tol));
    errors[i] = std::abs(r.peak_force / F_max - 1.0);
    rebound_errors[i] = std::abs(r.rebound_velocity.value() / v0 - 1.0);
    steps[i] = r.steps;
    std::printf(
        "  tolerance %s: peak force error %.3e, contact time error %.3e, rebound error %.3e, %ld steps "
        "(%ld redone), smallest step %.3g us\n",
        tol, errors[i], std::abs(r.contact_duration / T - 1.0), rebound_errors[i], r.steps,
        r.time_steps->rejected_steps, r.time_steps->smallest_used_dt * 1e6);
    EXPECT_TRUE(r.complete);
    EXPECT_EQ(r.time_steps->steps_above_tolerance, 0);
    EXPECT_LE(r.time_steps->largest_error_ratio, 1.0);
    ++i;
  }
  EXPECT_GT(errors[0] / errors[1], 15.0);
  EXPECT_GT(rebound_errors[0] / rebound_errors[1], 15.0); // elastic: the rebound speed tends to v0 as well
  const double step_ratio = static_cast<double>(steps[1]) / static_cast<double>(steps[0]);
  EXPECT_GT(step_ratio, 4.0);
  EXPECT_LT(step_ratio, 12.0);
}

/// The §4.2 plate and impactor on a 6 × 4 mesh, elastic contact: `time` is the [time] table's body.
std::string plate_deck(const std::string& time) {
  return test::thesis_3_6_deck("mass = 0.314\nvelocity = 2.92",
                               "[contact]\nk = 0.6e9\nunloading = \"elastic\"\n[time]\n" + time, "6, 4");
}

TEST(AdaptiveImpact, PlateImpactAgreesWithAFineFixedStepAndKeepsTheEnergy) {
  // The same event at a fixed 0.25 µs and error-controlled from 50 µs down: the peak force, the contact
  // time and the rebound agree to the tolerance's order, the energy balance holds (to the contact work's
  // trapezoidal error, which the steps' control keeps small), and after the impactor has left only the
  // longest step is used (nothing there changes the contact force).
  const ImpactResult fixed = run_deck(plate_deck("dt = 0.25e-6\n"));
  const ImpactResult adaptive =
      run_deck(plate_deck("dt = 50e-6\nadaptive = true\nlevels = 12\ntolerance = 1e-4\n"));
  std::printf("  fixed 0.25 us: %.3f N, contact %.3f us, rebound %.6f m/s, %ld steps\n", fixed.peak_force,
              fixed.contact_duration * 1e6, fixed.rebound_velocity.value(), fixed.steps);
  std::printf(
      "  adaptive: %.3f N, contact %.3f us, rebound %.6f m/s, %ld steps (%ld redone), %.3g to %.3g us, "
      "energy balance error %.3g\n",
      adaptive.peak_force, adaptive.contact_duration * 1e6, adaptive.rebound_velocity.value(), adaptive.steps,
      adaptive.time_steps->rejected_steps, adaptive.time_steps->smallest_used_dt * 1e6,
      adaptive.time_steps->largest_dt * 1e6, adaptive.energy_balance_error);
  EXPECT_NEAR(adaptive.peak_force / fixed.peak_force, 1.0, 5e-3);
  EXPECT_NEAR(adaptive.contact_duration / fixed.contact_duration, 1.0, 2e-2);
  EXPECT_NEAR(adaptive.rebound_velocity.value() / fixed.rebound_velocity.value(), 1.0, 5e-3);
  EXPECT_LT(adaptive.energy_balance_error, 1e-4);
  EXPECT_FALSE(adaptive.suspect);
  EXPECT_LT(adaptive.steps * 10, fixed.steps);
  // Out of contact (after the step that ends the contact) every step is the longest.
  const auto& h = adaptive.history;
  const double separation = adaptive.episodes.back().end;
  long after = 0;
  for (std::size_t n = 2; n < h.size(); ++n)
    if (h[n - 2].t > separation + 1e-12) {
      ++after;
      EXPECT_NEAR(h[n].t - h[n - 1].t, 50e-6, 1e-15) << "at t = " << h[n].t;
    }
  EXPECT_GT(after, 10);
}

TEST(TimeStepControl, OutOfContactTheNextStepIsTheLongest) {
  TimeStepControl c(NewmarkCoefficients(32e-6, 0.25, 0.5), AdaptiveTimeStep{1e-3, 4}, 1e-4);
  EXPECT_FALSE(c.accept({1.0, 0.0}));
  EXPECT_EQ(c.level(), 3);
  c.accept_free_flight();
  EXPECT_EQ(c.level(), 0);
  EXPECT_DOUBLE_EQ(c.step_end_time(), 4e-6 + 32e-6);
}

TEST(AdaptiveImpact, AGivenEndTimeIsWhereTheRunStops) {
  // 50 µs steps out of contact, from wherever the contact ended, would overshoot 1 200 µs by up to 50 µs;
  // the last steps are shortened to end there (1 200 µs is 24 × 50 µs, a whole number of every step).
  const ImpactResult r =
      run_deck(plate_deck("dt = 50e-6\nadaptive = true\nlevels = 12\ntolerance = 1e-4\nend = 1200e-6\n"));
  EXPECT_NEAR(r.end_time, 1200e-6, 1e-15);
  EXPECT_TRUE(r.complete);
}

TEST(TimeStepControl, EndByShortensTheNextStepUntilItFits) {
  TimeStepControl c(NewmarkCoefficients(32e-6, 0.25, 0.5), AdaptiveTimeStep{1e-3, 4}, 1e-4);
  c.end_by(12e-6); // 32 → 16 → 8 µs fits
  EXPECT_EQ(c.level(), 2);
  EXPECT_DOUBLE_EQ(c.step_end_time(), 8e-6);
  c.end_by(3e-6); // cannot fit: the smallest, 4 µs
  EXPECT_EQ(c.level(), 3);
  EXPECT_EQ(c.result(1).rejected_steps, 0);
}

TEST(AdaptiveImpact, RunsOfOneCaseShareTheFactorsOfEachStepLevel) {
  const Deck deck =
      parse_deck(plate_deck("dt = 50e-6\nadaptive = true\nlevels = 12\ntolerance = 1e-4\n"), "t.toml");
  const ImpactCase impact(impact_case_description(deck));
  const ImpactResult first = impact.run();
  const ImpactResult second = impact.run();
  EXPECT_EQ(first.peak_force, second.peak_force);
  EXPECT_EQ(first.steps, second.steps);
  EXPECT_EQ(second.time_steps->factorizations, first.time_steps->factorizations);
  EXPECT_GT(first.time_steps->factorizations, 1);
}

TEST(AdaptiveImpact, EachLevelsFactorCountsAgainstTheMemoryLimit) {
  // The limit holds level 0's factor and half another: the run stops with InsufficientMemory when it
  // needs a second level, instead of growing past the memory it was given.
  const Deck deck =
      parse_deck(plate_deck("dt = 50e-6\nadaptive = true\nlevels = 12\ntolerance = 1e-4\n"), "t.toml");
  ImpactCaseDescription d = impact_case_description(deck);
  const DiscretePlate model = impact_plate_model(d);
  const SparseMatrix K = model.stiffness(), M = model.mass();
  const EquationSubset equations = bending_equations_if_decoupled(model, K, M);
  const NewmarkCoefficients largest(50e-6, 0.25, 0.5);
  const double one = estimate_factor_memory(equations.restrict(K) + largest.c0 * equations.restrict(M)).bytes;
  d.memory_limit_bytes = 1.5 * one;
  const ImpactCase impact(d);
  try {
    (void)impact.run();
    ADD_FAILURE() << "no InsufficientMemory";
  } catch (const InsufficientMemory& e) {
    EXPECT_NE(std::string(e.what()).find("would make 2 factors held"), std::string::npos) << e.what();
  }
  d.memory_limit_bytes = 12.5 * one; // room for every level
  EXPECT_GT(ImpactCase(d).run().time_steps->factorizations, 1);
}

TEST(AdaptiveImpact, DeckKeysAndTheirSlips) {
  const auto error_of = [](const std::string& text) {
    try {
      (void)parse_deck(text, "t.toml");
    } catch (const DeckError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const Deck deck =
      parse_deck(plate_deck("dt = 50e-6\nadaptive = true\nlevels = 5\ntolerance = 1e-4\n"), "t.toml");
  ASSERT_TRUE(deck.time.adaptive.has_value());
  EXPECT_EQ(deck.time.adaptive->levels, 5);
  EXPECT_DOUBLE_EQ(deck.time.adaptive->tolerance, 1e-4);
  EXPECT_FALSE(parse_deck(plate_deck("dt = 1e-6\n"), "t.toml").time.adaptive.has_value());
  EXPECT_NE(error_of(plate_deck("dt = 1e-6\ntolerance = 1e-3\n")).find("add adaptive = true"),
            std::string::npos);
  EXPECT_NE(error_of(plate_deck("adaptive = \"yes\"\n")).find("time.adaptive must be true or false"),
            std::string::npos);
  EXPECT_NE(error_of(plate_deck("adaptive = true\nlevels = 30\n")).find("between 1 and 24"),
            std::string::npos);
  EXPECT_NE(error_of(plate_deck("adaptive = true\ntolerance = 2.0\n")).find("(0, 1)"), std::string::npos);
  std::string with_strengths =
      plate_deck("adaptive = true\n") + "[damage]\ncriteria = [\"choi-chang-matrix\"]\n";
  with_strengths.replace(
      with_strengths.find("rho = 1540.0"), 12,
      "rho = 1540.0\nXt = 1.5e9\nXc = 1.2e9\nYt = 55e6\nYc = 294e6\nS12 = 101e6\nS23 = 33e6");
  EXPECT_NE(error_of(with_strengths).find("controls the error of the contact force only"), std::string::npos)
      << error_of(with_strengths);
}

TEST(AdaptiveImpact, AutomaticStepMakesTheAutomaticFixedStepTheSmallest) {
  const Deck deck = parse_deck(plate_deck("adaptive = true\nlevels = 4\n"), "t.toml");
  const ImpactCaseDescription d = impact_case_description(deck);
  const double fixed = automatic_time_step(0.314, 0.6e9, 2.92);
  EXPECT_DOUBLE_EQ(resolved_settings(d).dt, 8.0 * fixed);
}

TEST(AdaptiveImpact, TheNonLinearPlateRefusesAdaptiveSteps) {
  Deck deck = parse_deck(plate_deck("dt = 50e-6\nadaptive = true\n"), "t.toml");
  ImpactCaseDescription d = impact_case_description(deck);
  d.nonlinear = NonlinearImpactSettings{};
  // refused by the table of what runs when the case is built (issue 78), before anything is assembled
  EXPECT_THROW({ const ImpactCase impact(d); }, std::invalid_argument);
}

} // namespace
} // namespace plyimpact::time_step_control_tests
