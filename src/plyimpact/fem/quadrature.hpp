#pragma once
// One-dimensional quadrature rules on [−1, 1]; 2-D rules are their tensor products.
#include <array>
#include <cstddef>

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

} // namespace plyimpact
