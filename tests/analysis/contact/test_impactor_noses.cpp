// Impactor noses other than the hemisphere (parameters.hpp NoseShape, docs/impactor.md): the
// flat-ended cylinder (F = k α, k = 2 R E*) and the cone (F = k α², k = (2/π) tan θ E*).
//   - On a rigid target the impactor is an oscillator with the law's potential: for n = 1 the harmonic
//     one (F_max = v0 √(m k), contact time π √(m/k)); for n = 2 α_m = (3 m v0²/(2k))^(1/3),
//     F_max = k α_m² and the contact lasts 2 (α_m/v0) ∫₀¹ dx/√(1 − x³), integrated here by quadrature.
//   - The contact constants from the deck's moduli, by hand.
//   - Their pressure profiles carry the whole force (the flat punch's 1/√ edge and the cone's
//     logarithmic tip are integrable).
//   - Deck slips are refused with the key named.
#include "plyimpact/analysis/contact/contact_rules.hpp"
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/fem/circle_load.hpp"
#include "plyimpact/fem/shape_functions.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/deck/deck.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace plyimpact::impactor_noses_tests {
namespace {

constexpr double m = 0.314, v0 = 2.92;

/// The thesis's graphite/epoxy as a rigid target (or a plate), struck by `impactor`, with `contact`.
std::string deck(const std::string& impactor, const std::string& contact, bool rigid = true) {
  return std::string(R"(
[materials.m]
E1 = 129.0e9
E2 = 7.5e9
G12 = 3.5e9
nu12 = 0.33
rho = 1540.0
[laminate]
material = "m"
layup = "[45/90/-45/0]3s"
ply_thickness = 0.19375e-3
[plate]
a = 0.127
b = 0.0762
rigid = )") +
         (rigid ? "true" : "false") + "\n[impactor]\nmass = 0.314\nE = 207e9\nvelocity = 2.92\n" + impactor +
         "\n" + contact;
}

ImpactResult run(const std::string& text) {
  return ImpactCase(impact_case_description(parse_deck(text, "noses.toml"))).run();
}

TEST(ImpactorNoses, AFlatEndOnARigidTargetIsAHarmonicOscillator) {
  const double k = 2.0e7; // N/m
  const ImpactResult r =
      run(deck("nose = \"flat\"\nradius = 5e-3", "[contact]\nk = 2.0e7\n[time]\ndt = 2e-7\n"));
  const double F_max = v0 * std::sqrt(m * k), T = std::numbers::pi * std::sqrt(m / k);
  std::printf("  flat: F_max %.4f N (closed form %.4f), T %.3f us (%.3f)\n", r.peak_force, F_max,
              r.contact_duration * 1e6, T * 1e6);
  EXPECT_NEAR(r.peak_force / F_max, 1.0, 1e-4);
  EXPECT_NEAR(r.contact_duration / T, 1.0, 1e-3);
  EXPECT_NEAR(r.rebound_velocity.value() / v0, 1.0, 1e-4) << "elastic unloading: no energy lost";
  EXPECT_EQ(r.permanent_indentation, 0.0);
}

TEST(ImpactorNoses, AConeOnARigidTargetFollowsItsQuadraticLaw) {
  const double k = 1.0e12; // N/m²
  const ImpactResult r =
      run(deck("nose = \"cone\"\nhalf_angle = 60", "[contact]\nk = 1.0e12\n[time]\ndt = 5e-8\n"));
  const double alpha_m = std::cbrt(3.0 * m * v0 * v0 / (2.0 * k));
  // ∫₀¹ dx/√(1 − x³) with x = 1 − s² (smooth integrand), composite Simpson.
  const int n = 2000;
  double integral = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double s = static_cast<double>(i) / n;
    const double x = 1.0 - s * s;
    const double g = s == 0.0 ? 2.0 / std::sqrt(3.0) : 2.0 * s / std::sqrt(1.0 - x * x * x);
    integral += g * (i == 0 || i == n ? 1.0 : (i % 2 ? 4.0 : 2.0));
  }
  integral /= 3.0 * n;
  const double F_max = k * alpha_m * alpha_m, T = 2.0 * alpha_m / v0 * integral;
  std::printf("  cone: F_max %.4f N (closed form %.4f), T %.3f us (%.3f), integral %.6f\n", r.peak_force,
              F_max, r.contact_duration * 1e6, T * 1e6, integral);
  EXPECT_NEAR(r.peak_force / F_max, 1.0, 1e-4);
  EXPECT_NEAR(r.contact_duration / T, 1.0, 1e-3);
  EXPECT_NEAR(r.max_indentation / alpha_m, 1.0, 1e-4);
}

