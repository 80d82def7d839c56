#pragma once
// The quadrature rules of the plate elements, in one place: one-dimensional rules on [−1, 1] and
// their tensor products on the parent square [−1, 1]².
#include <array>
#include <cstddef>
#include <utility>

namespace plyimpact {

template <std::size_t N>
struct QuadratureRule1D {
  std::array<double, N> points;
  std::array<double, N> weights;
};

/// 2-point Gauss–Legendre (exact to degree 3): transverse shear, reduced (2×2).
inline constexpr QuadratureRule1D<2> gauss2{{-0.57735026918962576451, 0.57735026918962576451}, {1.0, 1.0}};

/// 3-point Gauss–Legendre (exact to degree 5): membrane, coupling, bending, consistent mass (3×3).
/// Point order ξ = −√0.6, 0, +√0.6 (the thesis's IPGS/JPGS = 1, 2, 3).
inline constexpr QuadratureRule1D<3> gauss3{{-0.77459666924148337704, 0.0, 0.77459666924148337704},
                                            {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0}};

/// 3-point Gauss–Lobatto (nodes −1, 0, 1; weights 1/3, 4/3, 1/3): diagonal mass (thesis (3.7)/(3.8)).
inline constexpr QuadratureRule1D<3> lobatto3{{-1.0, 0.0, 1.0}, {1.0 / 3.0, 4.0 / 3.0, 1.0 / 3.0}};

/// The part of [−1, 1] that point k of a rule stands for: the rule's weights laid end to end from −1
/// (they add up to 2), so that the interval's length is the point's weight and the intervals tile [−1, 1]
/// in the order of the points (for the rules above each interval contains its point).
template <std::size_t N>
constexpr std::pair<double, double> tributary_interval(const QuadratureRule1D<N>& r, std::size_t k) {
  double start = -1.0;
  for (std::size_t i = 0; i < k; ++i)
    start += r.weights[i];
  return {start, k + 1 == N ? 1.0 : start + r.weights[k]}; // the last ends at 1 exactly, not 1 + round-off
}

/// A point of a tensor-product rule: parent coordinates, weight w_i w_j, and its indices i along ξ and
/// j along η (0-based; the thesis's IPGS = i + 1, JPGS = j + 1).
struct QuadraturePoint {
  double xi = 0.0, eta = 0.0, weight = 0.0;
  int i = 0, j = 0;
};

/// The N × N tensor product of a 1-D rule, i (ξ) outer and j (η) inner.
template <std::size_t N>
constexpr std::array<QuadraturePoint, N * N> tensor_product(const QuadratureRule1D<N>& r) {
  std::array<QuadraturePoint, N * N> rule{};
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j)
      rule[N * i + j] = {r.points[i], r.points[j], r.weights[i] * r.weights[j], static_cast<int>(i),
                         static_cast<int>(j)};
  return rule;
}

inline constexpr auto gauss2x2 = tensor_product(gauss2);
inline constexpr auto gauss3x3 = tensor_product(gauss3);

/// Position of point (i, j) of the 3×3 Gauss rule in gauss3x3.
constexpr std::size_t gauss3x3_index(int i, int j) {
  return 3 * static_cast<std::size_t>(i) + static_cast<std::size_t>(j);
}

} // namespace plyimpact
