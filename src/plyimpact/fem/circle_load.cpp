#include "plyimpact/fem/circle_load.hpp"

#include "plyimpact/fem/shape_functions.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace plyimpact {

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

/// One element edge, x(s) = A s² + B s + C for s ∈ [−1, 1] (corner, mid-side node, corner).
struct Edge {
  Eigen::Vector2d A, B, C;
  [[nodiscard]] Eigen::Vector2d at(double s) const { return (A * s + B) * s + C; }
  [[nodiscard]] Eigen::Vector2d tangent(double s) const { return 2.0 * A * s + B; }
};

/// The four edges counter-clockwise: η = −1 (0-4-1), ξ = +1 (1-5-2), η = +1 (2-6-3), ξ = −1 (3-7-0).
std::array<Edge, 4> element_edges(const Q9NodeCoordinates& X) {
  constexpr std::array<std::array<int, 3>, 4> nodes{{{0, 4, 1}, {1, 5, 2}, {2, 6, 3}, {3, 7, 0}}};
  std::array<Edge, 4> edges;
  for (std::size_t k = 0; k < 4; ++k) {
    const Eigen::Vector2d start = X.row(nodes[k][0]).transpose(), mid = X.row(nodes[k][1]).transpose(),
                          end = X.row(nodes[k][2]).transpose();
    // Quadratic Lagrange interpolation through s = −1, 0, 1 written in powers of s.
    edges[k] = Edge{0.5 * (start + end) - mid, 0.5 * (end - start), mid};
  }
  return edges;
}

/// The real roots of a polynomial of degree 4 at most, kept without allocating (the circle-load table of
/// an impact asks for them tens of thousands of times: 47 496 in bench/README.md's graded run).
class Roots {
public:
  void push_back(double s) { value_.at(count_++) = s; }
  [[nodiscard]] const double* begin() const { return value_.data(); }
  [[nodiscard]] const double* end() const { return value_.data() + count_; }

private:
  std::array<double, 4> value_{};
  std::size_t count_ = 0;
};

/// Real roots in [−1, 1] of Σ c_k s^k, degree ≤ 4 (companion matrix, then Newton polish on the
/// polynomial). The matrices have a fixed capacity: the same arithmetic as dynamic ones, no allocation.
Roots roots_in_unit_interval(std::initializer_list<double> coefficients) {
  std::array<double, 5> c{};
  std::copy(coefficients.begin(), coefficients.end(), c.begin());
  std::size_t size = coefficients.size();
  const double scale =
      std::max(1e-300, std::abs(*std::max_element(c.begin(), c.begin() + size, [](double x, double y) {
                 return std::abs(x) < std::abs(y);
               })));
  while (size > 1 && std::abs(c[size - 1]) <= 1e-13 * scale)
    --size; // lower the degree
  const auto degree = static_cast<Eigen::Index>(size) - 1;
  Roots roots;
  if (degree < 1) return roots;
  using Companion = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 4, 4>;
  Companion companion = Companion::Zero(degree, degree);
  for (Eigen::Index i = 0; i < degree; ++i) {
    companion(0, i) = -c[static_cast<std::size_t>(degree - 1 - i)] / c[size - 1];
    if (i + 1 < degree) companion(i + 1, i) = 1.0;
  }
  const Eigen::EigenSolver<Companion> eig(companion, false);
  const auto value = [&](double s) {
    double v = 0.0, d = 0.0;
    for (std::size_t k = size; k-- > 0;) {
      d = d * s + v;
      v = v * s + c[k];
    }
    return std::pair{v, d};
  };
  for (Eigen::Index i = 0; i < degree; ++i) {
    const std::complex<double> z = eig.eigenvalues()(i);
    if (std::abs(z.imag()) > 1e-7 * (1.0 + std::abs(z.real()))) continue;
    double s = z.real();
    for (int it = 0; it < 3; ++it) {
      const auto [v, d] = value(s);
      if (d == 0.0) break;
      s -= v / d;
    }
    if (s >= -1.0 - 1e-12 && s <= 1.0 + 1e-12) roots.push_back(std::clamp(s, -1.0, 1.0));
  }
  return roots;
}

/// n-point Gauss–Legendre rule on [0, 1] (Newton on the Legendre polynomial P_n).
struct Rule {
  std::vector<double> x, w;
};
Rule gauss_legendre_01(int n) {
  Rule r;
  for (int i = 0; i < n; ++i) {
    double t = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = t;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * t * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (t * p1 - p0) / (t * t - 1.0);
      const double step = p1 / dp;
      t -= step;
      if (std::abs(step) < 1e-16) break;
    }
    r.x.push_back(0.5 * (1.0 - t));
    r.w.push_back(1.0 / ((1.0 - t * t) * dp * dp));
  }
  return r;
}