TEST(ImpactorNoses, ContactConstantsAndRadiiFollowFromTheModuli) {
  const Deck flat = parse_deck(deck("nose = \"flat\"\nradius = 5e-3", ""), "noses.toml");
  const Deck cone = parse_deck(deck("nose = \"cone\"\nhalf_angle = 60", ""), "noses.toml");
  const double E_star = 1.0 / ((1.0 - 0.3 * 0.3) / 207e9 + 1.0 / 7.5e9); // ν of the impactor defaults to 0.3
  EXPECT_NEAR(automatic_contact_stiffness(*flat.impactor, *flat.laminate) / (2.0 * 5e-3 * E_star), 1.0,
              1e-14);
  EXPECT_NEAR(automatic_contact_stiffness(*cone.impactor, *cone.laminate) /
                  (2.0 / std::numbers::pi * std::tan(std::numbers::pi / 3.0) * E_star),
              1.0, 1e-14);
  EXPECT_EQ(contact_radius(*flat.impactor, 1e-5), 5e-3);
  EXPECT_EQ(contact_radius(*flat.impactor, 0.0), 5e-3) << "one load shape throughout";
  EXPECT_NEAR(contact_radius(*cone.impactor, 1e-4), 2.0 / std::numbers::pi * 1e-4 * std::sqrt(3.0), 1e-18);
  EXPECT_EQ(flat.contact.unloading, UnloadingLaw::elastic)
      << "Tan & Sun's unloading was measured with spheres";
}

TEST(ImpactorNoses, TheFlatPunchAndConePressuresCarryTheWholeForce) {
  // One square element of 10 mm around a circle of 2 mm radius.
  Q9NodeCoordinates X;
  for (int a = 0; a < 9; ++a) {
    const auto& n = q9_node_coordinates[static_cast<std::size_t>(a)];
    X.row(a) << 0.005 * (n[0] + 1.0), 0.005 * (n[1] + 1.0);
  }
  const Eigen::Vector2d centre(0.0051, 0.0048);
  const double flat = circle_load(X, flat_punch_pressure(centre, 0.002, 1.0)).sum();
  const double cone = circle_load(X, cone_pressure(centre, 0.002, 1.0)).sum();
  std::printf("  total force: flat punch %.12f, cone %.12f\n", flat, cone);
  EXPECT_NEAR(flat, 1.0, 1e-6);
  EXPECT_NEAR(cone, 1.0, 1e-4);
}

TEST(ImpactorNoses, OnAPlateTheEnergyBalanceClosesForEveryNose) {
  for (const std::string nose : {"nose = \"flat\"\nradius = 2e-3", "nose = \"cone\"\nhalf_angle = 70"}) {
    const ImpactResult r = run(deck(
        nose, "[mesh]\nnx = 12\nny = 8\n[boundary]\nx0 = \"ss\"\nxa = \"ss\"\ny0 = \"ss\"\nyb = \"ss\"\n",
        false));
    std::printf("  %s: peak force %.2f N, energy balance error %.3g %%\n",
                nose.substr(0, nose.find('\n')).c_str(), r.peak_force, 100.0 * r.energy_balance_error);
    EXPECT_TRUE(r.complete);
    // Elastic law, β = 1/4: the balance closes to round-off when the contact is work-conjugate (the flat
    // punch's indentation sampled with its pressure's weights); sampled at the centre it was 1e-4 here
    // and blew up on a finer mesh.
    EXPECT_LT(r.energy_balance_error, 1e-5);
    EXPECT_GT(r.peak_force, 0.0);
  }
}

/// The message of the DeckError that parsing `text` throws.
std::string error_of(const std::string& text) {
  try {
    (void)parse_deck(text, "noses.toml");
  } catch (const DeckError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ImpactorNoses, SlipsAreRefusedWithTheKeyNamed) {
  EXPECT_NE(
      error_of(deck("nose = \"cone\"\nhalf_angle = 60\nradius = 0.01", "")).find("a cone has no radius"),
      std::string::npos);
  EXPECT_NE(error_of(deck("nose = \"cone\"", "")).find("half_angle"), std::string::npos);
  EXPECT_NE(error_of(deck("nose = \"cone\"\nhalf_angle = 95", "")).find("below 90"), std::string::npos);
  EXPECT_NE(error_of(deck("nose = \"flat\"\nradius = 0.005\nhalf_angle = 30", ""))
                .find("belongs to nose = \"cone\""),
            std::string::npos);
  EXPECT_NE(error_of(deck("nose = \"flat\"\nradius = 0.005", "[contact]\nunloading = \"tan-sun\"\n"))
                .find("measured with hemispherical impactors"),
            std::string::npos);
  EXPECT_NE(error_of(deck("nose = \"flatt\"\nradius = 0.005", "")).find("did you mean \"flat\"?"),
            std::string::npos);
}

} // namespace
} // namespace plyimpact::impactor_noses_tests
