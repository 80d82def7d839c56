// Mass scaling of explicit runs (analysis/mass_scaling.hpp, docs/mass_scaling.md): Gershgorin's bound
// (MS1) holds on a real plate, nodal scaling reaches the step it was asked for (MS2 bounds ω_max), rotary
// scaling touches the rotations alone and leaves the §3.6 answer where it was, the added mass's kinetic
// energy is ½ Σ Δm v², and a run whose added mass carries more than 1 % of the impact energy says so.
#include "plyimpact/analysis/guards.hpp"
#include "plyimpact/analysis/mass_scaling.hpp"
#include "plyimpact/analysis/modal_analysis.hpp"
#include "plyimpact/analysis/step_policy.hpp"
#include "support/impact_decks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>

namespace plyimpact {
namespace {

const auto with = test::with_key;

/// examples/thesis-3.6-v268-explicit.toml (von Kármán plate) with `time_keys` added to [time].
std::string thesis_3_6_explicit(const std::string& time_keys) {
  return with(test::example_text("thesis-3.6-v268-explicit.toml"), "integration",
              "\"explicit\"\n" + time_keys);
}

ImpactCase explicit_case(const std::string& time_keys) {
  return ImpactCase(impact_case_description(parse_deck(thesis_3_6_explicit(time_keys), "ms.toml")));
}

double sum(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0);
}

TEST(MassScaling, GershgorinBoundsTheHighestFrequencyOfThePlateFromAbove) {
  // MS1 on the §3.6 plate's explicit model (elastic here, lumped mass): max_i g_i ≥ ω_max², the rotations'
  // and the translations' own rows each below the whole.
  const ImpactCaseDescription d = impact_case_description(parse_deck(thesis_3_6_explicit(""), "ms.toml"));
  const PlateModel plate = impact_plate_model(d);
  PlatePhysics physics;
  physics.integrator = Integrator::central_difference;
  const std::unique_ptr<MechanicalModel> model = mechanical_model(plate, physics);
  const ScaledMass m = explicit_mass(*model, "[time] integration", MassScaling{});
  const std::vector<EquationPlace> places = model->places();
  ASSERT_EQ(places.size(), static_cast<std::size_t>(model->size()));
  const double omega = highest_angular_frequency(model->initial_stiffness(), m.mass);
  const double all = gershgorin_bound(model->initial_stiffness(), m.mass, places, DofGroup::all);
  const double rotations = gershgorin_bound(model->initial_stiffness(), m.mass, places, DofGroup::rotations);
  const double translations =
      gershgorin_bound(model->initial_stiffness(), m.mass, places, DofGroup::translations);
  std::printf("[ measured ] omega_max %.6g rad/s; Gershgorin %.6g (rotations %.6g, translations %.6g)\n",
              omega, std::sqrt(all), std::sqrt(rotations), std::sqrt(translations));
  EXPECT_GE(all, omega * omega);
  EXPECT_DOUBLE_EQ(all, std::max(rotations, translations));
}

TEST(MassScaling, NodalScalingReachesTheTargetStep) {
  // MS2 brings every row's g_i to at most ω_t², so ω_max ≤ ω_t and the measured stable step is at least
  // target_dt (the Lanczos ω_max is an upper bound within 5e-4). 1 µs is 2.5 times the unscaled step.
  const ImpactCase plain = explicit_case("");
  const ImpactCase scaled = explicit_case("mass_scaling = \"nodal\"\ntarget_dt = 1e-6");
  ASSERT_TRUE(scaled.settings().mass_scaling.has_value());
  const MassScalingReport& r = *scaled.settings().mass_scaling;
  std::printf("[ measured ] nodal to 1 us: step %.6g s (unscaled %.6g s), %d nodes, factor up to %.4g, "
              "mass +%.4g kg on %.4g kg, rotary inertia +%.4g on %.4g kg m^2\n",
              scaled.settings().dt, plain.settings().dt, r.scaled_nodes, r.largest_factor,
              sum(r.added_mass_kg), sum(r.mass_kg), sum(r.added_rotary_inertia_kg_m2),
              sum(r.rotary_inertia_kg_m2));
  EXPECT_DOUBLE_EQ(r.target_dt, 1e-6);
  EXPECT_GE(scaled.settings().dt, 1e-6 / (1.0 + 5e-4));
  EXPECT_LT(plain.settings().dt, 0.5e-6);
  EXPECT_GT(r.largest_factor, 1.0);
  EXPECT_GT(sum(r.added_mass_kg), 0.0);
  EXPECT_FALSE(plain.settings().mass_scaling.has_value());
}

TEST(MassScaling, RotaryScalingAddsInertiaOnlyAndLeavesThe36AnswerWhereItWas) {
  // Rotary scaling raises the rotations' inertia up to the translations' Gershgorin level: no mass is
  // added, the stable step can only grow (the mass only grows), and the §3.6 plate, whose rotary inertia
  // barely matters at these wavelengths, keeps its peak force and contact time within 1e-4 (measured:
  // 2.5 % more rotary inertia, 3.4 % fewer steps, peak force equal to 1e-6) while the added inertia carries
  // a negligible kinetic energy (measured 2.3e-7 of the impact energy).
  const ImpactCase plain = explicit_case("");
  const ImpactCase scaled = explicit_case("mass_scaling = \"rotary\"");
  ASSERT_TRUE(scaled.settings().mass_scaling.has_value());
  const MassScalingReport& r = *scaled.settings().mass_scaling;
  EXPECT_EQ(r.kind, MassScalingKind::rotary);
  EXPECT_EQ(sum(r.added_mass_kg), 0.0);
  EXPECT_GT(sum(r.added_rotary_inertia_kg_m2), 0.0);
  EXPECT_GE(scaled.settings().dt, plain.settings().dt);
  const ImpactResult a = plain.run();
  const ImpactResult b = scaled.run();
  const double e0 = 0.5 * scaled.settings().impactor.mass * std::pow(scaled.settings().impactor.velocity, 2);
  ASSERT_TRUE(b.added_mass_kinetic_energy.has_value());
  EXPECT_FALSE(a.added_mass_kinetic_energy.has_value());
  std::printf(
      "[ measured ] rotary: step %.6g s against %.6g s, %ld against %ld steps; peak force %.8g N "
      "against %.8g N; added inertia %.4g of %.4g kg m^2; added kinetic energy %.3g of the impact's\n",
      scaled.settings().dt, plain.settings().dt, b.steps, a.steps, b.peak_force, a.peak_force,
      sum(r.added_rotary_inertia_kg_m2), sum(r.rotary_inertia_kg_m2), *b.added_mass_kinetic_energy / e0);
  EXPECT_NEAR(b.peak_force, a.peak_force, 1e-4 * a.peak_force);
  EXPECT_NEAR(b.contact_duration, a.contact_duration, 1e-3 * a.contact_duration);
  EXPECT_LT(*b.added_mass_kinetic_energy, 1e-4 * e0);
  EXPECT_LT(b.energy_balance_error, 1e-3);
  EXPECT_TRUE(std::none_of(b.warnings.begin(), b.warnings.end(),
                           [](const std::string& w) { return w.find("mass_scaling") != std::string::npos; }));
}

TEST(MassScaling, TheAddedMassesKineticEnergyIsHalfTheirMassTimesVelocitySquared) {
  ScaledMass m;
  m.mass = Eigen::VectorXd::Ones(4);
  m.equations = {1, 3};
  m.added = {2.0, 0.5};
  const Eigen::VectorXd v = (Eigen::VectorXd(4) << 1.0, 2.0, 3.0, 4.0).finished();
  EXPECT_DOUBLE_EQ(m.added_kinetic_energy(v), 0.5 * (2.0 * 4.0 + 0.5 * 16.0));
}

TEST(MassScaling, ARunWhoseAddedMassCarriesMoreThanOnePercentOfTheImpactEnergyWarns) {
  // Nodal scaling to 4 µs, ten times the plate's step, adds several times the plate's mass where the
  // impactor strikes: its kinetic energy passes 1 % of the impact's, and the run says so.
  const ImpactCase scaled = explicit_case("mass_scaling = \"nodal\"\ntarget_dt = 4e-6");
  const ImpactResult r = scaled.run();
  const double e0 = 0.5 * scaled.settings().impactor.mass * std::pow(scaled.settings().impactor.velocity, 2);
  ASSERT_TRUE(r.added_mass_kinetic_energy.has_value());
  std::printf("[ measured ] nodal to 4 us: added kinetic energy %.4g J, %.3g of the impact's\n",
              *r.added_mass_kinetic_energy, *r.added_mass_kinetic_energy / e0);
  EXPECT_GT(*r.added_mass_kinetic_energy, added_mass_energy_tolerance * e0);
  EXPECT_TRUE(std::any_of(r.warnings.begin(), r.warnings.end(), [](const std::string& w) {
    return w.find("the mass added by [time] mass_scaling carried up to") != std::string::npos;
  }));
}

TEST(MassScaling, ImplicitStepsRefuseIt) {
  ImpactCaseDescription d = impact_case_description(parse_deck(thesis_3_6_explicit(""), "ms.toml"));
  d.time.integration = TimeIntegration::newmark;
  d.time.mass_scaling.kind = MassScalingKind::rotary;
  EXPECT_THROW({ const ImpactCase c(d); }, std::invalid_argument);
}

} // namespace
} // namespace plyimpact
