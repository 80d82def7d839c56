#pragma once
// 9-node Lagrange quadrilateral (thesis 2.6.5.2). Local node order:
//
//   3 ---- 6 ---- 2        η
//   |             |        ^
//   7      8      5        |
//   |             |        +--> ξ
//   0 ---- 4 ---- 1
//
// corners 0–3 counter-clockwise from (−1, −1), mid-sides 4–7, centre 8.
#include <Eigen/Core>
#include <array>

namespace plyimpact {

inline constexpr int q9_nodes = 9;

/// (ξ, η) of the nine local nodes.
inline constexpr std::array<std::array<double, 2>, 9> q9_node_coordinates{
    {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1}, {1, 0}, {0, 1}, {-1, 0}, {0, 0}}};

/// Shape function values N_a and their derivatives with respect to ξ and η at one point.
struct Q9Shape {
  Eigen::Matrix<double, 9, 1> N;
  Eigen::Matrix<double, 9, 1> dN_dxi;
  Eigen::Matrix<double, 9, 1> dN_deta;
};

[[nodiscard]] Q9Shape q9_shape(double xi, double eta);

} // namespace plyimpact
