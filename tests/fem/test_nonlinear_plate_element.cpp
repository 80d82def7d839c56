// The geometrically non-linear element (SPEC §8): its tangent is the derivative of its internal force
// (central finite differences at random states), it reduces to the linear element at u = 0, and the
// assembled model agrees with the element.
#include "plyimpact/fem/nonlinear_plate.hpp"
#include "support/decks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>

namespace plyimpact::nonlinear_plate_element_tests {
namespace {

using test::laminate_of;
using test::thesis_3_6;

/// A straight-sided, distorted 9-node element about 10 mm across (mid-side and centre nodes on the
/// bilinear map of the corners).
ElementCoordinates distorted_element() {
  const Eigen::Vector2d c[4] = {{0.0, 0.0}, {0.011, 0.001}, {0.0105, 0.0095}, {-0.0008, 0.0102}};
  ElementCoordinates xy;
  for (int a = 0; a < 4; ++a)
    xy.row(a) = c[a].transpose();
  for (int a = 4; a < 8; ++a)
    xy.row(a) = 0.5 * (c[a - 4] + c[(a - 3) % 4]).transpose();
  xy.row(8) = 0.25 * (c[0] + c[1] + c[2] + c[3]).transpose();
  return xy;
}

/// Random nodal state on the scale of a large deflection: w ~ h, rotations ~ h/L, in-plane ~ h²/L.
ElementVector random_state(std::mt19937& rng, double h, double L) {
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  const double scale[5] = {h * h / L, h * h / L, h, h / L, h / L};
  ElementVector u;
  for (int i = 0; i < q9_dofs; ++i)
    u(i) = scale[i % 5] * r(rng);
  return u;
}

/// The non-linear element of one formulation and strain measure on one laminate, with its linear twin.
struct ElementUnderTest {
  ElementUnderTest(const Laminate& lam, ElementFormulation formulation, StrainMeasure measure)
      : linear(make_plate_element(formulation)), section(section_stiffness(lam)),
        nonlinear(*linear, measure) {}
  [[nodiscard]] ElementGeometry geometry(const ElementCoordinates& xy) const {
    return nonlinear.geometry(xy, section);
  }
  [[nodiscard]] ElementVector internal_force(const ElementGeometry& geo, const ElementVector& u) const {
    return nonlinear.internal_force(geo, section, u);
  }
  [[nodiscard]] ElementMatrix tangent_stiffness(const ElementGeometry& geo, const ElementVector& u) const {
    return nonlinear.tangent_stiffness(geo, section, u);
  }
  [[nodiscard]] ElementMatrix linear_stiffness(const ElementCoordinates& xy) const {
    return linear->stiffness(xy, ElementSection(section));
  }
  std::unique_ptr<PlateElement> linear;
  SectionStiffness section;
  NonlinearMindlinQ9 nonlinear;
};

struct TangentCheck {
  double full = 0.0;      ///< ‖K_T − K_FD‖ / ‖K_T‖
  double nonlinear = 0.0; ///< ‖(K_T − K_L) − (K_FD − K_L)‖ / ‖K_T − K_L‖
};

/// Central differences column by column, step 1e-5 of each DOF's scale (the force is a cubic
/// polynomial of u, so the truncation error is ~1e-10 relative).
TangentCheck check_tangent(const ElementUnderTest& el, const ElementGeometry& geo, const ElementVector& u,
                           const ElementMatrix& K_linear, double h, double L) {
  const double scale[5] = {h * h / L, h * h / L, h, h / L, h / L};
  const ElementMatrix K = el.tangent_stiffness(geo, u);
  ElementMatrix K_fd;
  for (int j = 0; j < q9_dofs; ++j) {
    const double step = 1e-5 * scale[j % 5];
    ElementVector up = u, um = u;
    up(j) += step;
    um(j) -= step;
    K_fd.col(j) = (el.internal_force(geo, up) - el.internal_force(geo, um)) / (2.0 * step);
  }
  return {(K - K_fd).norm() / K.norm(), ((K - K_linear) - (K_fd - K_linear)).norm() / (K - K_linear).norm()};
}

struct Case {
  ElementFormulation formulation;
  StrainMeasure measure;
};

class NonlinearTangent : public ::testing::TestWithParam<Case> {};

TEST_P(NonlinearTangent, EqualsFiniteDifferenceOfInternalForceAtRandomStates) {
  // Unsymmetric layup: B ≠ 0 couples membrane and bending, so every block of C is exercised.
  const Laminate lam = laminate_of(thesis_3_6(), "[0/45/90/-30]", 0.4e-3);
  const ElementUnderTest el(lam, GetParam().formulation, GetParam().measure);
  const ElementCoordinates xy = distorted_element();
  const ElementGeometry geo = el.geometry(xy);
  const ElementMatrix K_linear = el.linear_stiffness(xy);
  std::mt19937 rng(20261122);
  double worst_full = 0.0, worst_nonlinear = 0.0;
  for (int trial = 0; trial < 5; ++trial) {
    const ElementVector u = random_state(rng, lam.thickness(), 0.01);
    const TangentCheck c = check_tangent(el, geo, u, K_linear, lam.thickness(), 0.01);
    EXPECT_LT(c.full, 1e-6) << "trial " << trial;
    EXPECT_LT(c.nonlinear, 1e-6) << "trial " << trial;
    worst_full = std::max(worst_full, c.full);
    worst_nonlinear = std::max(worst_nonlinear, c.nonlinear);
    const ElementMatrix K = el.tangent_stiffness(geo, u);
    EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm()); // conservative: K_T symmetric
  }
  std::printf(
      "tangent vs finite differences: worst relative error %.2e (whole K_T), %.2e (non-linear part)\n",
      worst_full, worst_nonlinear);
}

TEST_P(NonlinearTangent, ReducesToTheLinearElementAtSmallDisplacements) {
  const Laminate lam = laminate_of(thesis_3_6(), "[0/45/90/-30]", 0.4e-3);
  const ElementUnderTest el(lam, GetParam().formulation, GetParam().measure);
  const ElementCoordinates xy = distorted_element();
  const ElementGeometry geo = el.geometry(xy);
  const ElementMatrix K_linear = el.linear_stiffness(xy);
  EXPECT_LT((el.tangent_stiffness(geo, ElementVector::Zero()) - K_linear).norm(), 1e-13 * K_linear.norm());
  // f(εu) = ε K_L u + O(ε²): the relative departure scales with ε.
  std::mt19937 rng(7);
  const ElementVector u = random_state(rng, lam.thickness(), 0.01);
  for (const double eps : {1e-3, 1e-6}) {
    const ElementVector f_lin = K_linear * (eps * u);
    const double rel = (el.internal_force(geo, eps * u) - f_lin).norm() / f_lin.norm();
    EXPECT_LT(rel, 10.0 * eps) << "eps " << eps;
    EXPECT_GT(rel, 0.01 * eps) << "eps " << eps; // and the non-linear part is really there
  }
}

INSTANTIATE_TEST_SUITE_P(StrainMeasures, NonlinearTangent,
                         ::testing::Values(Case{ElementFormulation::q9, StrainMeasure::von_karman},
                                           Case{ElementFormulation::q9, StrainMeasure::green_lagrange},
                                           Case{ElementFormulation::mitc9, StrainMeasure::von_karman}),
                         [](const ::testing::TestParamInfo<Case>& p) {
                           return std::string(p.param.formulation == ElementFormulation::q9 ? "q9_"
                                                                                            : "mitc9_") +
                                  (p.param.measure == StrainMeasure::von_karman ? "von_karman"
                                                                                : "green_lagrange");
                         });

TEST(NonlinearElement, Mitc9ShearForceIsTheLinearShearStiffnessTimesU) {
  // The force path multiplies K_s on (w, θx, θy) alone; the difference of the forces with and without
  // it must be the whole 45 × 45 K_s of the linear element times u (its u, v rows and columns zero).
  const Laminate lam = laminate_of(thesis_3_6(), "[0/45/90/-30]", 0.4e-3);
  const ElementUnderTest el(lam, ElementFormulation::mitc9, StrainMeasure::von_karman);
  const ElementGeometry geo = el.geometry(distorted_element());
  ElementGeometry no_shear = geo;
  no_shear.shear_stiffness_wt.setZero();
  std::mt19937 rng(11);
  const ElementVector u = random_state(rng, lam.thickness(), 0.01);
  const ElementVector expected = geo.shear_stiffness * u;
  const ElementVector got = el.internal_force(geo, u) - el.internal_force(no_shear, u);
  EXPECT_GT(expected.norm(), 0.0);
  EXPECT_LT((got - expected).norm(), 1e-12 * el.internal_force(geo, u).norm());
}

TEST(NonlinearElement, GreenLagrangeWithMitc9IsRefusedWithAClearMessage) {
  const Laminate lam = laminate_of(thesis_3_6(), "[0/90]s", 0.4e-3);
  try {
    const ElementUnderTest el(lam, ElementFormulation::mitc9, StrainMeasure::green_lagrange);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("q9"), std::string::npos);
  }
}

