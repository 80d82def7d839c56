// Consistent nodal forces of a circular pressure on one 9-node element (src/plyimpact/fem/circle_load):
// checked against closed forms (moments of the Hertz pressure, the Hertz load beyond a straight cut),
// partition of unity over the elements sharing a node or an edge, the consistent load of a uniform
// pressure, the first moment ∫ x p dA, and convergence of the quadrature orders.
#include "plyimpact/fem/circle_load.hpp"

#include "plyimpact/fem/shape_functions.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

namespace circle_load_tests {

namespace {

using plyimpact::circle_load;
using plyimpact::CircleQuadrature;
using plyimpact::Q9NodeCoordinates;
using Vec9 = Eigen::Matrix<double, 9, 1>;
constexpr double pi = std::numbers::pi;

// Element [x0, x0 + hx] × [y0, y0 + hy] with its nodes passed through `map` (identity: a rectangle).
// Neighbouring elements built with the same map share their edge nodes, hence their (curved) edges.
Q9NodeCoordinates element(double x0, double y0, double hx, double hy,
                          const std::function<Eigen::Vector2d(Eigen::Vector2d)>& map = {}) {
  Q9NodeCoordinates X;
  for (int a = 0; a < 9; ++a) {
    const auto& n = plyimpact::q9_node_coordinates[static_cast<std::size_t>(a)];
    Eigen::Vector2d p(x0 + 0.5 * (n[0] + 1.0) * hx, y0 + 0.5 * (n[1] + 1.0) * hy);
    if (map) p = map(p);
    X.row(a) = p.transpose();
  }
  return X;
}

// A smooth distortion of the plane: straight grid lines become curves, elements become curved quads.
Eigen::Vector2d wavy(const Eigen::Vector2d& p) {
  return {p.x() + 0.08 * std::sin(3.0 * p.y() + 0.4) + 0.03 * p.x() * p.y(),
          p.y() + 0.06 * std::sin(2.5 * p.x() + 1.1) - 0.02 * p.x() * p.x()};
}

// ∫ g(ξ, η) det J dξ dη over the element by a high-order tensor Gauss rule (the integrand is a
// polynomial of degree ≤ 8 per direction for these elements: exact with 6 points).
Vec9 element_integral(const Q9NodeCoordinates& X, const std::function<double(const Eigen::Vector2d&)>& p) {
  static const std::array<double, 6> xg{-0.9324695142031521, -0.6612093864662645, -0.2386191860831969,
                                        0.2386191860831969,  0.6612093864662645,  0.9324695142031521};
  static const std::array<double, 6> wg{0.1713244923791704, 0.3607615730481386, 0.4679139345726910,
                                        0.4679139345726910, 0.3607615730481386, 0.1713244923791704};
  Vec9 f = Vec9::Zero();
  for (std::size_t i = 0; i < 6; ++i)
    for (std::size_t j = 0; j < 6; ++j) {
      const plyimpact::Q9Shape sh = plyimpact::q9_shape(xg[i], xg[j]);
      Eigen::Matrix2d G;
      G.col(0) = X.transpose() * sh.dN_dxi;
      G.col(1) = X.transpose() * sh.dN_deta;
      const Eigen::Vector2d x = X.transpose() * sh.N;
      f += wg[i] * wg[j] * G.determinant() * p(x) * sh.N;
    }
  return f;
}

// Expected moments of the unit-force Hertz pressure p̂ (E[g] = ∫ p̂ g dA) about its centre:
// E[u²] = E[v²] = c²/5, E[u²v²] = c⁴/35, odd moments 0 (∫₀¹ ρ³√(1−ρ²) dρ = 2/15, ∫₀¹ ρ⁵√(1−ρ²) dρ = 8/105).
// For a rectangular element N_a = L_i(ξ(x)) L_j(η(y)) is biquadratic in (u, v), so f_a follows exactly.
Vec9 hertz_on_rectangle_exact(double x0, double y0, double hx, double hy, const Eigen::Vector2d& centre,
                              double c) {
  Vec9 f;
  const auto coeffs = [](double s0, double scale, int node) { // L(s0 + t·scale) = α + β t + γ t²
    // L₋(s) = s(s − 1)/2, L₀ = 1 − s², L₊ = s(s + 1)/2
    const double a2 = node == 0 ? -1.0 : 0.5;
    const double a1 = node == -1 ? -0.5 : node == 0 ? 0.0 : 0.5;
    const double a0 = node == 0 ? 1.0 : 0.0;
    return std::array<double, 3>{a0 + a1 * s0 + a2 * s0 * s0, (a1 + 2.0 * a2 * s0) * scale,
                                 a2 * scale * scale};
  };
  const double xi0 = 2.0 * (centre.x() - x0) / hx - 1.0, eta0 = 2.0 * (centre.y() - y0) / hy - 1.0;
  for (int a = 0; a < 9; ++a) {
    const auto& n = plyimpact::q9_node_coordinates[static_cast<std::size_t>(a)];
    const auto L = coeffs(xi0, 2.0 / hx, static_cast<int>(n[0]));
    const auto M = coeffs(eta0, 2.0 / hy, static_cast<int>(n[1]));
    const double u2 = c * c / 5.0, u2v2 = std::pow(c, 4) / 35.0;
    f(a) = L[0] * M[0] + L[0] * M[2] * u2 + L[2] * M[0] * u2 + L[2] * M[2] * u2v2;
  }
  return f;
}

Eigen::Vector2d first_moment(const Q9NodeCoordinates& X, const Vec9& f) {
  return X.transpose() * f; // Σ_a f_a x_a = ∫ p Σ N_a x_a dA = ∫ p x dA (isoparametric)
}

} // namespace

// A Hertz circle inside a rectangular element: the nine forces equal the closed form from the moments
// of the Hertz pressure, for a tiny circle (c = h/1000) and one nearly filling the element.
TEST(CircleLoad, HertzCircleInsideRectangleEqualsClosedFormMoments) {
  const double x0 = 0.1, y0 = 0.2, hx = 0.004, hy = 0.003;
  for (const auto& [cx, cy, c] : {std::tuple{0.1013, 0.2011, 3e-6}, std::tuple{0.1021, 0.2016, 1.2e-3},
                                  std::tuple{0.1004, 0.2027, 2e-4}}) {
    const Eigen::Vector2d centre(cx, cy);
    const Vec9 f = circle_load(element(x0, y0, hx, hy), plyimpact::hertz_pressure(centre, c, 1.0));
    const Vec9 exact = hertz_on_rectangle_exact(x0, y0, hx, hy, centre, c);
    EXPECT_LE((f - exact).cwiseAbs().maxCoeff(), 1e-13) << c << "\n"
                                                        << f.transpose() << "\n"
                                                        << exact.transpose();
    EXPECT_NEAR(f.sum(), 1.0, 1e-13);
  }
}

// Circle inside a distorted (curved) element: the forces sum to the total force and reproduce the
// first moment ∫ x p dA = F x_c.
TEST(CircleLoad, TotalAndFirstMomentOnADistortedElement) {
  const Q9NodeCoordinates X = element(0.3, 0.5, 0.2, 0.15, wavy);
  const Eigen::Vector2d centre = X.transpose() * plyimpact::q9_shape(0.2, -0.3).N;
  for (const double c : {1e-4, 0.02, 0.05}) {
    const Vec9 f = circle_load(X, plyimpact::hertz_pressure(centre, c, 250.0));
    EXPECT_NEAR(f.sum(), 250.0, 250.0 * 1e-12) << c;
    EXPECT_LE((first_moment(X, f) - 250.0 * centre).norm(), 250.0 * 1e-12) << c;
  }
}

// Four elements sharing a node, circle centred on it: the shares of the unit force sum to 1 to 1e-10
// and are equal (rectangles); with a curved mesh they still sum to 1 and the moment is the centre's.
TEST(CircleLoad, FourElementsAroundANodeShareTheWholeForce) {
  const double h = 0.004, c = 0.0006;
  const Eigen::Vector2d node(0.05, 0.03);
  double total = 0.0;
  for (const auto& [i, j] : {std::pair{-1, -1}, std::pair{0, -1}, std::pair{-1, 0}, std::pair{0, 0}}) {
    const Vec9 f = circle_load(element(node.x() + i * h, node.y() + j * h, h, h),
                               plyimpact::hertz_pressure(node, c, 1.0));
    EXPECT_NEAR(f.sum(), 0.25, 1e-13);
    total += f.sum();
  }
  EXPECT_NEAR(total, 1.0, 1e-10);

  const Eigen::Vector2d curved_node = wavy(node);
  double curved_total = 0.0;
  Eigen::Vector2d moment = Eigen::Vector2d::Zero();
  for (const auto& [i, j] : {std::pair{-1, -1}, std::pair{0, -1}, std::pair{-1, 0}, std::pair{0, 0}}) {
    const Q9NodeCoordinates X = element(node.x() + i * h, node.y() + j * h, h, h, wavy);
    const Vec9 f = circle_load(X, plyimpact::hertz_pressure(curved_node, c, 1.0));
    curved_total += f.sum();
    moment += first_moment(X, f);
  }
  EXPECT_NEAR(curved_total, 1.0, 1e-10);
  EXPECT_LE((moment - curved_node).norm(), 1e-12);
}

// A circle much larger than the element: every point of the element is loaded, so the forces are the
// consistent pressure load p ∫ N_a dA (6×6 Gauss), also for a curved element.
TEST(CircleLoad, LargeUniformCircleGivesTheConsistentPressureLoad) {
  for (const bool curved : {false, true}) {
    const Q9NodeCoordinates X =
        curved ? element(0.3, 0.5, 0.02, 0.015, wavy) : element(0.3, 0.5, 0.02, 0.015);
    const Eigen::Vector2d centre(0.27, 0.49);
    const Vec9 f = circle_load(X, plyimpact::uniform_pressure(centre, 0.5, 2.0e5));
    const Vec9 expected = element_integral(X, [](const Eigen::Vector2d&) { return 2.0e5; });
    EXPECT_LE((f - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff()) << curved;
    // And the Hertz profile over the same large circle: the nodal forces of p(r) itself.
    const auto hertz = plyimpact::hertz_pressure(centre, 0.5, 1.0e4);
    const Vec9 fh = circle_load(X, hertz);
    const Vec9 eh =
        element_integral(X, [&](const Eigen::Vector2d& x) { return hertz.pressure((x - centre).norm()); });
    EXPECT_LE((fh - eh).cwiseAbs().maxCoeff(), 1e-10 * eh.cwiseAbs().maxCoeff()) << curved;
  }
}

// A Hertz circle cut by one straight element edge, the element on the side u = x − x_c > d (d < 0:
// the centre is inside): the element carries F (½ − ¾ d/c + ¼ (d/c)³) with first moment
// ∫ u p dA = 3F (c² − d²)²/(16 c³) (∫ p0 √(c² − u² − v²)/c dv = p0 π (c² − u²)/(2c), then integrate in u).
TEST(CircleLoad, CircleStraddlingAnEdgeLoadsTheElementWithTheSegmentForce) {
  const double h = 0.01, c = 0.002;
  const Q9NodeCoordinates X = element(0.0, 0.0, h, h);
  for (const double d : {-0.0015, -0.0005, 0.0, 0.0007, 0.0019}) {
    const Eigen::Vector2d centre(-d, 0.5 * h); // the edge x = 0 lies at distance d on the +x side
    const Vec9 f = circle_load(X, plyimpact::hertz_pressure(centre, c, 1.0));
    const double s = d / c;
    EXPECT_NEAR(f.sum(), 0.5 - 0.75 * s + 0.25 * s * s * s, 1e-12) << d;
    const double moment = 3.0 * (c * c - d * d) * (c * c - d * d) / (16.0 * c * c * c);
    const double mx = first_moment(X, f).x() - centre.x() * f.sum(); // ∫ (x − x_c) p dA
    EXPECT_NEAR(mx, moment, 1e-12 * c) << d;
  }
}

// Two curved elements sharing a curved edge, circle across it: their loads add up to the whole force
// and its moment, i.e. the clipping along the curved edge is the same from both sides.
TEST(CircleLoad, TwoCurvedElementsShareACurvedEdgeExactly) {
  const double h = 0.01;
  const Q9NodeCoordinates left = element(0.0, 0.0, h, h, wavy), right = element(h, 0.0, h, h, wavy);
  const Eigen::Vector2d centre = right.transpose() * plyimpact::q9_shape(-0.85, 0.1).N;
  const double c = 0.0025;
  const auto load = plyimpact::hertz_pressure(centre, c, 1.0);
  const Vec9 fl = circle_load(left, load), fr = circle_load(right, load);
  EXPECT_GT(fl.sum(), 0.05);
  EXPECT_GT(fr.sum(), 0.5);
  EXPECT_NEAR(fl.sum() + fr.sum(), 1.0, 1e-11);
  EXPECT_LE((first_moment(left, fl) + first_moment(right, fr) - centre).norm(), 1e-12);
}

// The quadrature converges fast in both orders: on the straddling case the error falls by orders of
// magnitude per doubling, and the defaults are within 1e-13 of the exact share.
TEST(CircleLoad, QuadratureOrdersConverge) {
  const double h = 0.01, c = 0.002, d = 0.0007;
  const Q9NodeCoordinates X = element(0.0, 0.0, h, h, {});
  const Eigen::Vector2d centre(-d, 0.3 * h);
  const double s = d / c, exact = 0.5 - 0.75 * s + 0.25 * s * s * s;
  std::vector<double> error;
  for (const int n : {4, 8, 16, 32}) {
    const Vec9 f = circle_load(X, plyimpact::hertz_pressure(centre, c, 1.0), CircleQuadrature{n, n});
    error.push_back(std::abs(f.sum() - exact));
  }
  EXPECT_LT(error[1], 0.1 * error[0]);
  EXPECT_LT(error[2], 1e-2 * error[1] + 1e-15);
  EXPECT_LT(error[3], 1e-13);
  EXPECT_LT(std::abs(circle_load(X, plyimpact::hertz_pressure(centre, c, 1.0)).sum() - exact), 1e-13);
}

TEST(CircleLoad, RejectsInvalidInput) {
  const Q9NodeCoordinates X = element(0.0, 0.0, 1.0, 1.0);
  EXPECT_THROW((void)circle_load(X, plyimpact::hertz_pressure({0.5, 0.5}, 0.0, 1.0)), std::invalid_argument);
  EXPECT_THROW((void)circle_load(X, plyimpact::hertz_pressure({0.5, 0.5}, 0.1, 1.0), CircleQuadrature{0, 8}),
               std::invalid_argument);
}

} // namespace circle_load_tests
