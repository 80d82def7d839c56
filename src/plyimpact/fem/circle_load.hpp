#pragma once
// Consistent nodal forces of a pressure distributed over a circle, for one 9-node element (issue 16):
//
//     f_a = ∫_{circle ∩ element} p(r) N_a dA,       a = 0..8 (node order of shape_functions.hpp),
//
// accurate whether the circle is tiny inside the element, much larger than it, or straddles its
// edges and corners; the element may be distorted (curved edges through its mid-side nodes).
//
// Method: polar integration around the circle's centre, clipped by the element boundary, in physical
// coordinates (x = x0 + r cos θ, y = y0 + r sin θ):
//   * each ray θ meets the four element edges (quadratic curves through corner, mid-side, corner) where
//     a quadratic in the edge parameter vanishes; the pieces of the ray between crossings lie wholly
//     inside or outside the element (classified by the inverse isoparametric map at their midpoints);
//   * the angular integrand I(θ) is smooth except where the ray passes an element corner, touches a
//     curved edge, or crosses an edge exactly on the circle; these angles split [0, 2π) into
//     intervals, each integrated by Gauss–Legendre after the change of variable θ − θa ∝ u² at
//     both ends, which makes the half-integer-power behaviour there analytic (√ at a tangent ray,
//     (θ − θ*)^(3/2) where an edge crosses the rim of a Hertz circle);
//   * along a ray, r = c sin φ: the √(1 − r²/c²) edge of a Hertz profile becomes cos φ and the
//     radial integrand is analytic, so Gauss–Legendre in φ converges exponentially;
//   * N_a at each point comes from the inverse isoparametric map (Newton).
// Convergence is exponential in the number of points (tests/fem/test_circle_load.cpp measures it);
// the defaults reach about 1e-12 of the total force.
//
// Independent of any mesh class: the caller passes one element's node coordinates.
#include <Eigen/Core>

#include <functional>

namespace plyimpact {

/// Coordinates of the nine nodes of one element (rows in the local node order of shape_functions.hpp).
using Q9NodeCoordinates = Eigen::Matrix<double, 9, 2>;

/// A pressure p(r) over the circle of centre `centre` and radius `radius` (p = 0 for r > radius).
/// p should be smooth on [0, radius); a square-root edge (Hertz) or a jump at r = radius (uniform)
/// is handled exactly by the radial change of variable.
struct CircularPressure {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero(); ///< [m]
  double radius = 0.0;                              ///< [m]
  std::function<double(double)> pressure;           ///< p(r) [Pa], r in [0, radius]
};

/// Hertz pressure of resultant `force` over the contact circle of radius c:
/// p(r) = p0 √(1 − r²/c²), p0 = 3F/(2πc²) (Johnson, Contact Mechanics, 1985, eq. 4.23).
[[nodiscard]] CircularPressure hertz_pressure(const Eigen::Vector2d& centre, double radius, double force);
/// Pressure under a rigid flat-ended punch of radius c pressed with `force` (Boussinesq; Johnson, Contact
/// Mechanics, 1985): p(r) = F / (2π c √(c² − r²)), unbounded at the rim, integrable.
[[nodiscard]] CircularPressure flat_punch_pressure(const Eigen::Vector2d& centre, double radius,
                                                   double force);
/// Pressure under a rigid cone whose contact circle has radius c (Sneddon 1965; Johnson 1985):
/// p(r) = F/(π c²) · arccosh(c/r), logarithmic at the tip, integrable.
[[nodiscard]] CircularPressure cone_pressure(const Eigen::Vector2d& centre, double radius, double force);
/// Uniform pressure p over the circle.
[[nodiscard]] CircularPressure uniform_pressure(const Eigen::Vector2d& centre, double radius,
                                                double pressure);

/// Quadrature of circle_load: Gauss points per angular interval and per radial segment.
struct CircleQuadrature {
  int angular_points = 32;
  int radial_points = 16;
};

/// f_a = ∫_{circle ∩ element} p(r) N_a dA [N] for the element with the given node coordinates.
/// Throws std::invalid_argument for a non-positive radius or quadrature orders below 1.
[[nodiscard]] Eigen::Matrix<double, 9, 1> circle_load(const Q9NodeCoordinates& nodes,
                                                      const CircularPressure& load,
                                                      const CircleQuadrature& quadrature = {});

} // namespace plyimpact