/// Sigmoidal change of variable θ = θa + (θb − θa) S(u), S(u) = u²/(u² + (1 − u)²), S' = 2u(1 − u)/(…)²:
/// θ − θa ∝ u² near u = 0, so an endpoint behaviour (θ − θa)^(k/2) becomes u^(k+1) — analytic. Every
/// endpoint behaviour here is a half-integer power (√ where a ray touches a curved edge, ^(3/2) where
/// an edge crosses the edge of a Hertz circle, kinks at corners), and Gauss–Legendre converges
/// exponentially on each interval.
std::pair<double, double> sigmoid(double u) {
  const double p = u * u, q = (1.0 - u) * (1.0 - u), den = p + q;
  return {p / den, 2.0 * u * (1.0 - u) / (den * den)};
}

/// Inverse isoparametric map by Newton from `start`; empty if it does not converge.
std::optional<Eigen::Vector2d> parent_coordinates(const Q9NodeCoordinates& X, const Eigen::Vector2d& x,
                                                  Eigen::Vector2d xi) {
  for (int it = 0; it < 60; ++it) {
    const Q9Shape sh = q9_shape(xi.x(), xi.y());
    const Eigen::Vector2d residual = x - X.transpose() * sh.N;
    Eigen::Matrix2d G; // ∂(x, y)/∂(ξ, η)
    G.col(0) = X.transpose() * sh.dN_dxi;
    G.col(1) = X.transpose() * sh.dN_deta;
    const double det = G.determinant();
    if (!(std::abs(det) > 0.0)) return std::nullopt;
    const Eigen::Matrix2d G_inv = G.inverse();
    Eigen::Vector2d step = G_inv * residual;
    if (step.norm() > 1.0) step *= 1.0 / step.norm(); // damped far from the element
    xi += step;
    // Quadratic convergence: after a step below 1e-10 the error is at the round-off level — unless the
    // element is so small against its coordinates that their round-off alone is more, in ξ (µm elements
    // 75 mm from the origin): then that floor.
    const double round_off =
        16.0 * std::numeric_limits<double>::epsilon() * X.cwiseAbs().maxCoeff() * G_inv.norm();
    if (step.norm() <= std::max(1e-10, round_off)) return xi;
  }
  return std::nullopt;
}

bool inside_parent(const Eigen::Vector2d& xi) {
  return std::abs(xi.x()) <= 1.0 + 1e-12 && std::abs(xi.y()) <= 1.0 + 1e-12;
}

class CircleOnElement {
public:
  CircleOnElement(const Q9NodeCoordinates& X, const CircularPressure& load, const CircleQuadrature& q)
      : X_(X), load_(load), edges_(element_edges(X)), angular_(gauss_legendre_01(q.angular_points)),
        radial_(gauss_legendre_01(q.radial_points)) {
    for (int i = 0; i < 9; ++i)
      for (int j = 0; j < 9; ++j)
        length_ = std::max(length_, (X.row(i) - X.row(j)).norm());
  }

  Eigen::Matrix<double, 9, 1> integrate() const {
    Eigen::Matrix<double, 9, 1> f = Eigen::Matrix<double, 9, 1>::Zero();
    std::vector<double> cuts = breakpoints();
    if (cuts.empty()) cuts.push_back(0.0);
    for (std::size_t k = 0; k < cuts.size(); ++k) {
      const double ta = cuts[k], tb = k + 1 < cuts.size() ? cuts[k + 1] : cuts.front() + two_pi;
      if (tb - ta <= 1e-15) continue;
      for (std::size_t i = 0; i < angular_.x.size(); ++i) {
        const auto [s, ds] = sigmoid(angular_.x[i]);
        f += (angular_.w[i] * ds * (tb - ta)) * along_ray(ta + (tb - ta) * s);
      }
    }
    return f;
  }

private:
  /// Angles where the angular integrand is not smooth, sorted in [0, 2π): rays through a corner node,
  /// rays tangent to an edge (including both edge directions where the centre lies on an edge), and
  /// rays to the points where an edge crosses the circle.
  std::vector<double> breakpoints() const {
    const Eigen::Vector2d P = load_.centre;
    const double c = load_.radius, tiny = 1e-12 * length_;
    std::vector<double> angles;
    const auto add_direction = [&](const Eigen::Vector2d& d) {
      double t = std::atan2(d.y(), d.x());
      if (t < 0.0) t += two_pi;
      angles.push_back(t);
    };
    for (int i = 0; i < 4; ++i)
      if ((X_.row(i).transpose() - P).norm() > tiny) add_direction(X_.row(i).transpose() - P);
    for (const Edge& e : edges_) {
      const Eigen::Vector2d C = e.C - P;
      // Tangency: (x(s) − P) × x'(s) = −(A×B) s² + 2 (C'×A) s + C'×B = 0.
      for (const double s : roots_in_unit_interval({cross(C, e.B), 2.0 * cross(C, e.A), -cross(e.A, e.B)})) {
        const Eigen::Vector2d d = e.at(s) - P;
        if (d.norm() > tiny) {
          add_direction(d);
        } else { // the centre lies on this edge: the edge's two directions bound the element there
          add_direction(e.tangent(s));
          add_direction(-e.tangent(s));
        }
      }
      // Circle crossing: |x(s) − P|² − c² = 0, a quartic in s.
      for (const double s :
           roots_in_unit_interval({C.dot(C) - c * c, 2.0 * e.B.dot(C), e.B.dot(e.B) + 2.0 * e.A.dot(C),
                                   2.0 * e.A.dot(e.B), e.A.dot(e.A)}))
        add_direction(e.at(s) - P);
    }
    std::sort(angles.begin(), angles.end());
    angles.erase(std::unique(angles.begin(), angles.end(), [](double x, double y) { return y - x <= 1e-14; }),
                 angles.end());
    if (angles.size() > 1 && angles.back() - angles.front() >= two_pi - 1e-14) angles.pop_back();
    return angles;
  }

