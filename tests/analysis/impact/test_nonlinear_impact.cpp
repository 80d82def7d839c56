// Large-deflection impact (SPEC §8): the linear limit at low velocity, the membrane-stiffening trend
// of Chen & Sun (1985) on a thin plate at high velocity, and the discrete energy balance.
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/deck/deck.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace plyimpact::nonlinear_impact_tests {
namespace {

/// The §3.6 material, 127 × 76.2 mm, hard simple support, 8×6 q9 mesh, steel sphere R = 12.7 mm,
/// k = 0.6e9; layup, ply thickness, impactor mass and velocity vary.
std::string deck(const std::string& layup, double ply, double mass, double velocity,
                 const std::string& unloading = "tan-sun", const std::string& end = "\"auto\"",
                 double dt = 1.0e-6) {
  return "[materials.m]\nE1 = 129.0e9\nE2 = 7.5e9\nG12 = 3.5e9\nnu12 = 0.33\nrho = 1540.0\n"
         "[laminate]\nmaterial = \"m\"\nlayup = \"" +
         layup + "\"\nply_thickness = " + std::to_string(ply) +
         "\n[plate]\na = 0.127\nb = 0.0762\n[mesh]\nnx = 8\nny = 6\nelement = \"q9\"\n"
         "[boundary]\nx0 = \"ss\"\nxa = \"ss\"\ny0 = \"ss\"\nyb = \"ss\"\n"
         "[impactor]\nradius = 12.7e-3\nE = 207e9\nnu = 0.3\nmass = " +
         std::to_string(mass) + "\nvelocity = " + std::to_string(velocity) +
         "\n[contact]\nk = 0.6e9\nunloading = \"" + unloading + "\"\n[time]\ndt = " + std::to_string(dt) +
         "\nend = " + end + "\n";
}

struct Pair {
  ImpactResult linear;
  ImpactResult nonlinear;
};

/// The deck's case with the linear plate, or with the non-linear one of strain measure `measure`.
ImpactResult run(const std::string& text, std::optional<StrainMeasure> measure) {
  ImpactCaseDescription d = impact_case_description(parse_deck(text, "test.toml"));
  if (measure) d.nonlinear = NonlinearImpactSettings{.measure = *measure};
  return ImpactCase(d).run();
}

Pair run_both(const std::string& text) {
  return {run(text, std::nullopt), run(text, StrainMeasure::von_karman)};
}

TEST(NonlinearImpact, LowVelocityEqualsTheLinearRun) {
  // §3.6 plate (h = 4.65 mm), 0.314 kg at 0.3 m/s: the peak deflection is a few % of h, so the
  // membrane forces are negligible.
  const Pair p = run_both(deck("[45/90/-45/0]3s", 0.19375e-3, 0.314, 0.3));
  ASSERT_TRUE(p.nonlinear.complete);
  EXPECT_LT(p.linear.peak_contact_deflection / 4.65e-3, 0.1);
  EXPECT_NEAR(p.nonlinear.peak_force, p.linear.peak_force, 0.005 * p.linear.peak_force);
  EXPECT_NEAR(p.nonlinear.peak_contact_deflection, p.linear.peak_contact_deflection,
              0.005 * p.linear.peak_contact_deflection);
  EXPECT_NEAR(p.nonlinear.contact_duration, p.linear.contact_duration, 0.005 * p.linear.contact_duration);
  std::printf(
      "0.3 m/s: peak force %.3f N (linear %.3f N, %+.4f %%), peak deflection %.5f mm (linear %.5f mm), "
      "%.2f Newton iterations/step\n",
      p.nonlinear.peak_force, p.linear.peak_force,
      100.0 * (p.nonlinear.peak_force / p.linear.peak_force - 1.0), p.nonlinear.peak_contact_deflection * 1e3,
      p.linear.peak_contact_deflection * 1e3,
      static_cast<double>(p.nonlinear.newton->iterations) / static_cast<double>(p.nonlinear.steps));
}

TEST(NonlinearImpact, ThinPlateAtHighVelocityStiffensChenSunTrend) {
  // Thin cross-ply plate h = 1 mm, 0.314 kg at 3 m/s: the linear peak deflection is several
  // thicknesses, where membrane stretching stiffens the plate (Chen & Sun 1985): the non-linear run
  // has a higher peak force and a smaller peak deflection (Δt = 2 µs).
  // A light, brief first touch is followed by the main contact, in which the peaks occur.
  const std::string text = deck("[0/90/0/90]s", 0.125e-3, 0.314, 3.0, "tan-sun", "\"auto\"", 2.0e-6);
  const Pair p = run_both(text);
  const ImpactResult& nl = p.nonlinear;
  ASSERT_TRUE(nl.complete);
  EXPECT_GT(p.linear.peak_contact_deflection / 1e-3, 2.0);
  EXPECT_GT(nl.peak_force, 1.5 * p.linear.peak_force);
  EXPECT_LT(nl.peak_contact_deflection, 0.8 * p.linear.peak_contact_deflection);
  std::printf(
      "thin plate 3 m/s: peak force %.1f N (linear %.1f N), peak deflection %.4f mm (linear %.4f mm), "
      "main contact %.0f us (linear %.0f us), %.2f Newton iterations/step (max %d), %d factorizations\n",
      nl.peak_force, p.linear.peak_force, nl.peak_contact_deflection * 1e3,
      p.linear.peak_contact_deflection * 1e3, (nl.episodes.back().end - nl.episodes.back().start) * 1e6,
      (p.linear.episodes.back().end - p.linear.episodes.back().start) * 1e6,
      static_cast<double>(nl.newton->iterations) / static_cast<double>(nl.steps),
      nl.newton->max_iterations_per_step, nl.newton->factorizations);

  // The Green–Lagrange measure adds terms of the order of the in-plane gradients and of rotation
  // products, small next to w,x² here: the two measures agree to 2 % in peak force and deflection.
  const ImpactResult gl = run(text, StrainMeasure::green_lagrange);
  EXPECT_NEAR(gl.peak_force, nl.peak_force, 0.02 * nl.peak_force);
  EXPECT_NEAR(gl.peak_contact_deflection, nl.peak_contact_deflection, 0.02 * nl.peak_contact_deflection);
  std::printf("Green-Lagrange: peak force %.1f N, peak deflection %.4f mm\n", gl.peak_force,
              gl.peak_contact_deflection * 1e3);
}

TEST(NonlinearImpact, ElasticContactConservesTotalEnergy) {
  // Average-acceleration Newmark with the trapezoidal work of the internal forces balances energy
  // exactly in the discrete sense: impactor + plate kinetic + plate strain + Hertz potential
  // (2/5) k α^2.5 stays at ½ m v0² up to the Newton tolerance and the contact-force kink.
  const ImpactResult r =
      run(deck("[0/90/0/90]s", 0.125e-3, 0.314, 3.0, "elastic", "1.0e-3"), StrainMeasure::von_karman);
  const double e0 = 0.5 * 0.314 * 9.0, k = 0.6e9;
  double worst = 0.0;
  for (const auto& h : r.history) {
    const double potential = h.indentation > 0 ? 0.4 * k * std::pow(h.indentation, 2.5) : 0.0;
    worst = std::max(worst, std::abs(h.impactor_energy + h.plate_kinetic + h.plate_strain + potential - e0));
  }
  EXPECT_LT(worst, 1e-3 * e0);
}

} // namespace
} // namespace plyimpact::nonlinear_impact_tests
