// Progressive ply damage with explicit central differences ([damage] integration = "explicit",
// central differences on the damaging plate, analysis/integrators/central_difference_step.cpp): the highest
// frequency that sets the stable step against a closed form, the energy balance where many points soften at
// once (where the implicit step stops and the lagged one leaks energy), the elastic plate of the implicit
// scheme when nothing cracks, agreement with the iterated implicit step where that one runs, and the refusals
// of a step that cannot be stable.
#include "plyimpact/analysis/integrators/step_policy.hpp"
#include "plyimpact/analysis/plate_analyses/modal_analysis.hpp"
#include "plyimpact/analysis/plate_analyses/nonlinear_static.hpp"
#include "support/impact_decks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace plyimpact::explicit_damage_step_tests {
namespace {

ImpactResult run(const std::string& text) {
  return test::run_deck(text, "explicit.toml");
}

const auto with = test::with_key;

/// examples/damage-progressive-lagged.toml (7 × 7 mesh of 1.7 mm, 30 g at 3 m/s, strengths lowered to the
/// band limit, point load) with the given integration and time step, ended at 300 µs (past the peak).
std::string hard_impact(const std::string& integration, const std::string& dt) {
  return with(with(with(test::example_text("damage-progressive-lagged.toml"), "dt", dt), "integration",
                   "\"" + integration + "\""),
              "end", "3.0e-4");
}

/// The stiffness of n masses in a chain between fixed ends, n + 1 springs k.
SparseMatrix spring_chain(int n, double k) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, 2.0 * k);
    if (i > 0) entries.emplace_back(i, i - 1, -k), entries.emplace_back(i - 1, i, -k);
  }
  SparseMatrix K(n, n);
  K.setFromTriplets(entries.begin(), entries.end());
  return K;
}

/// ω_max of n equal masses m on spring_chain(n, k): 2 √(k/m) sin(nπ / (2(n + 1))).
double chain_highest_frequency(int n, double k, double m) {
  return 2.0 * std::sqrt(k / m) * std::sin(n * std::numbers::pi / (2.0 * (n + 1)));
}

TEST(HighestFrequency, SpringChainClosedForm) {
  const double k = 3.0e5, m = 2.0e-3;
  // The estimate bounds ω_max from above, within the residual bound √(1 + 1e-3) of the Ritz value, for 40
  // masses and for 2000 (the upper spectrum clustered: λ_n-1/λ_n = 1 - 2.5e-6).
  for (const int n : {40, 2000}) {
    const double exact = chain_highest_frequency(n, k, m);
    const double omega = highest_angular_frequency(spring_chain(n, k), Eigen::VectorXd::Constant(n, m));
    EXPECT_GE(omega, exact) << n;
    EXPECT_LE(omega, exact * std::sqrt(1.0 + highest_frequency_tolerance)) << n;
  }
  // Halving one mass cannot lower ω_max (Rayleigh quotient over a smaller M).
  const int n = 40;
  Eigen::VectorXd lighter = Eigen::VectorXd::Constant(n, m);
  lighter(n / 2) = 0.5 * m;
  EXPECT_GT(highest_angular_frequency(spring_chain(n, k), lighter), chain_highest_frequency(n, k, m));
}

TEST(HighestFrequency, TheModeOfALightMassOnTheChainIsLargestThere) {
  // One mass 100 times lighter in a chain of 40: its own frequency √(2k/(m/100)) is far above the chain's
  // band 2√(k/m), so the highest mode is localised on it, and highest_mode names its equation.
  const int n = 40, light = 23;
  const double k = 3.0e5, m = 2.0e-3;
  Eigen::VectorXd mass = Eigen::VectorXd::Constant(n, m);
  mass(light) = m / 100.0;
  const HighestMode mode = highest_mode(spring_chain(n, k), mass);
  EXPECT_EQ(mode.equation, light);
  EXPECT_GE(mode.omega, std::sqrt(2.0 * k / mass(light))); // its Rayleigh quotient bounds ω_max from below
}

TEST(ExplicitDamageStep, EnergyBalanceClosesWhereManyPointsSoften) {
  // At 3 m/s whole regions soften within a few steps: the implicit step stops, the lagged one runs
  // with a balance error of 0.5-1 % that is first order in Δt (test_progressive_impact.cpp). The
  // explicit step evaluates the law once at each step's own displacement, so the damage dissipation
  // the law records is the energy the plate loses: the balance closes to the time integration's
  // second-order error, far below the 1 %.
  const ImpactResult r = run(hard_impact("explicit", "6.0e-8"));
  const ImpactResult lagged = run(hard_impact("lagged", "1.75e-6"));
  const double e0 = 0.5 * 0.03 * 3.0 * 3.0;
  const double damage = r.progressive->dissipated.sum();
  std::printf(
      "[ measured ] explicit: balance error %.3g %% of %.4g J, damage dissipation %.4g J, peak %.5g N "
      "(%ld steps); lagged at 1.75 us: %.3g %%, %.4g J, %.5g N\n",
      100.0 * r.energy_balance_error, e0, damage, r.peak_force, r.steps, 100.0 * lagged.energy_balance_error,
      lagged.progressive->dissipated.sum(), lagged.peak_force);
  EXPECT_GT(damage, 0.1 * e0); // a real share of the impact energy goes into the plies
  EXPECT_LT(r.energy_balance_error, 1e-4);
  EXPECT_LT(r.energy_balance_error, 0.05 * lagged.energy_balance_error);
  EXPECT_FALSE(r.suspect);
}

