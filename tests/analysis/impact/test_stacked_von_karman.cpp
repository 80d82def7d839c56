// The stacked plate whose sub-laminates deflect largely (fem/stacked_model.cpp with nonlinear = true):
// each sub-laminate a von Kármán plate on its own mid-plane. Tied faces move as one laminate's (u_k = u₀ −
// z_k w' makes sub-laminate k's membrane strain the laminate's at every height), so with interfaces that
// hold, the stack stiffens with deflection as the von Kármán laminate does; with interfaces that crack,
// the lagged and the implicit Newton–Newmark steps and central differences solve the same equations and
// keep the energy. The shipped delamination example (a [0_2/90_2]s AS4/PEEK plate, 13.2 mm square, 1.04 mm
// thick) on 5 × 5 elements with the lumped mass.
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "support/impact_decks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>

namespace plyimpact::stacked_von_karman_tests {
namespace {

/// The example on 5 × 5 elements with the lumped mass, at `velocity`, to `end`, the interfaces integrated
/// as `integration`; `nonlinear` makes every plate von Kármán's.
std::string example_5x5(const std::string& integration, const std::string& velocity, const std::string& end,
                        bool nonlinear) {
  std::string text = test::example_text("impact-delamination.toml");
  if (nonlinear) text = test::with_key(text, "analysis", "\"impact\"\nnonlinear = true");
  text = test::with_key(text, "nx", "5");
  text = test::with_key(text, "ny", "5\nmass = \"lumped\"");
  text = test::with_key(text, "end", end);
  text = test::with_key(text, "velocity", velocity);
  return test::with_key(text, "shear_strength", "98.2e6\nintegration = \"" + integration + "\"");
}

/// The same plate without interfaces: one laminate.
std::string without_interfaces(const std::string& text) {
  return text.substr(0, text.find("[delamination]"));
}

/// Strengths and toughnesses far above what the event reaches: no interface point leaves its penalty.
std::string interfaces_that_hold(std::string text) {
  for (const auto& [key, value] : {std::pair{"G_Ic", "969.0e4"},
                                   {"G_IIc", "1719.0e4"},
                                   {"normal_strength", "73.7e8"},
                                   {"shear_strength", "98.2e8"}})
    text = test::with_key(text, key, value);
  return text;
}

// At 12 m/s the plate deflects about its thickness (w/h = 0.89) and membrane tension stiffens it: the
// von Kármán laminate's peak force is a third above the linear one's. The stack whose interfaces hold is
// the von Kármán laminate up to the sub-laminates' own shear corrections (DL0), which make the linear stack
// 1.34 % softer than the linear laminate on this thick plate (a/h = 12.7, test_explicit_delamination_step)
// and matter less as membrane action takes over: measured, the von Kármán stack is 0.36 % below the
// von Kármán laminate, where a stack whose sub-laminates stayed linear would be 26 % below.
TEST(StackedVonKarman, WithInterfacesThatHoldItIsTheVonKarmanLaminate) {
  const std::string base = interfaces_that_hold(example_5x5("explicit", "12.0", "0.2e-3", false));
  const std::string large = interfaces_that_hold(example_5x5("explicit", "12.0", "0.2e-3", true));
  const auto explicit_laminate = [](const std::string& stack) {
    return test::with_key(without_interfaces(stack), "end", "0.2e-3\nintegration = \"explicit\"");
  };
  const ImpactResult stack_linear = test::run_deck(base);
  const ImpactResult stack_large = test::run_deck(large);
  const ImpactResult plate_linear = test::run_deck(explicit_laminate(base));
  const ImpactResult plate_large = test::run_deck(explicit_laminate(large));
  ASSERT_TRUE(stack_large.delamination);
  EXPECT_EQ(stack_large.delamination->dissipated, 0.0);
  const double linear_gap = stack_linear.peak_force / plate_linear.peak_force - 1.0;
  const double large_gap = stack_large.peak_force / plate_large.peak_force - 1.0;
  std::printf("[ measured ] w/h = %.2f; peak force: stack %.2f N (linear %.2f), laminate %.2f N (linear "
              "%.2f): stack - laminate %+.2f %% (linear %+.2f %%); laminate stiffened x %.4f; balance error "
              "%.2e\n",
              stack_large.peak_contact_deflection / 1.04e-3, stack_large.peak_force, stack_linear.peak_force,
              plate_large.peak_force, plate_linear.peak_force, 100.0 * large_gap, 100.0 * linear_gap,
              plate_large.peak_force / plate_linear.peak_force, stack_large.energy_balance_error);
  EXPECT_GT(stack_large.peak_contact_deflection, 0.5 * 1.04e-3);
  EXPECT_GT(plate_large.peak_force / plate_linear.peak_force, 1.2); // the check means something
  EXPECT_LT(std::abs(large_gap), std::abs(linear_gap));             // the shear corrections' gap, no more
  EXPECT_LT(stack_large.energy_balance_error, 1e-3);
}

// At the example's 3 m/s with its own interfaces, which soften and crack: the lagged Newton–Newmark step
// (trapezoidal, each sub-laminate's tangent, the interfaces held over the step) and central differences
// at the stable step give the same peak force (2 %) and interface dissipation (5 %), and each closes its
// energy balance within 1 %.
TEST(StackedVonKarman, TheLaggedStepFollowsTheExplicitOneWhereTheInterfacesCrack) {
  const ImpactResult expl = test::run_deck(example_5x5("explicit", "3.0", "0.3e-3", true));
  const ImpactResult lagged = test::run_deck(example_5x5("lagged", "3.0", "0.3e-3", true));
  ASSERT_TRUE(expl.delamination && lagged.delamination);
  std::printf("[ measured ] peak %.3f N (lagged %.3f, %+.2f %%), interfaces dissipated %.4g J (lagged %.4g, "
              "%+.2f %%), balance error %.2e (lagged %.2e)\n",
              expl.peak_force, lagged.peak_force, 100.0 * (lagged.peak_force / expl.peak_force - 1.0),
              expl.delamination->dissipated, lagged.delamination->dissipated,
              100.0 * (lagged.delamination->dissipated / expl.delamination->dissipated - 1.0),
              expl.energy_balance_error, lagged.energy_balance_error);
  EXPECT_GT(expl.delamination->dissipated, 0.0);
  EXPECT_NEAR(lagged.peak_force / expl.peak_force, 1.0, 0.02);
  EXPECT_NEAR(lagged.delamination->dissipated / expl.delamination->dissipated, 1.0, 0.05);
  EXPECT_LT(expl.energy_balance_error, 0.01);
  EXPECT_LT(lagged.energy_balance_error, 0.01);
}

// Iterating the interfaces' damage within the step (implicit: Newton–Newmark on the stacked model, the
// mixed-mode tangent by LU, each sub-laminate's von Kármán tangent) solves the same equations as
// central differences: to 0.2 ms, where both interfaces have cracked over 3.1 mm², the same peak force
// (0.2 %) and interface dissipation (1 %), the balance within 0.1 %. The iterated law needs a step of
// 0.04 µs on this mesh: at the automatic 0.16 µs (and at 0.08 µs) the iterations stop converging where
// the first points soften (84–136 µs), as the linear stack's own implicit step did on it before the
// redesign (docs/delamination.md, "The implicit step").
TEST(StackedVonKarman, TheImplicitStepFollowsTheExplicitOneWhereTheInterfacesCrack) {
  const ImpactResult expl = test::run_deck(example_5x5("explicit", "3.0", "0.2e-3", true));
  const ImpactResult implicit = test::run_deck(example_5x5("implicit", "3.0", "0.2e-3\ndt = 0.04e-6", true));
  ASSERT_TRUE(expl.delamination && implicit.delamination);
  std::printf("[ measured ] peak %.3f N (implicit %.3f, %+.2f %%), interfaces dissipated %.4g J (implicit "
              "%.4g, %+.2f %%), balance error %.2e (implicit %.2e)\n",
              expl.peak_force, implicit.peak_force, 100.0 * (implicit.peak_force / expl.peak_force - 1.0),
              expl.delamination->dissipated, implicit.delamination->dissipated,
              100.0 * (implicit.delamination->dissipated / expl.delamination->dissipated - 1.0),
              expl.energy_balance_error, implicit.energy_balance_error);
  EXPECT_GT(implicit.delamination->projected_area, 1e-6); // cracked, not only softened
  EXPECT_NEAR(implicit.peak_force / expl.peak_force, 1.0, 0.002);
  EXPECT_NEAR(implicit.delamination->dissipated / expl.delamination->dissipated, 1.0, 0.01);
  EXPECT_LT(implicit.energy_balance_error, 1e-3);
}

} // namespace
} // namespace plyimpact::stacked_von_karman_tests
