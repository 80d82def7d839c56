#include "plyimpact/laminate/ply_stiffness.hpp"

#include <cmath>
#include <numbers>

namespace plyimpact {

Eigen::Matrix3d reduced_stiffness(const Material& m, ReducedStiffnessModel model) {
  Eigen::Matrix3d Q = Eigen::Matrix3d::Zero();
  if (model == ReducedStiffnessModel::poisson_free) {
    Q(0, 0) = m.E1;
    Q(1, 1) = m.E2;
  } else {
    const double denom = 1.0 - m.nu12 * m.nu21(); // (1.3)
    Q(0, 0) = m.E1 / denom;
    Q(1, 1) = m.E2 / denom;
    Q(0, 1) = Q(1, 0) = m.nu12 * m.E2 / denom;
  }
  Q(2, 2) = m.G12;
  return Q;
}

Eigen::Matrix2d transverse_shear_stiffness(const Material& m) {
  Eigen::Matrix2d G = Eigen::Matrix2d::Zero();
  G(0, 0) = m.G23; // Q44 (yz)
  G(1, 1) = m.G13; // Q55 (xz)
  return G;
}

CosSin cos_sin_degrees(double angle_deg) {
  const double quarter_turns = angle_deg / 90.0;
  if (quarter_turns == std::round(quarter_turns)) {
    constexpr CosSin exact[4] = {{1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}, {0.0, -1.0}};
    const auto q = static_cast<long>(std::round(quarter_turns));
    return exact[((q % 4) + 4) % 4];
  }
  const double rad = angle_deg * std::numbers::pi / 180.0;
  return {std::cos(rad), std::sin(rad)};
}

Eigen::Matrix3d rotate_in_plane(const Eigen::Matrix3d& Q, double angle_deg) {
  const auto [c, s] = cos_sin_degrees(angle_deg);
  const double c2 = c * c, s2 = s * s, c4 = c2 * c2, s4 = s2 * s2, s2c2 = s2 * c2;
  const double Q11 = Q(0, 0), Q12 = Q(0, 1), Q22 = Q(1, 1), Q66 = Q(2, 2);
  Eigen::Matrix3d Qb;
  // (1.12), with the Q̄22 misprint of the thesis corrected (SPEC §2).
  Qb(0, 0) = Q11 * c4 + 2.0 * (Q12 + 2.0 * Q66) * s2c2 + Q22 * s4;
  Qb(1, 1) = Q11 * s4 + 2.0 * (Q12 + 2.0 * Q66) * s2c2 + Q22 * c4;
  Qb(0, 1) = (Q11 + Q22 - 4.0 * Q66) * s2c2 + Q12 * (s4 + c4);
  Qb(0, 2) = (Q11 - Q12 - 2.0 * Q66) * c2 * c * s + (Q12 - Q22 + 2.0 * Q66) * s2 * s * c;
  Qb(1, 2) = (Q11 - Q12 - 2.0 * Q66) * c * s2 * s + (Q12 - Q22 + 2.0 * Q66) * s * c2 * c;
  Qb(2, 2) = (Q11 + Q22 - 2.0 * Q12 - 2.0 * Q66) * s2c2 + Q66 * (s4 + c4);
  Qb(1, 0) = Qb(0, 1);
  Qb(2, 0) = Qb(0, 2);
  Qb(2, 1) = Qb(1, 2);
  return Qb;
}

Eigen::Matrix2d rotate_transverse_shear(const Eigen::Matrix2d& G, double angle_deg) {
  const auto [c, s] = cos_sin_degrees(angle_deg);
  const double Q44 = G(0, 0), Q55 = G(1, 1);
  Eigen::Matrix2d Gb;
  Gb(0, 0) = Q44 * c * c + Q55 * s * s;
  Gb(1, 1) = Q55 * c * c + Q44 * s * s;
  Gb(0, 1) = Gb(1, 0) = (Q55 - Q44) * c * s;
  return Gb;
}

} // namespace plyimpact
