// Mass scaling of explicit runs (analysis/impact/mass_scaling.hpp, docs/mass_scaling.md): Gershgorin's bound
// (MS1) holds on a real plate, nodal scaling reaches the step it was asked for (MS2 bounds ω_max), rotary
// scaling touches the rotations alone and leaves the §3.6 answer where it was, the added mass's kinetic
// energy is ½ Σ Δm v², and a run whose added mass carries more than 1 % of the impact energy says so.
// Selective scaling of a stack's interfaces (MS3) adds no mass to the plate's motion, bounds the faces'
// relative modes by ω_c, lengthens the stacked example's step by an order of magnitude and leaves its
// answer where it was.
#include "plyimpact/analysis/impact/guards.hpp"
#include "plyimpact/analysis/impact/mass_scaling.hpp"
#include "plyimpact/analysis/integrators/step_policy.hpp"
#include "plyimpact/analysis/plate_analyses/modal_analysis.hpp"
#include "plyimpact/fem/element_loop.hpp"
#include "support/impact_decks.hpp"

#include <Eigen/Eigenvalues>
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>

namespace plyimpact::mass_scaling_tests {
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
  const DiscretePlate plate = impact_plate_model(d);
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

/// examples/impact-delamination-explicit.toml on a 5 × 5 mesh to 0.25 ms (past its peak force), with
/// `time_keys` added to [time]; `unbreakable`: strengths × 100 and toughnesses × 10⁴.
std::string stacked_explicit(const std::string& time_keys, bool unbreakable) {
  std::string text = test::example_text("impact-delamination-explicit.toml");
  text = with(with(with(text, "nx", "5"), "ny", "5"), "end", "2.5e-4\n" + time_keys);
  if (unbreakable)
    for (const auto& [key, value] : {std::pair{"G_Ic", "969.0e4"},
                                     {"G_IIc", "1719.0e4"},
                                     {"normal_strength", "73.7e8"},
                                     {"shear_strength", "98.2e8"}})
      text = with(text, key, value);
  return text;
}

/// The stacked example's explicit model and its selectively scaled mass.
struct SelectiveStack {
  std::unique_ptr<MechanicalModel> model;
  ScaledMass unscaled, scaled;
};

SelectiveStack selective_stack() {
  const ImpactCaseDescription d =
      impact_case_description(parse_deck(stacked_explicit("", false), "selective.toml"));
  static const DiscretePlate plate = impact_plate_model(d);
  PlatePhysics physics;
  physics.interfaces = d.delamination;
  physics.integrator = Integrator::central_difference;
  SelectiveStack s{mechanical_model(plate, physics), {}, {}};
  s.unscaled = explicit_mass(*s.model, "[time] integration", MassScaling{});
  s.scaled = explicit_mass(*s.model, "[time] integration", MassScaling{MassScalingKind::selective, {}});
  return s;
}

TEST(MassScaling, SelectiveScalingAddsNoMassToThePlatesMotionAndBoundsTheFacesRelativeModes) {
  // MS3: K_c annihilates the common motion of the faces, so the added K_c/ω_c² changes neither the
  // plate's mass (1ᵀ M_s 1 over every sub-laminate's w) nor any motion that moves the faces together;
  // K_c φ = λ M_s φ has λ < ω_c² = (ω_t/2)².
  const SelectiveStack s = selective_stack();
  ASSERT_NE(s.model->interface_stiffness(), nullptr);
  ASSERT_TRUE(s.scaled.blocks);
  const std::vector<EquationPlace> places = s.model->places();
  Eigen::VectorXd w = Eigen::VectorXd::Zero(s.model->size());
  for (std::size_t i = 0; i < places.size(); ++i)
    if (places[i].dof == 2) w[static_cast<Eigen::Index>(i)] = 1.0; // every w: the stack moves as one
  const SparseMatrix M = s.scaled.matrix();
  const double plate_mass = w.dot(s.unscaled.mass.cwiseProduct(w));
  EXPECT_NEAR(w.dot(M * w), plate_mass, 1e-12 * plate_mass);
  EXPECT_LT((s.scaled.coupling * w).norm(), 1e-9 * (s.scaled.coupling.diagonal().cwiseProduct(w)).norm());
  const double omega_c = interface_frequency_ratio * s.scaled.report.target_omega;
  const double interfaces = highest_mode(*s.model->interface_stiffness(), *s.scaled.blocks).omega;
  std::printf("[ measured ] interfaces' highest mode %.6g rad/s on the scaled mass, omega_c %.6g rad/s; "
              "interface mass factor %.4g\n",
              interfaces, omega_c, s.scaled.report.interface_factor);
  EXPECT_LT(interfaces, omega_c);
  EXPECT_EQ(sum(s.scaled.report.added_mass_kg), 0.0);
}

TEST(MassScaling, TheAddedKineticEnergyOfSelectiveScalingIsHalfVTransposeDeltaMVOnAnyThreadCount) {
  // ½ Σ Δm_i v_i² + ½ vᵀ (K_c/ω_c²) v of the stack: the value of the direct formula to round-off (the sums
  // are made in 2 × 64 fixed chunks), and the same bits on 1, 2 and 4 threads.
  const SelectiveStack s = selective_stack();
  ASSERT_GT(s.scaled.coupling.nonZeros(), 0);
  std::srand(5);
  const Eigen::VectorXd v = Eigen::VectorXd::Random(s.model->size());
  double direct = v.dot(s.scaled.coupling * v);
  for (std::size_t k = 0; k < s.scaled.equations.size(); ++k)
    direct += s.scaled.added[k] * v[s.scaled.equations[k]] * v[s.scaled.equations[k]];
  direct *= 0.5;
  double one = 0.0;
  {
    const ElementThreads setting(1);
    one = s.scaled.added_kinetic_energy(v);
  }
  EXPECT_GT(one, 0.0);
  EXPECT_NEAR(one, direct, 1e-12 * std::abs(direct));
  for (const int threads : {2, 4}) {
    const ElementThreads setting(threads);
    EXPECT_EQ(s.scaled.added_kinetic_energy(v), one) << threads << " threads";
  }
}

TEST(MassScaling, TheHighestFrequencyOnABlockMassIsTheDenseGeneralisedEigenvalue) {
  // Lanczos on M^-½ K M^-½ (block M) against Eigen's dense generalised solver of K φ = ω² M φ on a chain
  // of 12 springs whose masses are coupled in pairs: the same ω_max to the Lanczos tolerance.
  const int n = 12;
  std::vector<Eigen::Triplet<double>> k, m;
  for (int i = 0; i < n; ++i) {
    k.emplace_back(i, i, 2.0e6 * (1.0 + 0.05 * i));
    if (i > 0) {
      k.emplace_back(i, i - 1, -1.0e6);
      k.emplace_back(i - 1, i, -1.0e6);
    }
    m.emplace_back(i, i, 1.0 + 0.2 * (i % 3));
  }
  for (int i = 0; i + 6 < n; i += 2) { // pairs (i, i + 6): an interface's coupling pattern
    m.emplace_back(i, i, 0.5);
    m.emplace_back(i + 6, i + 6, 0.5);
    m.emplace_back(i, i + 6, -0.5);
    m.emplace_back(i + 6, i, -0.5);
  }
  SparseMatrix K(n, n), M(n, n);
  K.setFromTriplets(k.begin(), k.end());
  M.setFromTriplets(m.begin(), m.end());
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense{Eigen::MatrixXd(K),
                                                                        Eigen::MatrixXd(M)};
  const double exact = std::sqrt(dense.eigenvalues().maxCoeff());
  const double lanczos = highest_mode(K, BlockDiagonalMass(M)).omega;
  EXPECT_GE(lanczos, exact * (1.0 - 1e-12));
  EXPECT_LE(lanczos, exact * (1.0 + highest_frequency_tolerance));
}

TEST(MassScaling, SelectiveScalingLengthensTheStacksStepTenfoldAndKeepsItsAnswer) {
  // The stacked example (two interfaces, 5 × 5) whose interfaces never break: the faces' penalty and the
  // thin sub-laminates' rotations set the unscaled step (9.9 ns); selectively scaled, the plates' in-plane
  // and bending modes do (117 ns measured). The contact force of the scaled run is the unscaled one's
  // (measured: 798.09 against 798.28 N, 2.4e-4), and both close their energy balance.
  const ImpactCase plain(impact_case_description(parse_deck(stacked_explicit("", true), "s.toml")));
  const ImpactCase scaled(
      impact_case_description(parse_deck(stacked_explicit("mass_scaling = \"selective\"", true), "s.toml")));
  EXPECT_GT(scaled.settings().dt, 10.0 * plain.settings().dt);
  const ImpactResult a = plain.run();
  const ImpactResult b = scaled.run();
  const double e0 = 0.5 * scaled.settings().impactor.mass * std::pow(scaled.settings().impactor.velocity, 2);
  std::printf(
      "[ measured ] selective, unbreakable: step %.4g against %.4g s, %ld against %ld steps; peak force "
      "%.6g against %.6g N; balance %.3g and %.3g; added kinetic energy %.3g of the impact's\n",
      scaled.settings().dt, plain.settings().dt, b.steps, a.steps, b.peak_force, a.peak_force,
      b.energy_balance_error, a.energy_balance_error, *b.added_mass_kinetic_energy / e0);
  EXPECT_NEAR(b.peak_force, a.peak_force, 1e-3 * a.peak_force);
  EXPECT_LT(b.energy_balance_error, 1e-5);
  EXPECT_LT(*b.added_mass_kinetic_energy, 1e-4 * e0);
}

TEST(MassScaling, SelectiveScalingOfInterfacesThatDelaminateKeepsTheIssuesTolerances) {
  // The same stack with its interfaces' own law (they soften and crack under the impactor): the scaled
  // run's peak force within 2 %, the interfaces' dissipation and the delaminated area within 5 % of the
  // unscaled run's (issue 50's tolerances; measured +0.85 %, +1.4 %, equal), energy balance below 1e-5.
  const ImpactResult a = test::run_deck(stacked_explicit("", false));
  const ImpactResult b = test::run_deck(stacked_explicit("mass_scaling = \"selective\"", false));
  ASSERT_TRUE(a.delamination && b.delamination);
  const double area_a = a.delamination->projected_area, area_b = b.delamination->projected_area;
  std::printf("[ measured ] selective, delaminating: peak force %.6g against %.6g N; interface dissipation "
              "%.5g against %.5g J; area %.4g against %.4g mm^2; balance %.3g\n",
              b.peak_force, a.peak_force, b.delamination->dissipated, a.delamination->dissipated,
              1e6 * area_b, 1e6 * area_a, b.energy_balance_error);
  ASSERT_GT(area_a, 0.0);
  EXPECT_NEAR(b.peak_force, a.peak_force, 0.02 * a.peak_force);
  EXPECT_NEAR(b.delamination->dissipated, a.delamination->dissipated, 0.05 * a.delamination->dissipated);
  EXPECT_NEAR(area_b, area_a, 0.05 * area_a);
  EXPECT_LT(b.energy_balance_error, 1e-5);
}

TEST(MassScaling, SelectiveScalingOfAPlateWithoutInterfacesIsRefused) {
  try {
    (void)parse_deck(thesis_3_6_explicit("mass_scaling = \"selective\""), "ms.toml");
    ADD_FAILURE() << "a single plate was scaled selectively";
  } catch (const DeckError& e) {
    EXPECT_NE(std::string(e.what()).find("has no [delamination]: use \"rotary\""), std::string::npos)
        << e.what();
  }
}

TEST(MassScaling, ImplicitStepsRefuseIt) {
  ImpactCaseDescription d = impact_case_description(parse_deck(thesis_3_6_explicit(""), "ms.toml"));
  d.time.integration = TimeScheme::newmark;
  d.time.mass_scaling.kind = MassScalingKind::rotary;
  EXPECT_THROW({ const ImpactCase c(d); }, std::invalid_argument);
}

// Issue 77: nodal scaling with target_dt = 1e-6 s added 19.7 kg to a 0.2 g plate and quadrupled the peak
// force, silently. Above 5 % of the plate's mass the run is suspect, with the added mass, the plate's and
// the fall of the frequency of a mode that moves the mass together, sqrt(m / (m + dm)).
TEST(MassScaling, AddedMassAboveFivePercentOfThePlateMakesTheRunSuspect) {
  MassScalingReport r;
  r.kind = MassScalingKind::nodal;
  r.mass_kg = {2e-4};
  r.added_mass_kg = {19.7};
  const auto why = added_mass_suspicion(r);
  ASSERT_TRUE(why.has_value());
  EXPECT_NE(why->find("added 19.7 kg to a plate of 0.0002 kg"), std::string::npos) << *why;
  EXPECT_NE(why->find(fmt::format("{:.3g}", std::sqrt(2e-4 / (2e-4 + 19.7)))), std::string::npos) << *why;
  r.added_mass_kg = {0.049 * 2e-4}; // 4.9 %: within the bound
  EXPECT_FALSE(added_mass_suspicion(r).has_value());
  r.added_mass_kg = {0.051 * 2e-4};
  EXPECT_TRUE(added_mass_suspicion(r).has_value());
  r.mass_kg = {1e-4, 1e-4}; // a stack: the plate's mass is the sum of its sub-laminates'
  r.added_mass_kg = {0.0, 0.09 * 2e-4};
  EXPECT_TRUE(added_mass_suspicion(r).has_value());
  r.added_mass_kg = {0.0, 0.0}; // rotary scaling adds no translational mass
  EXPECT_FALSE(added_mass_suspicion(r).has_value());
}

} // namespace
} // namespace plyimpact::mass_scaling_tests
