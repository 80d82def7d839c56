// The stacked plate (issue 19): the laminate cut into sub-laminates tied by cohesive interfaces. Checks
// the cut, the kinematics of the separation (DL1) and that a stack whose interfaces do not fail is the
// single laminate.
#include "plyimpact/fem/element_loop.hpp"
#include "plyimpact/fem/quadrature.hpp"
#include "plyimpact/fem/stacked_plate.hpp"
#include "plyimpact/fem/structured_mesh.hpp"
#include "support/as4_peek.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>

namespace plyimpact::stacked_plate_tests {
namespace {

using test::as4_peek;

using test::as4_peek_interface;

Laminate cross_ply(double ply) {
  return test::as4_peek_cross_ply(ply);
}

TEST(SplitLaminate, CutsAtOrientationChangesIntoSubLaminatesThatAddUp) {
  const Laminate lam = cross_ply(0.25e-3);
  const std::vector<int> cuts = interfaces_between_orientations(lam);
  ASSERT_EQ(cuts, (std::vector<int>{0, 2})); // 0|90 90|0
  const auto parts = split_laminate(lam, cuts);
  ASSERT_EQ(parts.size(), 3u);
  EXPECT_DOUBLE_EQ(parts[0].thickness(), 0.25e-3);
  EXPECT_DOUBLE_EQ(parts[1].thickness(), 0.5e-3);
  EXPECT_DOUBLE_EQ(parts[1].plies()[0].angle_deg, 90.0);
  // The parts' D about the laminate's mid-plane (parallel axes) add up to the laminate's D.
  double z = -0.5 * lam.thickness();
  Eigen::Matrix3d D = Eigen::Matrix3d::Zero();
  for (const Laminate& p : parts) {
    const double zc = z + 0.5 * p.thickness();
    D += p.D() + zc * zc * p.A();
    z += p.thickness();
  }
  EXPECT_LT((D - lam.D()).norm(), 1e-12 * lam.D().norm());
}

TEST(SplitLaminate, ACutThatDoesNotExistIsNamed) {
  const Laminate lam = cross_ply(0.25e-3);
  try {
    (void)split_laminate(lam, {3});
    FAIL() << "expected invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("after ply 4"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("plies 1 to 3"), std::string::npos) << e.what();
  }
}

TEST(InterfaceValuesFromPlies, TheSmallestOfThePliesThatMeetAtTheCutsAndNoneWhereOneLacksIt) {
  // A hybrid [A/B/B/C]: cuts after plies 1 and 3 meet A, B and B, C. Material C's toughnesses are
  // lower, but C meets only the second cut: with both cuts it sets G_Ic and G_IIc; with the first
  // alone A and B do. B has no Yt, so N is unknown wherever B meets a cut.
  Material A = as4_peek(), B = as4_peek(), C = as4_peek();
  A.toughness.G_mt = 300.0;
  A.toughness.G_mc = 900.0;
  A.strength.Yt = 60e6;
  B.strength.Yt.reset();
  B.toughness.G_mt = 250.0;
  B.toughness.G_mc = 1000.0;
  C.toughness.G_mt = 100.0;
  C.toughness.G_mc = 400.0;
  C.strength.Yt = 40e6;
  const Laminate lam({A, B, C},
                     {{0.0, 0.25e-3, 0}, {90.0, 0.25e-3, 1}, {90.0, 0.25e-3, 1}, {0.0, 0.25e-3, 2}});
  const PlyInterfaceValues both = interface_values_from_plies(lam, {0, 2});
  EXPECT_EQ(both.G_Ic, 100.0);
  EXPECT_EQ(both.G_IIc, 400.0);
  EXPECT_FALSE(both.normal_strength);
  const PlyInterfaceValues first = interface_values_from_plies(lam, {0});
  EXPECT_EQ(first.G_Ic, 250.0);
  EXPECT_EQ(first.G_IIc, 900.0);
  const Laminate without_b({A, C}, {{0.0, 0.25e-3, 0}, {90.0, 0.25e-3, 1}});
  EXPECT_EQ(interface_values_from_plies(without_b, {0}).normal_strength, 40e6);
  // Turon's S = N √(G_IIc/G_Ic): 60 MPa × √(900/300) = 103.923 MPa.
  EXPECT_NEAR(turon_shear_strength(60e6, 300.0, 900.0), 103.923e6, 1e3);
}

class TwoSubLaminates : public ::testing::Test {
protected:
  static constexpr double a = 0.04, b = 0.03, h = 1e-3;
  Laminate lam{{as4_peek()}, {{0.0, h, 0}, {90.0, 2.0 * h, 0}}};
  Mesh mesh = structured_rectangle({a, b}, 2, 2);
  StackedPlate stack{mesh, lam, StackSettings{{0}, as4_peek_interface(h)}, {}, free_edges};
  /// The same stack integrated with `rule`.
  std::unique_ptr<StackedPlate> stack_with(CohesiveQuadrature rule) const {
    return std::make_unique<StackedPlate>(mesh, lam, StackSettings{{0}, as4_peek_interface(h), rule},
                                          Discretization{}, free_edges);
  }
  static BoundaryConditions free_edges(int /*sublaminate*/) {
    return BoundaryConditions::on_edges("free", "free", "free", "free");
  }

