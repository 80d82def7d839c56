// Delamination specimens on the stacked plate under displacement control (issue 19), against the
// beam-theory closed forms of tests/support/beam_fracture (docs/delamination.md): the double
// cantilever beam (DCB, mode I) and the end-notched flexure (ENF, mode II).
#include "plyimpact/analysis/thresholds/delamination_path.hpp"
#include "plyimpact/fem/structured_mesh.hpp"
#include "support/as4_peek.hpp"
#include "support/beam_fracture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

namespace plyimpact::delamination_path_tests {
namespace {

namespace bf = test::beam_fracture;

using test::as4_peek;

using test::as4_peek_interface;

/// Element boundaries: `coarse` up to x0, `fine` from x0 to x1, `coarse` to L.
std::vector<double> strip_lines(double L, double x0, double x1, double coarse, double fine) {
  std::vector<double> x{0.0};
  const auto fill = [&](double to, double h) {
    const int n = static_cast<int>(std::ceil((to - x.back()) / h - 1e-9));
    const double from = x.back();
    for (int i = 1; i <= n; ++i)
      x.push_back(from + (to - from) * i / n);
  };
  fill(x0, coarse);
  fill(x1, fine);
  fill(L, coarse);
  return x;
}

/// Where the elements are `fine` long.
struct Refinement {
  double x0, x1, fine = 0.5e-3, coarse = 2.5e-3;
};
/// The interface strengths: N half the tabulated 80 MPa (see Specimen), S the tabulated 100 MPa.
struct Strengths {
  double N = 40e6, S = 100e6;
};

/// The two [0]1 arms of thickness h (AS4/PEEK) of a 5 mm wide strip, one element across, with elements
/// of `fine` length on [x0, x1] and `coarse` (2.5 mm) elsewhere, and an initial crack from x = 0 to a0; the
/// interface strengths N and S.
///
/// Two choices keep the cohesive zone resolved (docs/delamination.md, "The DCB"): the narrow strip
/// (beam theory is per unit width; on a 25 mm width with one element across, the mid-width node carries
/// 2/3 of the width and its failure snaps back: Newton stops at 6.2 mm DCB opening), and the normal
/// strength lowered to half the tabulated one (N = 40 MPa) so that the mode I zone in the slender arms
/// spans ~3 elements of 0.5 mm (Turon et al. 2007's remedy: the toughness, and so the propagation
/// branch, is unchanged). With the tabulated N = 80 MPa the DCB reaches the same branch on 0.25 mm elements
/// (measured 0.23 %, 63 s).
struct Specimen {
  static constexpr double h = 1.56e-3, b = 5e-3;
  double a0;
  Mesh mesh;
  Laminate laminate{{as4_peek()}, {{0.0, h, 0}, {0.0, h, 0}}};
  StackedPlate stack;

  Specimen(double length, double crack, Refinement r, const std::function<BoundaryConditions(int)>& bc_of,
           Strengths strengths = {})
      : a0(crack), mesh(structured_rectangle({length, b}, strip_lines(length, r.x0, r.x1, r.coarse, r.fine),
                                             std::vector<double>{0.0, b})),
        stack(mesh, laminate, StackSettings{{0}, as4_peek_interface(h, strengths.N, strengths.S)}, {},
              bc_of) {}

