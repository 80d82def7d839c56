// Impact solver (SPEC §4): closed-form rigid-target limit, energy balance, time-step convergence,
// mesh convergence of the §3.6 case and the parametric trends of thesis §4.2.
#include "support/impact_decks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace plyimpact::impact_tests {
namespace {

using test::run_deck;
using test::thesis_3_6_deck;

TEST(Impact, ElasticContactConservesTotalEnergy) {
  // β = 1/4, γ = 1/2: impactor + plate kinetic + plate strain + Hertz potential (2/5) k α^2.5 stays at
  // ½ m v0² (the potential is the exact one, not the integrated contact work). With the point load: the
  // Hertz pressure works on the mean deflection under it while the law sees the centre value, which
  // is not conservative (docs/notes/contact-reference.md §1).
  const ImpactResult r = run_deck(thesis_3_6_deck("mass = 0.314\nvelocity = 2.92", R"(
[contact]
k = 0.6e9
unloading = "elastic"
load = "point"
[time]
dt = 0.25e-6
end = 1.0e-3
)",
                                                  "8, 6"));
  const double e0 = 0.5 * 0.314 * 2.92 * 2.92, k = 0.6e9;
  double worst = 0.0;
  for (const auto& h : r.history) {
    const double potential = h.indentation > 0 ? 0.4 * k * std::pow(h.indentation, 2.5) : 0.0;
    const double total = h.impactor_energy + h.plate_kinetic + h.plate_strain + potential;
    worst = std::max(worst, std::abs(total / e0 - 1.0));
  }
  std::printf("  elastic contact: worst relative energy error %.2e over %zu steps\n", worst,
              r.history.size());
  EXPECT_LT(worst, 1e-3);
  EXPECT_GT(r.peak_force, 0.0);
}

TEST(Impact, TanSunAbsorbedEnergyIsTheForceIndentationLoopPlusPlateVibration) {
  const ImpactResult r = run_deck(thesis_3_6_deck("mass = 0.314\nvelocity = 2.92", R"(
[contact]
k = 0.6e9
alpha_cr = 1.7e-5
load = "point"
[time]
dt = 0.25e-6
)",
                                                  "8, 6"));
  // Loop area ∮F dα from the history (trapezoids), independent of the solver's own bookkeeping.
  double loop = 0.0;
  for (std::size_t i = 1; i < r.history.size(); ++i)
    loop += 0.5 * (r.history[i].force + r.history[i - 1].force) *
            (r.history[i].indentation - r.history[i - 1].indentation);
  const auto& last = r.history.back();
  const double plate_energy = last.plate_kinetic + last.plate_strain;
  std::printf("  tan-sun: absorbed %.6f J = loop %.6f J + plate %.6f J; permanent indentation %.3e m\n",
              r.absorbed_energy.value(), loop, plate_energy, r.permanent_indentation);
  EXPECT_GT(loop, 0.0);
  EXPECT_GT(r.permanent_indentation, 0.0);
  EXPECT_NEAR(r.absorbed_energy.value(), loop + plate_energy, 1e-6 * r.absorbed_energy.value());
  EXPECT_NEAR(loop, r.contact_dissipation, 1e-9 * loop);
}

std::string rigid_target_deck(double dt) {
  char time[64];
  std::snprintf(time, sizeof time, "dt = %.17g\n", dt);
  return test::rigid_target_deck(time);
}

TEST(Impact, RigidTargetReproducesTheHertzClosedForm) {
  // Elastic Hertz impact on a rigid half-space: F_max = k^(2/5) (5 m v0²/4)^(3/5),
  // contact time T = 3.21807 (m²/(k² v0))^(1/5), rebound speed = v0.
  const double m = 0.314, v0 = 2.92, k = 0.6e9;
  const ImpactResult rigid = run_deck(rigid_target_deck(0.05e-6));
  const double F_max = std::pow(k, 0.4) * std::pow(1.25 * m * v0 * v0, 0.6);
  const double T = 3.21807 * std::pow(m * m / (k * k * v0), 0.2);
  std::printf("  rigid target: F_max %.4f N (closed form %.4f), T %.4f us (%.4f), rebound %.6f m/s\n",
              rigid.peak_force, F_max, rigid.contact_duration * 1e6, T * 1e6, rigid.rebound_velocity.value());
  EXPECT_NEAR(rigid.peak_force / F_max, 1.0, 1e-3);
  EXPECT_NEAR(rigid.rebound_velocity.value() / v0, 1.0, 1e-3);
  EXPECT_NEAR(rigid.contact_duration / T, 1.0, 5e-3);
  EXPECT_NEAR(rigid.contact_duration, 2.94328 * rigid.max_indentation / v0, 5e-3 * T);
  EXPECT_TRUE(rigid.complete);
}