  /// A stacked vector from a displacement field u(x, y, z) of the whole laminate that is a Mindlin field
  /// with the same (w, θx, θy) in both sub-laminates: u0_k = u(z_k) at each sub-laminate's mid-plane.
  Eigen::VectorXd
  whole_laminate_field(const std::function<std::array<double, 5>(double x, double y)>& mid) const {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(stack.size());
    const std::array<double, 2> z_mid{-0.5 * lam.thickness() + 0.5 * h, -0.5 * lam.thickness() + 2.0 * h};
    for (int k = 0; k < 2; ++k)
      for (int n = 0; n < mesh.node_count(); ++n) {
        const auto f = mid(mesh.node(n).x(), mesh.node(n).y());
        const std::array<double, 5> sub{f[0] + z_mid[k] * f[3], f[1] + z_mid[k] * f[4], f[2], f[3], f[4]};
        for (int d = 0; d < 5; ++d)
          u(stack.equation(k, n, d)) = sub[static_cast<std::size_t>(d)];
      }
    return u;
  }
};

// A motion of the whole laminate (rigid, or any Mindlin field shared by both sub-laminates) does not
// separate the faces: the separation (DL1) is the jump of the through-thickness field, which is zero.
TEST_F(TwoSubLaminates, AMotionOfTheWholeLaminateDoesNotSeparateTheFaces) {
  const Eigen::VectorXd u = whole_laminate_field([](double x, double y) {
    return std::array<double, 5>{1e-4 + 2e-3 * y, -3e-4 + 1e-3 * x * x, 5e-4 + 0.02 * x - 0.01 * y * x,
                                 0.03 - 0.5 * y, -0.02 + 0.7 * x};
  });
  const CohesiveInterface& face = stack.interface(0);
  for (int p = 0; p < face.point_count(); ++p)
    EXPECT_LT(face.separation(p, u).norm(), 1e-15) << "point " << p;
}

// Opening and sliding read exactly as the faces move: w of the lower minus w of the upper, and
// u_l − ½h_l θx_l − u_u − ½h_u θx_u.
TEST_F(TwoSubLaminates, SeparationIsTheJumpOfTheFaces) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(stack.size());
  for (int n = 0; n < mesh.node_count(); ++n) {
    u(stack.equation(1, n, 2)) = 2e-6;  // lower w
    u(stack.equation(0, n, 2)) = -1e-6; // upper w
    u(stack.equation(0, n, 0)) = 3e-6;  // upper u
    u(stack.equation(0, n, 3)) = 4e-3;  // upper θx: its bottom face moves by +½h θx
    u(stack.equation(1, n, 4)) = 1e-3;  // lower θy: its top face moves by −½(2h) θy
  }
  const Eigen::Vector3d d = stack.interface(0).separation(7, u);
  EXPECT_NEAR(d(2), 3e-6, 1e-20);
  EXPECT_NEAR(d(0), -3e-6 - 0.5 * h * 4e-3, 1e-20);
  EXPECT_NEAR(d(1), -0.5 * (2.0 * h) * 1e-3, 1e-20);
}

// The nodal rule's points cover the plate once: their areas add up to a × b.
TEST_F(TwoSubLaminates, InterfacePointsCoverThePlate) {
  const CohesiveInterface& face = stack.interface(0);
  double area = 0.0;
  for (int p = 0; p < face.point_count(); ++p)
    area += face.point_area(p);
  EXPECT_NEAR(area, a * b, 1e-15);
  StackedPlateState state = stack.virgin_state();
  stack.crack(state, 0, [](const Eigen::Vector2d& xy) { return xy.x() < 0.5 * a; });
  // The points on x = a/2, an element boundary, are not cracked (strict inequality): the left element
  // column loses the Simpson weight 1/6 of its width a/2.
  EXPECT_NEAR(face.damaged_area(state.interfaces[0], 1.0), 0.5 * a * b - (a / 2.0) * b / 6.0, 1e-15);
}

// A rule's tributary intervals lie end to end over [−1, 1], each as long as its point's weight and holding
// its point (Gauss and Lobatto alike).
TEST(TributaryInterval, TilesTheParentIntervalAndHoldsItsPoint) {
  for (const QuadratureRule1D<3>& rule : {gauss3, lobatto3}) {
    double end = -1.0;
    for (std::size_t k = 0; k < 3; ++k) {
      const auto [from, to] = tributary_interval(rule, k);
      EXPECT_DOUBLE_EQ(from, end);
      EXPECT_NEAR(to - from, rule.weights[k], 1e-15);
      EXPECT_GE(rule.points[k], from);
      EXPECT_LE(rule.points[k], to);
      end = to;
    }
    EXPECT_NEAR(end, 1.0, 1e-15);
  }
  // Simpson's nodal rule: the corner points stand for a sixth of the side each, the middle for 2/3.
  EXPECT_DOUBLE_EQ(tributary_interval(lobatto3, 0).second, -2.0 / 3.0);
}

// Each interface point stands for a cell of its element (the map of its tributary rectangle): on this
// rectangular mesh the cell's area is the point's w detJ, the cell holds the point, and the cells tile the
// plate (their areas add up to a × b, and to the elements' areas element by element).
TEST_F(TwoSubLaminates, EachPointStandsForACellOfItsElementWithThePointsArea) {
  const CohesiveInterface& face = stack.interface(0);
  double total = 0.0;
  for (int p = 0; p < face.point_count(); ++p) {
    const std::array<Eigen::Vector2d, 4> c = face.point_cell(p);
    double shoelace = 0.0;
    for (std::size_t k = 0; k < 4; ++k) {
      const Eigen::Vector2d& u = c[k];
      const Eigen::Vector2d& v = c[(k + 1) % 4];
      shoelace += 0.5 * (u.x() * v.y() - v.x() * u.y());
    }
    EXPECT_NEAR(shoelace, face.point_area(p), 1e-18) << "point " << p; // > 0: counter-clockwise
    const Eigen::Vector2d& x = face.point_position(p);
    constexpr double round_off = 1e-15; // the nodal rule's points lie on their cells' edges
    EXPECT_TRUE(x.x() >= c[0].x() - round_off && x.x() <= c[2].x() + round_off &&
                x.y() >= c[0].y() - round_off && x.y() <= c[2].y() + round_off)
        << p;
    total += shoelace;
  }
  EXPECT_NEAR(total, a * b, 1e-15);
  // The corner point of the first element stands for (a/2)/6 × (b/2)/6.
  EXPECT_NEAR(face.point_area(0), (a / 12.0) * (b / 12.0), 1e-18);
}

// The force is the gradient of the stored energy: central differences of ψ(u) along random directions
// equal f·v (the interface part, undamaged and with a half-damaged interface), with either rule.
TEST_F(TwoSubLaminates, ForceIsTheGradientOfTheStoredEnergy) {
  for (const CohesiveQuadrature rule : {CohesiveQuadrature::nodal, CohesiveQuadrature::gauss}) {
    const auto ruled = stack_with(rule);
    std::srand(7);
    const Eigen::VectorXd u = 1e-9 * Eigen::VectorXd::Random(ruled->size());
    const Eigen::VectorXd v = 1e-9 * Eigen::VectorXd::Random(ruled->size());
    for (const double d : {0.0, 0.5}) {
      StackedPlateState state = ruled->virgin_state();
      for (auto& s : state.interfaces[0])
        s.damage = d;
      const StackedPlateEvaluation e = ruled->evaluate(u, state);
      const double eps = 1e-3;
      const double fd =
          (ruled->stored_energy(u + eps * v, state) - ruled->stored_energy(u - eps * v, state)) / (2 * eps);
      EXPECT_NEAR(e.force.dot(v), fd, 1e-7 * std::abs(fd)) << "d = " << d;
    }
  }
}

// The interfaces on threads (issue 50): force, trial states, dissipation, tangent and stored energy of a
// softening interface are the same bits on 1, 2 and 4 threads, each equation's sum made in element order
// as a one-thread loop makes it, with either rule.
TEST_F(TwoSubLaminates, InterfaceEvaluationIsTheSameBitsOnOneTwoAndFourThreads) {
  const Mesh fine = structured_rectangle({a, b}, 8, 6);
  for (const CohesiveQuadrature rule : {CohesiveQuadrature::nodal, CohesiveQuadrature::gauss}) {
    const StackedPlate ruled(fine, lam, StackSettings{{0}, as4_peek_interface(h), rule}, Discretization{},
                             free_edges);
    std::srand(11);
    const Eigen::VectorXd u = 1e-6 * Eigen::VectorXd::Random(ruled.size()); // well past the onset
    const StackedPlateState virgin = ruled.virgin_state();
    const auto evaluate = [&](int threads) {
      const ElementThreads setting(threads);
      return std::pair{ruled.evaluate(u, virgin), ruled.stored_energy(u, virgin)};
    };
    const auto [one, energy] = evaluate(1);
    ASSERT_GT(one.dissipated, 0.0) << "no point softened";
    for (const int threads : {2, 4}) {
      const auto [e, stored] = evaluate(threads);
      for (Eigen::Index i = 0; i < one.force.size(); ++i)
        ASSERT_EQ(e.force(i), one.force(i)) << "equation " << i << ", " << threads << " threads";
      EXPECT_EQ(e.dissipated, one.dissipated) << threads << " threads";
      EXPECT_EQ(stored, energy) << threads << " threads";
      const auto& trial = e.trial.interfaces[0];
      for (std::size_t p = 0; p < trial.size(); ++p) {
        ASSERT_EQ(trial[p].damage, one.trial.interfaces[0][p].damage) << "point " << p;
        ASSERT_EQ(trial[p].separation, one.trial.interfaces[0][p].separation) << "point " << p;
      }
      EXPECT_EQ((e.tangent - one.tangent).norm(), 0.0) << threads << " threads";
    }
  }
}

// Tangent = central differences of the force, across the onset of softening (FEBio's check), with either
// rule: the nodal one couples each node pair of the faces alone, Gauss couples all nine nodes.
TEST_F(TwoSubLaminates, TangentIsTheDerivativeOfTheForce) {
  for (const CohesiveQuadrature rule : {CohesiveQuadrature::nodal, CohesiveQuadrature::gauss}) {
    const auto ruled = stack_with(rule);
    std::srand(11);
    // Separations of about the onset (N/K = 80e6/5e14 = 1.6e-7 m) so that some points soften.
    Eigen::VectorXd u = 3e-7 * Eigen::VectorXd::Random(ruled->size());
    const StackedPlateState state = ruled->virgin_state();
    const StackedPlateEvaluation e = ruled->evaluate(u, state);
    EXPECT_GT(e.dissipated, 0.0);
    const Eigen::VectorXd v = Eigen::VectorXd::Random(ruled->size());
    const double eps = 1e-13;
    const Eigen::VectorXd fd =
        (ruled->evaluate(u + eps * v, state).force - ruled->evaluate(u - eps * v, state).force) / (2 * eps);
    const Eigen::VectorXd Kv = e.tangent * v;
    EXPECT_LT((Kv - fd).norm(), 1e-5 * Kv.norm());
  }
}

/// Consistent nodal forces of a uniform pressure q on `model`, placed from `offset` in a vector of `size`.
Eigen::VectorXd pressure(const DiscretePlate& model, double q, int offset, int size) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(size);
  Eigen::VectorXd fm = Eigen::VectorXd::Zero(model.size());
  for (int e = 0; e < model.mesh().element_count(); ++e)
    scatter_add(fm, model.element_equations(e),
                PlateElement::pressure_load(model.mesh().element_coordinates(e), q));
  f.segment(offset, model.size()) = fm;
  return f;
}