  [[nodiscard]] StackedPlateState precracked() const {
    StackedPlateState s = stack.virgin_state();
    stack.crack(s, 0, [&](const Eigen::Vector2d& xy) { return xy.x() < a0 - 1e-12; });
    return s;
  }
  /// The beam-theory arm with the plate's flexural modulus 12 D11/h³ (docs/delamination.md).
  [[nodiscard]] static bf::Specimen arm() {
    const Laminate one({as4_peek()}, {{0.0, h, 0}});
    return {b, h, 12.0 * one.D()(0, 0) / (h * h * h), 10.1e9, 5.5e9};
  }
  /// The nodes on the line x = const.
  [[nodiscard]] std::vector<int> nodes_at(double x) const {
    std::vector<int> nodes;
    for (int n = 0; n < mesh.node_count(); ++n)
      if (std::abs(mesh.node(n).x() - x) < 1e-9) nodes.push_back(n);
    return nodes;
  }
};

BoundaryConditions free_edges() {
  return BoundaryConditions::on_edges("free", "free", "free", "free");
}

struct SpecimenRun {
  DisplacementPath path;
  std::vector<double> delaminated; ///< fully failed area per point of the path [m²]
};

SpecimenRun run(const Specimen& s, const ControlledDisplacement& control, double final, int steps) {
  SpecimenRun out;
  const StackedPlateState initial = s.precracked();
  out.delaminated.push_back(s.stack.interface(0).damaged_area(initial.interfaces[0], 1.0));
  out.path = follow_displacement_path(
      s.stack, control, initial, {final, steps},
      [&](const PathPoint&, const Eigen::VectorXd&, const StackedPlateState& st) {
        out.delaminated.push_back(s.stack.interface(0).damaged_area(st.interfaces[0], 1.0));
      });
  return out;
}

/// Dissipation per new crack area over the points beyond `from`: the least-squares slope of the
/// dissipated energy against the fully delaminated area (the area grows by one column of interface
/// points at a time, while the process zone ahead of it holds a steady share of partial dissipation).
double dissipation_per_area(const SpecimenRun& r, double from) {
  double sa = 0, sd = 0, saa = 0, sad = 0;
  int n = 0;
  for (std::size_t i = 0; i < r.path.points.size(); ++i)
    if (r.path.points[i].displacement > from) {
      const double A = r.delaminated[i], D = r.path.points[i].dissipated;
      sa += A, sd += D, saa += A * A, sad += A * D, ++n;
    }
  return (n * sad - sa * sd) / (n * saa - sa * sa);
}

double peak_force(const DisplacementPath& p) {
  double peak = 0.0;
  for (const PathPoint& q : p.points)
    peak = std::max(peak, q.force);
  return peak;
}

// DCB (mode I): opened at the cracked end; the lower arm's far end holds the rigid motions (its reaction
// is zero by symmetry). Corrected beam theory: the propagation branch P(δ) = b √(8Q³/(E h³ δ)) within
// the 3 % once the crack propagates, G_Ic per new crack area within 2 %, W = stored + dissipated.
TEST(DoubleCantileverBeam, FollowsCorrectedBeamTheoryAndDissipatesTheToughness) {
  const double G = 969.0, a0 = 35e-3;
  const Specimen dcb(70e-3, a0, {a0 - 2e-3, a0 + 17e-3}, [](int k) {
    BoundaryConditions bc = free_edges();
    if (k == 1) bc.set("xa", "11100");
    return bc;
  });
  ControlledDisplacement opening;
  for (const int n : dcb.nodes_at(0.0)) {
    opening.dofs.emplace_back(dcb.stack.equation(0, n, 2), -0.5); // upper arm up (−z)
    opening.dofs.emplace_back(dcb.stack.equation(1, n, 2), 0.5);  // lower arm down
  }
  const bf::Specimen arm = Specimen::arm();
  const bf::Dcb beam{arm, a0, bf::dcb_crack_correction(arm)};
  const SpecimenRun r = run(dcb, opening, 9e-3, 90);
  const auto& points = r.path.points;

  const bf::LoadPoint cbt_peak = bf::propagation(beam, a0, G);
  std::printf("[ measured ] initial compliance %.5g m/N, CBT %.5g\n",
              points[10].displacement / points[10].force, bf::compliance(beam, a0));
  std::printf("[ measured ] peak %.4g N; CBT %.4g N at %.4g mm\n", peak_force(r.path), cbt_peak.force,
              cbt_peak.displacement * 1e3);
  double worst = 0.0;
  for (const PathPoint& p : points)
    if (p.displacement > 1.3 * cbt_peak.displacement)
      worst = std::max(worst, std::abs(p.force / bf::propagation_force(beam, p.displacement, G) - 1.0));
  std::printf("[ measured ] propagation branch: largest |P/P_CBT - 1| = %.4f\n", worst);
  EXPECT_LT(worst, 0.03);

  const PathPoint& last = points.back();
  EXPECT_NEAR(last.work, last.stored + last.dissipated, 1e-3 * last.work);
  const double slope = dissipation_per_area(r, 1.3 * cbt_peak.displacement);
  const double grown = (r.delaminated.back() - r.delaminated.front()) / Specimen::b;
  std::printf("[ measured ] crack grown %.3g mm; dD/dA = %.4f G_Ic; W - stored - D = %.3g of W\n",
              grown * 1e3, slope / G, (last.work - last.stored - last.dissipated) / last.work);
  EXPECT_GT(grown, 10e-3);
  EXPECT_NEAR(slope / G, 1.0, 0.02);
}

} // namespace
} // namespace plyimpact::delamination_path_tests