TEST(ExplicitDamageStep, UnbreakablePliesGiveTheElasticPlate) {
  // Strengths 1000 times larger: nothing cracks, and central differences on the lumped mass and the
  // implicit average-acceleration step of the elastic plate are two second-order schemes of the same
  // semi-discrete equations: at Δt = 60 ns (1/3000 of the contact) their peak forces agree to O(Δt²).
  std::string strong = test::unbreakable_t300_976(hard_impact("explicit", "6.0e-8"));
  strong = with(strong, "oversize", "\"error\"");
  const ImpactResult explicit_run = run(strong);
  const ImpactResult elastic = run(strong.substr(0, strong.find("\n[damage]") + 1)); // no [damage]
  std::printf("[ measured ] peak force %.8g N explicit, %.8g N implicit elastic; times %.6g, %.6g us\n",
              explicit_run.peak_force, elastic.peak_force, 1e6 * explicit_run.time_of_peak_force,
              1e6 * elastic.time_of_peak_force);
  EXPECT_EQ(explicit_run.progressive->dissipated.sum(), 0.0);
  EXPECT_NEAR(explicit_run.peak_force, elastic.peak_force, 1e-4 * elastic.peak_force);
  EXPECT_NEAR(explicit_run.time_of_peak_force, elastic.time_of_peak_force, 0.5e-6);
}

TEST(ExplicitDamageStep, AgreesWithTheIteratedSecantWhereItConverges) {
  // examples/damage-progressive.toml (2 m/s, 1 mm elements, the bottom ply cracks in matrix tension at
  // 48 µs) to 150 µs: the iterated implicit step at Δt = 0.875 µs and the explicit one at 35 ns crack the
  // same ply first, at the same time within the implicit step, and dissipate the same energy.
  const std::string deck = with(test::example_text("damage-progressive.toml"), "end", "1.5e-4");
  const ImpactResult implicit_run = run(with(deck, "dt", "0.875e-6"));
  const ImpactResult explicit_run = run(with(deck, "dt", "3.5e-8") + "integration = \"explicit\"\n");
  const double d_im = implicit_run.progressive->dissipated.sum();
  const double d_ex = explicit_run.progressive->dissipated.sum();
  ASSERT_TRUE(implicit_run.progressive->first() && explicit_run.progressive->first());
  std::printf("[ measured ] first damage at %.5g us implicit, %.5g us explicit; dissipation %.5g J, %.5g J; "
              "force at the end %.6g N, %.6g N\n",
              1e6 * implicit_run.progressive->first()->time, 1e6 * explicit_run.progressive->first()->time,
              d_im, d_ex, implicit_run.history.back().force, explicit_run.history.back().force);
  EXPECT_EQ(explicit_run.progressive->first_mode, implicit_run.progressive->first_mode);
  EXPECT_EQ(explicit_run.progressive->first()->ply, implicit_run.progressive->first()->ply);
  EXPECT_NEAR(explicit_run.progressive->first()->time, implicit_run.progressive->first()->time, 0.875e-6);
  EXPECT_NEAR(d_ex, d_im, 0.05 * d_im);
  EXPECT_NEAR(explicit_run.history.back().force, implicit_run.history.back().force,
              0.01 * implicit_run.history.back().force);
}

TEST(ExplicitDamageStep, RefusesAStepAboveTheStableStep) {
  // The 7 × 7 plate's ω_max is 2.76e7 rad/s: 0.9 · 2/ω_max = 65 ns. 1.75 µs is refused with the step
  // to use; so is a consistent mass (not diagonal).
  try {
    (void)run(hard_impact("explicit", "1.75e-6"));
    ADD_FAILURE() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("time.dt <= 6.5"), std::string::npos) << what;
  }
  const std::string consistent =
      with(hard_impact("explicit", "6.0e-8"), "element", "\"mitc9\"\nmass = \"consistent\"");
  EXPECT_THROW((void)run(consistent), DeckError); // at mesh.mass, by the table of what runs (issue 78)
}

TEST(ExplicitDamageStep, AutomaticStepIsTheStableStep) {
  // dt = "auto" is the contact time / 1000 (0.53 µs here), above the stable step: with the explicit
  // step it becomes 0.9 · 2/ω_max of the plate, 65 ns (the step the refusal above names).
  const ImpactCase impact(
      impact_case_description(parse_deck(hard_impact("explicit", "\"auto\""), "auto.toml")));
  std::printf("[ measured ] automatic explicit step %.6g s\n", impact.settings().dt);
  const DiscretePlate& plate = impact.model(); // the undamaged plate's K and lumped M
  EXPECT_DOUBLE_EQ(impact.settings().dt,
                   stable_time_step(highest_angular_frequency(plate.stiffness(),
                                                              MassOperator(plate.mass(), 1e-14).diagonal())));
  // Lanczos converged to 1e-6 gave 6.5134e-8 s; the estimate bounds ω_max from above within 5e-4.
  EXPECT_LE(impact.settings().dt, 6.5135e-8);
  EXPECT_GE(impact.settings().dt, 6.5134e-8 * (1.0 - 5e-4));
}

TEST(ExplicitDamageStep, StopsWhenTheContactSpringMakesTheStepUnstable) {
  // A contact stiffness 10⁴ times the Hertz value puts a spring of ~1e10 N/m on the impact point's
  // lumped mass (~1e-5 kg): ω_c ≈ 3e7 rad/s, so Δt = 60 ns is no longer stable. The run stops with the
  // step to use instead of producing a growing oscillation.
  const std::string stiff = with(hard_impact("explicit", "6.0e-8"), "k", "8.728e12");
  try {
    (void)run(stiff);
    ADD_FAILURE() << "expected NewtonFailure";
  } catch (const NewtonFailure& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("contact spring"), std::string::npos) << what;
  }
}

} // namespace
} // namespace plyimpact::explicit_damage_step_tests