// With interfaces that do not fail, the stack is the laminate: a [0/90]s plate (a/h = 50) clamped on
// all edges, cut at both orientation changes, deflects under a uniform pressure as the single-laminate
// plate within the 0.5 %. What differs is transverse shear: the stack is a layerwise model
// (each sub-laminate its own shear strain, no shear correction), the single plate first-order with
// 5/6 (docs/delamination.md, "Consistency with the single laminate"). The sub-laminates' shear
// correction is what this checks: with 5/6 in each the stack is 1.1 % softer.
TEST(StackedPlate, WithInterfacesThatHoldItIsTheSingleLaminate) {
  const double a = 0.1, ply = 0.5e-3, q = 1e4;
  const Laminate lam = cross_ply(ply);
  const Mesh mesh = structured_rectangle({a, a}, 8, 8);
  const auto clamped = [](int) {
    return BoundaryConditions::on_edges("clamped", "clamped", "clamped", "clamped");
  };
  int centre = 0;
  for (int n = 0; n < mesh.node_count(); ++n)
    if ((mesh.node(n) - Eigen::Vector2d(0.5 * a, 0.5 * a)).norm() < 1e-12) centre = n;
  ASSERT_GT(centre, 0);

  const DiscretePlate single(mesh, PlateSections{{lam}, {}}, {}, clamped(0));
  const Eigen::SimplicialLDLT<SparseMatrix> ldlt(single.stiffness());
  const double w_single =
      ldlt.solve(pressure(single, q, 0, single.size()))(single.dofs().equation(centre, 2));

  const auto stacked_deflections = [&](std::optional<double> shear_correction) {
    const StackedPlate stack(
        mesh, lam,
        StackSettings{interfaces_between_orientations(lam), as4_peek_interface(ply), {}, shear_correction},
        {}, clamped);
    const StackedPlateEvaluation e =
        stack.evaluate(Eigen::VectorXd::Zero(stack.size()), stack.virgin_state());
    const Eigen::SparseLU<SparseMatrix> lu(e.tangent);
    const Eigen::VectorXd us = lu.solve(pressure(stack.sublaminate(0), q, 0, stack.size())); // impacted side
    std::array<double, 3> w{};
    for (int k = 0; k < 3; ++k)
      w[static_cast<std::size_t>(k)] = us(stack.equation(k, centre, 2)) / w_single;
    return w;
  };
  const auto consistent = stacked_deflections(std::nullopt); // each slice's (DL0)
  for (const double w : consistent)
    EXPECT_NEAR(w, 1.0, 5e-3);
  const double five_sixths = stacked_deflections(5.0 / 6.0)[0], one = stacked_deflections(1.0)[0];
  EXPECT_GT(five_sixths, 1.005); // each sub-laminate with 5/6: too soft
  std::printf("[ measured ] centre deflection stacked/single: %.6f (every sub-laminate 5/6: %.6f, 1: %.6f)\n",
              consistent[0], five_sixths, one);
}