TEST(NonlinearPlate, AssembledTangentIsTheDerivativeOfTheAssembledForce) {
  const Laminate lam = laminate_of(thesis_3_6(), "[0/90]s", 0.5e-3);
  const DiscretePlate model(lam, {0.04, 0.03}, {3, 2, MassMatrix::lumped, ElementFormulation::q9},
                            test::all_edges("ss"));
  const NonlinearPlate nl(model, StrainMeasure::von_karman);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  Eigen::VectorXd u(model.size());
  for (int i = 0; i < model.size(); ++i)
    u(i) = 1e-3 * r(rng);
  Eigen::VectorXd du(model.size());
  for (int i = 0; i < model.size(); ++i)
    du(i) = 1e-3 * r(rng);
  const double step = 1e-5;
  const Eigen::VectorXd fd =
      (nl.internal_force(u + step * du) - nl.internal_force(u - step * du)) / (2 * step);
  const Eigen::VectorXd Kdu = nl.tangent_stiffness(u) * du;
  EXPECT_LT((Kdu - fd).norm(), 1e-6 * Kdu.norm());
  // At u = 0 the tangent is the linear stiffness.
  EXPECT_LT(
      SparseMatrix(nl.tangent_stiffness(Eigen::VectorXd::Zero(model.size())) - model.stiffness()).norm(),
      1e-13 * model.stiffness().norm());
}

} // namespace
} // namespace plyimpact::nonlinear_plate_element_tests