TEST(Impact, PeakForceConvergesAtSecondOrderInTheTimeStep) {
  // Rigid target: error of the peak force against the closed form at Δt = 8, 4, 2 µs (contact 504 µs).
  const double F_max = std::pow(0.6e9, 0.4) * std::pow(1.25 * 0.314 * 2.92 * 2.92, 0.6);
  std::vector<double> errors;
  for (const double dt : {8e-6, 4e-6, 2e-6})
    errors.push_back(std::abs(run_deck(rigid_target_deck(dt)).peak_force - F_max));
  const double order_rigid = std::log2(errors[1] / errors[2]);
  std::printf("  rigid target: peak force error %.3e / %.3e / %.3e N at dt = 8, 4, 2 us: order %.2f, %.2f\n",
              errors[0], errors[1], errors[2], std::log2(errors[0] / errors[1]), order_rigid);
  EXPECT_NEAR(order_rigid, 2.0, 0.3);
  // Plate (§4.2 impactor on a 6×4 mesh): Richardson estimate of the order from three step sizes,
  // on the impactor displacement at 300 µs (the peak of a sampled force history also carries the
  // unresolved plate modes, so it is printed but the smooth functional is asserted).
  std::vector<double> w, peaks;
  for (const double dt : {1e-6, 0.5e-6, 0.25e-6}) {
    char time[64];
    std::snprintf(time, sizeof time, "[time]\ndt = %.17g\nend = 3.0e-4\n", dt);
    const ImpactResult r = run_deck(
        thesis_3_6_deck("mass = 0.314\nvelocity = 2.92",
                        std::string("[contact]\nk = 0.6e9\nunloading = \"elastic\"\n") + time, "6, 4"));
    w.push_back(r.history.back().impactor_w);
    peaks.push_back(r.peak_force);
  }
  const double order_plate = std::log2((w[0] - w[1]) / (w[1] - w[2]));
  std::printf(
      "  plate: impactor w(300 us) %.9e / %.9e / %.9e m: order %.2f; peak force %.2f / %.2f / %.2f N\n", w[0],
      w[1], w[2], order_plate, peaks[0], peaks[1], peaks[2]);
  EXPECT_NEAR(order_plate, 2.0, 0.3);
}

TEST(Impact, Section36PeakForceAgreesBetween15x11And30x22Meshes) {
  // With the contact force spread as a Hertz pressure over the contact circle a = √(R α) the peak
  // force is mesh-converged; a point load on a Mindlin plate is not (w is log-singular under it, and
  // the 15×11 impact point is a centre node while the 30×22 one is a corner node): printed, not
  // asserted (docs/validation.md).
  const std::string impactor = "mass = 6.14\nvelocity = 2.68";
  const auto run = [&](const std::string& mesh, const std::string& load) {
    return run_deck(thesis_3_6_deck(
        impactor, "[contact]\nk = 0.6e9\nload = \"" + load + "\"\n[time]\ndt = 1.0e-6\nend = 2.6e-3\n",
        mesh)); // the peak comes at about 2.05 ms
  };
  const ImpactResult coarse = run("15, 11", "hertz-pressure");
  const ImpactResult fine = run("30, 22", "hertz-pressure");
  const ImpactResult coarse_point = run("15, 11", "point");
  const ImpactResult fine_point = run("30, 22", "point");
  std::printf("  §3.6 at 2.68 m/s, Hertz pressure: peak force 15x11 %.1f N at %.0f us, 30x22 %.1f N at %.0f "
              "us (%+.3f %%)\n",
              coarse.peak_force, coarse.time_of_peak_force * 1e6, fine.peak_force,
              fine.time_of_peak_force * 1e6, 100 * (coarse.peak_force / fine.peak_force - 1));
  std::printf("  §3.6 at 2.68 m/s, point load:     peak force 15x11 %.1f N, 30x22 %.1f N (%+.2f %%)\n",
              coarse_point.peak_force, fine_point.peak_force,
              100 * (coarse_point.peak_force / fine_point.peak_force - 1));
  EXPECT_NEAR(coarse.peak_force / fine.peak_force, 1.0, 0.01);
}