TEST(StackedPlate, SliceShearCorrectionsCarryTheParabolicShearEnergyOfTheWholeSection) {
  // (DL0): the whole section and its halves get 5/6; quarters carry their slice of the parabola, and
  // the stack's compliance Σ (Q_k/Q)² h/(κ_k h_k) is the section's 1/κ = 6/5 for any cut.
  EXPECT_NEAR(slice_shear_correction(-0.5, 0.5, 1.0), 5.0 / 6.0, 1e-14);
  EXPECT_NEAR(slice_shear_correction(-0.5, 0.0, 1.0), 5.0 / 6.0, 1e-14);
  EXPECT_NEAR(slice_shear_correction(0.0, 0.5, 1.0), 5.0 / 6.0, 1e-14);
  EXPECT_NEAR(slice_shear_correction(0.0, 0.25, 1.0), 0.993432, 1e-6); // hand: 0.34375² / (¼ · 0.4757813)
  EXPECT_NEAR(slice_shear_correction(0.25, 0.5, 1.0), 0.786164, 1e-6); // hand: 0.15625² / (¼ · 0.1242188)
  const std::vector<double> z{-2.0e-3, -1.3e-3, -0.2e-3, 0.9e-3, 2.0e-3}; // uneven cuts of h = 4 mm
  double compliance = 0.0;
  for (std::size_t k = 0; k + 1 < z.size(); ++k) {
    const double s1 = z[k] / 4e-3, s2 = z[k + 1] / 4e-3;
    const double share = 1.5 * ((s2 - 4.0 * s2 * s2 * s2 / 3.0) - (s1 - 4.0 * s1 * s1 * s1 / 3.0)); // Q_k/Q
    compliance += share * share / (slice_shear_correction(z[k], z[k + 1], 4e-3) * (s2 - s1));
  }
  EXPECT_NEAR(compliance, 6.0 / 5.0, 1e-12);
}

} // namespace
} // namespace plyimpact::stacked_plate_tests