  /// ∫ p(r) N_a r dr along the ray θ, over the parts of [0, c] inside the element.
  Eigen::Matrix<double, 9, 1> along_ray(double theta) const {
    const Eigen::Vector2d P = load_.centre, d(std::cos(theta), std::sin(theta));
    const double c = load_.radius;
    std::vector<double> r{0.0};
    for (const Edge& e : edges_) {
      const Eigen::Vector2d C = e.C - P;
      for (const double s : roots_in_unit_interval({cross(d, C), cross(d, e.B), cross(d, e.A)})) {
        const double rho = d.dot(e.at(s) - P);
        if (rho > 1e-12 * length_ && rho < c) r.push_back(rho);
      }
    }
    r.push_back(c);
    std::sort(r.begin(), r.end());
    Eigen::Matrix<double, 9, 1> f = Eigen::Matrix<double, 9, 1>::Zero();
    Eigen::Vector2d xi = Eigen::Vector2d::Zero();
    for (std::size_t k = 0; k + 1 < r.size(); ++k) {
      if (r[k + 1] - r[k] <= 1e-14 * c) continue;
      const auto mid = parent_coordinates(X_, P + 0.5 * (r[k] + r[k + 1]) * d, xi);
      if (!mid || !inside_parent(*mid)) continue;
      xi = *mid;
      // r = c sin φ: the radial integrand p(r) r dr = p(c sin φ) c² sin φ cos φ dφ is analytic for Hertz.
      const double pa = std::asin(std::min(r[k] / c, 1.0)), pb = std::asin(std::min(r[k + 1] / c, 1.0));
      for (std::size_t i = 0; i < radial_.x.size(); ++i) {
        const double phi = pa + (pb - pa) * radial_.x[i];
        const double rho = c * std::sin(phi);
        const auto xi_point = parent_coordinates(X_, P + rho * d, xi);
        if (!xi_point) throw std::runtime_error("circle_load: inverse isoparametric map did not converge");
        xi = *xi_point;
        const double weight = radial_.w[i] * (pb - pa) * load_.pressure(rho) * rho * c * std::cos(phi);
        f += weight * q9_shape(xi.x(), xi.y()).N;
      }
    }
    return f;
  }

  const Q9NodeCoordinates& X_;
  const CircularPressure& load_;
  std::array<Edge, 4> edges_;
  Rule angular_, radial_;
  double length_ = 0.0;
};

} // namespace

CircularPressure hertz_pressure(const Eigen::Vector2d& centre, double radius, double force) {
  const double p0 = 3.0 * force / (2.0 * std::numbers::pi * radius * radius);
  return {centre, radius, [p0, radius](double r) {
            const double s = r / radius;
            return s < 1.0 ? p0 * std::sqrt(1.0 - s * s) : 0.0;
          }};
}

CircularPressure flat_punch_pressure(const Eigen::Vector2d& centre, double radius, double force) {
  const double c = force / (2.0 * std::numbers::pi * radius * radius);
  return {centre, radius, [c, radius](double r) {
            const double s = r / radius;
            return s < 1.0 ? c / std::sqrt(1.0 - s * s) : 0.0;
          }};
}

CircularPressure cone_pressure(const Eigen::Vector2d& centre, double radius, double force) {
  const double mean = force / (std::numbers::pi * radius * radius);
  return {centre, radius, [mean, radius](double r) {
            const double s = r / radius;
            return s < 1.0 ? mean * std::acosh(1.0 / std::max(s, 1e-300)) : 0.0;
          }};
}

CircularPressure uniform_pressure(const Eigen::Vector2d& centre, double radius, double pressure) {
  return {centre, radius, [pressure, radius](double r) { return r <= radius ? pressure : 0.0; }};
}

Eigen::Matrix<double, 9, 1> circle_load(const Q9NodeCoordinates& nodes, const CircularPressure& load,
                                        const CircleQuadrature& quadrature) {
  if (!(load.radius > 0.0)) throw std::invalid_argument("circle_load: the radius must be positive");
  if (quadrature.angular_points < 1 || quadrature.radial_points < 1)
    throw std::invalid_argument("circle_load: quadrature orders must be at least 1");
  if (!load.pressure) throw std::invalid_argument("circle_load: no pressure profile");
  return CircleOnElement(nodes, load, quadrature).integrate();
}

} // namespace plyimpact