double peak(const std::string& impactor, const std::string& edge = "ss") {
  return run_deck(thesis_3_6_deck(impactor, "[contact]\nk = \"auto\"\n[time]\ndt = 0.5e-6\n", "10, 8", edge))
      .peak_force;
}

TEST(Impact, ThesisTrendsPeakForceRisesWithVelocityMassAndRadius) {
  const double base = peak("mass = 0.314\nvelocity = 2.0");
  const double faster = peak("mass = 0.314\nvelocity = 2.92");
  const double heavier = peak("mass = 0.628\nvelocity = 2.0");
  const std::string big = "mass = 0.314\nvelocity = 2.0";
  const ImpactResult larger = run_deck(
      thesis_3_6_deck(big, "[contact]\nk = \"auto\"\n[time]\ndt = 0.5e-6\n", "10, 8")
          .replace(thesis_3_6_deck(big, "", "10, 8").find("radius = 12.7e-3"), 16, "radius = 25.4e-3"));
  std::printf("  peak force: base %.1f N, v x1.46 %.1f N, m x2 %.1f N, R x2 %.1f N\n", base, faster, heavier,
              larger.peak_force);
  EXPECT_GT(faster, base);
  EXPECT_GT(heavier, base);
  EXPECT_GT(larger.peak_force, base);
}

TEST(Impact, ThesisTrendsContactDurationRisesWithMass) {
  const auto duration = [](const std::string& m) {
    return run_deck(thesis_3_6_deck("mass = " + m + "\nvelocity = 2.0",
                                    "[contact]\nk = 0.6e9\n[time]\ndt = 0.5e-6\n", "10, 8"))
        .contact_duration;
  };
  const double light = duration("0.157"), medium = duration("0.314"), heavy = duration("0.628");
  std::printf("  contact duration: m = 0.157 kg %.1f us, 0.314 kg %.1f us, 0.628 kg %.1f us\n", light * 1e6,
              medium * 1e6, heavy * 1e6);
  EXPECT_LT(light, medium);
  EXPECT_LT(medium, heavy);
}

TEST(Impact, SimplySupportedAndClampedDifferLittleForTheSection42Plate) {
  // The thesis's "simply supported" plate carries code 10101 on every edge (Annex 2): on the edges
  // y = 0, b that fixes θy, the rotation normal to the edge, so those edges are clamped in bending.
  // With that support, simply supported and clamped differ little, as thesis §4.2 finds. The hard
  // simple support of SPEC §3 ("ss") frees that rotation and gives a markedly softer plate.
  const double thesis_ss = peak("mass = 0.314\nvelocity = 2.92", "10101");
  const double clamped = peak("mass = 0.314\nvelocity = 2.92", "clamped");
  const double hard_ss = peak("mass = 0.314\nvelocity = 2.92", "ss");
  std::printf(
      "  §4.2 plate, 0.314 kg at 2.92 m/s: peak force thesis ss (10101) %.1f N, clamped %.1f N (%+.2f %%); "
      "hard ss %.1f N (%+.2f %%)\n",
      thesis_ss, clamped, 100 * (clamped / thesis_ss - 1), hard_ss, 100 * (clamped / hard_ss - 1));
  EXPECT_GT(clamped, thesis_ss); // stiffer support, higher force
  EXPECT_LT(clamped / thesis_ss - 1.0, 0.02);
  EXPECT_GT(thesis_ss, hard_ss);
}

TEST(Impact, EpisodesAndSummaryAreConsistent) {
  const ImpactResult r = run_deck(thesis_3_6_deck("mass = 0.314\nvelocity = 2.92",
                                                  "[contact]\nk = 0.6e9\n[time]\ndt = 0.5e-6\n", "8, 6"));
  ASSERT_GE(r.episodes.size(), 1U);
  EXPECT_TRUE(r.complete);
  EXPECT_DOUBLE_EQ(r.contact_duration, r.episodes.front().end - r.episodes.front().start);
  double highest = 0.0;
  for (const auto& e : r.episodes) {
    EXPECT_LT(e.start, e.end);
    highest = std::max(highest, e.peak_force);
  }
  EXPECT_DOUBLE_EQ(highest, r.peak_force);
  // The run ends only after the impactor has been free for max(first contact, 2 T1).
  const double free_time = r.history.back().t - r.episodes.back().end;
  EXPECT_GE(free_time + 1e-12, std::max(r.contact_duration, 2 * r.fundamental_period.value()));
  EXPECT_GT(r.rebound_velocity.value(), 0.0);
}

} // namespace
} // namespace plyimpact::impact_tests