namespace plyimpact::delamination_path_tests {
namespace {

/// The force of a stable propagation branch (deflection growing with the crack length a) at deflection δ:
/// a found by bisection on [a_lo, a_hi] of `branch(a)`.
template <class Branch>
double branch_force(const Branch& branch, double deflection, double a_lo, double a_hi) {
  for (int i = 0; i < 100; ++i) {
    const double a = 0.5 * (a_lo + a_hi);
    (branch(a).displacement < deflection ? a_lo : a_hi) = a;
  }
  return branch(0.5 * (a_lo + a_hi)).force;
}

/// The peak of a path and the largest |P/P_ref − 1| beyond it, against a propagation branch given as
/// the force at a deflection; both printed with the LEFM cusp `cusp`.
template <class Branch>
const PathPoint& compare_with_branch(const std::vector<PathPoint>& points, const Branch& branch,
                                     const bf::LoadPoint& cusp, double& worst) {
  const auto peak = std::max_element(
      points.begin(), points.end(), [](const PathPoint& p, const PathPoint& q) { return p.force < q.force; });
  std::printf("[ measured ] peak %.4g N at %.4g mm (CBT branch there %.4g N); CBT %.4g N at %.4g mm\n",
              peak->force, peak->displacement * 1e3, branch(peak->displacement), cusp.force,
              cusp.displacement * 1e3);
  worst = 0.0;
  for (const PathPoint& p : points)
    if (p.displacement > peak->displacement)
      worst = std::max(worst, std::abs(p.force / branch(p.displacement) - 1.0));
  std::printf("[ measured ] propagation branch: largest |P/P_CBT - 1| = %.4f\n", worst);
  return *peak;
}

// ENF (mode II): three-point bending over 2L = 100 mm, the lower arm on the two supports (w = 0; the far
// one also holds u, v), the upper arm pushed down at mid-span; the crack runs from the support at x = 0
// to a0 = 0.75 L, beyond the stable length (0.68 L). CBT with Wang & Williams' 0.42 χh: the propagation
// branch within 3 % once the crack propagates, G_IIc per new crack area within 2 %, W = stored + dissipated.
TEST(EndNotchedFlexure, FollowsCorrectedBeamTheoryAndDissipatesTheToughness) {
  const double G = 1719.0, L = 50e-3, a0 = 37.5e-3;
  const Specimen enf(2.0 * L, a0, {a0 - 2e-3, L}, [](int k) {
    BoundaryConditions bc = free_edges();
    if (k == 1) {
      bc.set("x0", "00100");
      bc.set("xa", "11100");
    }
    return bc;
  });
  ControlledDisplacement push;
  for (const int n : enf.nodes_at(L))
    push.dofs.emplace_back(enf.stack.equation(0, n, 2), 1.0); // upper arm down (+z)
  const bf::Specimen arm = Specimen::arm();
  const bf::Enf beam{arm, L, a0, bf::enf_crack_correction(arm), true};
  ASSERT_GT(a0, bf::stable_crack_length(beam));
  const bf::LoadPoint cbt_peak = bf::propagation(beam, a0, G);
  const auto cbt_branch = [&](double deflection) {
    return branch_force([&](double a) { return bf::propagation(beam, a, G); }, deflection, a0, L);
  };
  const SpecimenRun r = run(enf, push, bf::propagation(beam, 0.95 * L, G).displacement, 80);
  const auto& points = r.path.points;

  std::printf("[ measured ] initial compliance %.5g m/N, CBT %.5g\n",
              points[5].displacement / points[5].force, bf::compliance(beam, a0));
  double worst = 0.0;
  const PathPoint& peak = compare_with_branch(points, cbt_branch, cbt_peak, worst);
  EXPECT_LT(worst, 0.03);

  const PathPoint& last = points.back();
  EXPECT_NEAR(last.work, last.stored + last.dissipated, 1e-3 * last.work);
  const double slope = dissipation_per_area(r, peak.displacement);
  const double grown = (r.delaminated.back() - r.delaminated.front()) / Specimen::b;
  std::printf("[ measured ] crack grown %.3g mm; dD/dA = %.4f G_IIc; W - stored - D = %.3g of W\n",
              grown * 1e3, slope / G, (last.work - last.stored - last.dissipated) / last.work);
  EXPECT_GT(grown, 6e-3);
  EXPECT_NEAR(slope / G, 1.0, 0.02);
}

// MMB (mixed mode, Reeder & Crews 1990): the ENF's supports, and a rigid lever that pulls the upper arm's
// cracked end up through a hinge (x = 0), pushes it down through a saddle at mid-span and carries the
// load at c beyond the saddle. The lever-point deflection Δ is controlled; the lever's other coordinate
// (the hinge's deflection y) is an unknown: the saddle follows at (L Δ + c y)/(L + c). The lever c gives
// G_II/G = 1/2 at a0 (ASTM D6671). CBT with χh (mode I) and 0.42 χh (mode II), propagation at the B-K
// toughness G_c(m): the branch within 3 %, the dissipation per new crack area within 2 % of G_c(m) —
// 14 % above G_Ic and 35 % below G_IIc, so the check tells the B-K law from either pure toughness.
//
// Mixed mode needs strengths that go with the toughnesses: with one penalty stiffness the law dissipates
// G_c(B) under a changing mixity only if S/N = √(G_IIc/G_Ic) = 1.33 (Turon et al. 2010); the tabulated
// 80 and 100 MPa (1.25) nearly do, the DCB's lowered N = 40 MPa with S = 100 MPa (2.5) does not (measured
// on 0.5 mm elements: branch 37 % high, 1.23 G_c(m), 0.49 % of the work unaccounted). So this test keeps the
// tabulated strengths, on 0.25 mm elements for the mode I zone (docs/delamination.md).
TEST(MixedModeBending, FollowsTheBenzeggaghKenaneBranchAndDissipatesItsToughness) {
  const double G_Ic = 969.0, G_IIc = 1719.0, eta = 2.284, L = 50e-3, a0 = 30e-3, a_end = 0.85 * L;
  const Specimen mmb(2.0 * L, a0, {a0 - 1e-3, a_end + 2.5e-3, 0.25e-3},
                     [](int k) {
                       BoundaryConditions bc = free_edges();
                       if (k == 1) {
                         bc.set("x0", "00100");
                         bc.set("xa", "11100");
                       }
                       return bc;
                     },
                     {80e6, 100e6});
  const bf::Specimen arm = Specimen::arm();
  bf::Mmb beam{arm, L, 0.0, a0, bf::dcb_crack_correction(arm), bf::enf_crack_correction(arm), true};
  beam.lever = bf::lever_for_mode_II_fraction(beam, a0, 0.5);
  const double c = beam.lever;
  ControlledDisplacement lever;
  lever.rig_coordinates = 1;
  for (const int n : mmb.nodes_at(0.0))
    lever.rig.push_back({mmb.stack.equation(0, n, 2), 0.0, 0, 1.0}); // hinge: w = y
  for (const int n : mmb.nodes_at(L))
    lever.rig.push_back({mmb.stack.equation(0, n, 2), L / (L + c), 0, c / (L + c)}); // saddle
  const auto cbt = [&](double a) { return bf::propagation(beam, a, G_Ic, G_IIc, eta); };
  for (double a = a0; a < a_end; a += 1e-3)
    ASSERT_LT(cbt(a).displacement, cbt(a + 1e-3).displacement) << "unstable at a = " << a;
  const SpecimenRun r = run(mmb, lever, cbt(a_end).displacement, 60);
  const auto& points = r.path.points;

  std::printf("[ measured ] lever c = %.4g mm; G_II/G = %.3f at a0, %.3f at %.3g mm\n", c * 1e3,
              bf::mode_II_fraction(beam, a0), bf::mode_II_fraction(beam, a_end), a_end * 1e3);
  std::printf("[ measured ] initial compliance %.5g m/N, CBT %.5g\n",
              points[5].displacement / points[5].force, bf::compliance(beam, a0));
  const auto cbt_branch = [&](double deflection) { return branch_force(cbt, deflection, a0, a_end); };
  double worst = 0.0;
  const PathPoint& peak = compare_with_branch(points, cbt_branch, cbt(a0), worst);
  EXPECT_LT(worst, 0.03);

  const PathPoint& last = points.back();
  const double slope = dissipation_per_area(r, peak.displacement);
  const double grown = (r.delaminated.back() - r.delaminated.front()) / Specimen::b;
  const double m_mid = bf::mode_II_fraction(beam, a0 + 0.5 * grown);
  const double G_c = G_Ic + (G_IIc - G_Ic) * std::pow(m_mid, eta);
  const double unaccounted = (last.work - last.stored - last.dissipated) / last.work;
  std::printf("[ measured ] crack grown %.3g mm; dD/dA = %.4f G_c(m = %.3f) = %.5g J/m2; W - stored - D = "
              "%.3g of W\n",
              grown * 1e3, slope / G_c, m_mid, G_c, unaccounted);
  EXPECT_GT(grown, 8e-3);
  EXPECT_NEAR(slope / G_c, 1.0, 0.02);
  // The work's share not found as stored or dissipated energy is first order in the load step here (the
  // crack advances in jumps that the trapezoidal work rule cuts across; measured 2.8e-3 with 80 steps and
  // 8.5e-4 with 240 on the 0.5 mm mesh); 60 steps keep the test short.
  EXPECT_LT(std::abs(unaccounted), 5e-3);
}

} // namespace
} // namespace plyimpact::delamination_path_tests
