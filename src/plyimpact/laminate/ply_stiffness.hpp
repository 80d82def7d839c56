#pragma once
// Ply stiffness in material and plate axes (SPEC §2; thesis (1.3), (1.10), (1.12)).
#include "plyimpact/laminate/material.hpp"

#include <Eigen/Core>

namespace plyimpact {

/// How the in-plane reduced stiffness Q is formed.
enum class ReducedStiffnessModel {
  exact,        ///< (1.3): Q11 = E1/(1−ν12ν21), Q12 = ν12E2/(1−ν12ν21), ... (default)
  poisson_free, ///< Q11 = E1, Q22 = E2, Q12 = 0: what the thesis's program did (SPEC §2, Annex 2)
};

/// In-plane reduced stiffness Q in material axes, Voigt order (1, 2, 12) (1.3).
[[nodiscard]] Eigen::Matrix3d reduced_stiffness(const Material& m,
                                                ReducedStiffnessModel model = ReducedStiffnessModel::exact);

/// Transverse shear stiffness in material axes, order (23, 13): diag(Q44 = G23, Q55 = G13).
[[nodiscard]] Eigen::Matrix2d transverse_shear_stiffness(const Material& m);

/// cos θ and sin θ of an angle in degrees, exact (0, ±1) at multiples of 90° so that cross-ply
/// laminates have exactly zero A16, D16, ... rather than round-off.
struct CosSin {
  double c, s;
};
[[nodiscard]] CosSin cos_sin_degrees(double angle_deg);

/// Q̄ = Q rotated to plate axes, Voigt order (x, y, xy); θ from x towards y (SPEC §1, (1.10)/(1.12)).
[[nodiscard]] Eigen::Matrix3d rotate_in_plane(const Eigen::Matrix3d& Q, double angle_deg);

/// Rotated transverse shear stiffness, order (yz, xz): Q̄44 = Q44c² + Q55s², Q̄55 = Q55c² + Q44s²,
/// Q̄45 = (Q55 − Q44)cs (SPEC §2).
[[nodiscard]] Eigen::Matrix2d rotate_transverse_shear(const Eigen::Matrix2d& G, double angle_deg);

} // namespace plyimpact
