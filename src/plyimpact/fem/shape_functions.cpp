#include "plyimpact/fem/shape_functions.hpp"

namespace plyimpact {

namespace {

/// 1-D quadratic Lagrange polynomials through −1, 0, 1 and their derivatives.
struct Lagrange3 {
  std::array<double, 3> L, dL; // index 0 ↔ node −1, 1 ↔ node 0, 2 ↔ node +1
};

Lagrange3 lagrange3(double s) {
  return {{0.5 * s * (s - 1.0), 1.0 - s * s, 0.5 * s * (s + 1.0)}, {s - 0.5, -2.0 * s, s + 0.5}};
}

/// Index (0, 1, 2) of a local node coordinate −1, 0, 1.
constexpr int slot(double c) {
  return c < -0.5 ? 0 : (c > 0.5 ? 2 : 1);
}

} // namespace

Q9Shape q9_shape(double xi, double eta) {
  const Lagrange3 lx = lagrange3(xi);
  const Lagrange3 ly = lagrange3(eta);
  Q9Shape s;
  for (int a = 0; a < 9; ++a) {
    const int i = slot(q9_node_coordinates[static_cast<std::size_t>(a)][0]);
    const int j = slot(q9_node_coordinates[static_cast<std::size_t>(a)][1]);
    s.N(a) = lx.L[static_cast<std::size_t>(i)] * ly.L[static_cast<std::size_t>(j)];
    s.dN_dxi(a) = lx.dL[static_cast<std::size_t>(i)] * ly.L[static_cast<std::size_t>(j)];
    s.dN_deta(a) = lx.L[static_cast<std::size_t>(i)] * ly.dL[static_cast<std::size_t>(j)];
  }
  return s;
}

} // namespace plyimpact
