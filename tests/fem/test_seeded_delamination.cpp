// A seeded delamination (StackSettings::seed_radius, [delamination] seed_radius): a mid-plane
// delamination of radius a at the centre of a clamped circular plate under a central load adds
// ΔC = 3a²/(16πD) to the compliance of the centre, exactly in Kirchhoff theory
// (docs/delamination_threshold.md, (4)); hence G = 3P²/(32π²D) whatever a. Here the stacked plate
// (two Mindlin sub-laminates, cohesive interface, the seed's points at d = 1 held, their faces in
// contact through the penalty) on the circular rig's mesh, solved statically.
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/fem/spd_solver.hpp"
#include "plyimpact/fem/stacked_model.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/deck/deck.hpp"
#include "support/seeded_plate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace plyimpact::seeded_delamination_tests {
namespace {

constexpr double E = test::seeded_plate_E, nu = test::seeded_plate_nu, h = 2e-3, R = 0.05; // 8 plies
constexpr double P = 100.0; // [N]: w ≈ 0.1 h, linear

struct CentreResponse {
  double compliance = 0.0; ///< w of the top sub-laminate's centre node / P [m/N]
  double seed_area = 0.0;  ///< area of the interface points at d = 1 [m²]
};

CentreResponse centre_response(double seed_radius) {
  const ImpactCaseDescription d =
      impact_case_description(test::seeded_plate_deck({.seed_radius = seed_radius}));
  const DiscretePlate model = impact_plate_model(d); // the case's plate, without its time stepping
  const StackedPlate stack = impact_stack(model, *d.delamination);
  const StackedPlateState state = stack.initial_state();
  int centre = 0;
  for (int n = 0; n < model.mesh().node_count(); ++n)
    if (model.mesh().node(n).norm() < model.mesh().node(centre).norm()) centre = n;
  const int eq = stack.offset(0) + stack.sublaminate(0).dofs().equation(centre, 2);
  const int eq_bottom = stack.offset(1) + stack.sublaminate(1).dofs().equation(centre, 2);
  // Under P on the top the equal halves keep w equal, so their contact carries P/2 at the centre alone
  // (D/8 ∇⁴w = P δ − p on the top, = p below): the same as P/2 on each, with the faces just touching.
  Eigen::VectorXd F = Eigen::VectorXd::Zero(stack.size());
  F(eq) = 0.5 * P;
  F(eq_bottom) = 0.5 * P;
  // Newton with the damage held (the penalty acts only where faces press together).
  Eigen::VectorXd u = Eigen::VectorXd::Zero(stack.size());
  SpdSolver solver(SparseSolverKind::cholmod);
  for (int it = 0; it < 30; ++it) {
    const StackedPlateEvaluation ev = stack.evaluate(u, state, CohesiveDamage::held);
    const Eigen::VectorXd r = F - ev.force;
    if (r.norm() <= 1e-9 * P) break;
    solver.factorize(ev.tangent);
    u += solver.solve(r);
  }
  EXPECT_LE((F - stack.evaluate(u, state, CohesiveDamage::held).force).norm(), 1e-9 * P);
  return {u(eq) / P, stack.interface(0).damaged_area(state.interfaces[0], 1.0)};
}

TEST(SeededDelamination, AddsTheRigidEdgeComplianceAndReleasesTheEnergyOfTheClosedForm) {
  const double D = E * h * h * h / (12.0 * (1.0 - nu * nu));
  const double per_a2 = 3.0 / (16.0 * std::numbers::pi * D); // ΔC / a², (4) with n = 1
  const CentreResponse intact = centre_response(0.0);
  EXPECT_EQ(intact.seed_area, 0.0);
  std::printf("  intact: C = %.5g m/N (Kirchhoff R²/16πD = %.5g; the rest is shear)\n", intact.compliance,
              R * R / (16.0 * std::numbers::pi * D));
  std::vector<CentreResponse> seeded;
  std::vector<double> tip;
  for (const double a : {0.01, 0.015, 0.02}) {
    const CentreResponse s = seeded.emplace_back(centre_response(a));
    // The seed is the union of the interface points' cells within a: its radius is the area's.
    const double a_seed = std::sqrt(s.seed_area / std::numbers::pi);
    EXPECT_NEAR(a_seed, a, 0.05 * a);
    const double added = s.compliance - intact.compliance;
    // The stacked Mindlin plate is a little softer at the front than Kirchhoff's tied front (the
    // sub-plates' shear and the interface's penalty let the tie act over a zone of the order of the
    // thickness): ΔC = per_a2 (a + Δ)², with the same Δ for every seed.
    tip.push_back(std::sqrt(added / per_a2) - a_seed);
    std::printf(
        "  a = %.1f mm (seed area's %.2f mm): ΔC = %.5g m/N, 3a²/16πD = %.5g (%+.2f %%), Δ = %.3f mm\n",
        a * 1e3, a_seed * 1e3, added, per_a2 * a_seed * a_seed,
        100.0 * (added / (per_a2 * a_seed * a_seed) - 1.0), tip.back() * 1e3);
    EXPECT_GT(tip.back(), 0.0);
    EXPECT_LT(tip.back(), 0.5 * h);
  }
  EXPECT_LT(*std::max_element(tip.begin(), tip.end()) - *std::min_element(tip.begin(), tip.end()), 0.05 * h);
  // G = (P²/2) ΔC/ΔA between consecutive seeds: 3P²/(32π²D) (5), up by 2Δ/(a₁ + a₂) (2–4 % here).
  const double G = 3.0 * P * P / (32.0 * std::numbers::pi * std::numbers::pi * D);
  for (std::size_t i = 0; i + 1 < seeded.size(); ++i) {
    const double released = 0.5 * P * P * (seeded[i + 1].compliance - seeded[i].compliance) /
                            (seeded[i + 1].seed_area - seeded[i].seed_area);
    std::printf("  G between seeds %zu and %zu: %.4g J/m² against 3P²/32π²D = %.4g J/m² (%+.2f %%)\n", i,
                i + 1, released, G, 100.0 * (released / G - 1.0));
    EXPECT_GT(released / G, 1.0);
    EXPECT_LT(released / G, 1.05);
  }
}

} // namespace
} // namespace plyimpact::seeded_delamination_tests
