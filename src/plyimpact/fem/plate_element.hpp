#pragma once
// The 9-node Mindlin laminated plate element (SPEC §3; thesis 2.6–2.9).
//
// Nodal DOFs (u, v, w, θx, θy), element DOF 5a + d for local node a. Generalized strains (2.73)–(2.77):
//   membrane ε0 = (u,x, v,y, u,y + v,x), curvature κ = (θx,x, θy,y, θx,y + θy,x),
//   transverse shear γ = (γyz, γxz) = (θy + w,y, θx + w,x).
// Resultants (N, M) = [[A, B], [B, D]] (ε0, κ) and (Qy, Qx) = F γ with F in order (yz, xz).
#include "plyimpact/fem/mesh.hpp"
#include "plyimpact/fem/mesh_spec.hpp"
#include "plyimpact/fem/shape_functions.hpp"
#include "plyimpact/laminate/laminate.hpp"

#include <Eigen/Core>

namespace plyimpact {

inline constexpr int dofs_per_node = 5;
inline constexpr int q9_dofs = 45;

using ElementMatrix = Eigen::Matrix<double, q9_dofs, q9_dofs>;
using ElementVector = Eigen::Matrix<double, q9_dofs, 1>;
using MembraneBendingB = Eigen::Matrix<double, 6, q9_dofs>; ///< rows ε0 (3), κ (3)
using ShearB = Eigen::Matrix<double, 2, q9_dofs>;           ///< rows γyz, γxz

/// Shape functions with physical derivatives at one point of an element (2.78)–(2.82).
struct PointKinematics {
  Q9Shape shape;
  Eigen::Matrix<double, 9, 1> dN_dx, dN_dy;
  double detJ = 0.0;
};

/// Throws std::domain_error when the element is inverted or degenerate (det J ≤ 0).
[[nodiscard]] PointKinematics point_kinematics(const ElementCoordinates& xy, double xi, double eta);
[[nodiscard]] MembraneBendingB membrane_bending_B(const PointKinematics& k);
[[nodiscard]] ShearB shear_B(const PointKinematics& k);

/// Generalized strains at a point: ε0, κ (membrane, bending) and γ (yz, xz).
struct GeneralizedStrains {
  Eigen::Vector3d membrane;
  Eigen::Vector3d curvature;
  Eigen::Vector2d shear;
};

class MindlinQ9 {
public:
  /// `formulation` must be q9 or mitc9 (resolve `automatic` first, see resolve_formulation).
  explicit MindlinQ9(const Laminate& laminate, ElementFormulation formulation = ElementFormulation::q9);

  /// Ke = ∫ B_Lᵀ C B_L dA: 3×3 Gauss for membrane/coupling/bending, 2×2 Gauss for shear (q9), or
  /// MITC9 assumed shear strains (Bucalem & Bathe 1993) integrated 3×3.
  [[nodiscard]] ElementMatrix stiffness(const ElementCoordinates& xy) const;
  /// Me = ∫ Nᵀ m̄ N dA with m̄ of (2.108): consistent (3×3 Gauss) or lumped (3-point Lobatto).
  [[nodiscard]] ElementMatrix mass(const ElementCoordinates& xy, MassMatrix kind) const;
  /// Geometric stiffness of uniform in-plane resultants N = [[Nx, Nxy], [Nxy, Ny]] on w (von Kármán
  /// part of (2.100)): ∫ ∇Nᵀ N ∇N dA on the w DOFs, 3×3 Gauss.
  [[nodiscard]] ElementMatrix geometric_stiffness(const ElementCoordinates& xy,
                                                  const Eigen::Matrix2d& N) const;
  /// Consistent nodal forces of a uniform pressure q (positive along +z) on w, 3×3 Gauss.
  [[nodiscard]] ElementVector pressure_load(const ElementCoordinates& xy, double q) const;
  /// Generalized strains at (ξ, η) from element DOFs (shear as the formulation defines it).
  [[nodiscard]] GeneralizedStrains strains(const ElementCoordinates& xy, const ElementVector& ue, double xi,
                                           double eta) const;

  /// The transverse-shear part of `stiffness` alone: ∫ B_sᵀ F B_s dA with the formulation's shear
  /// interpolation and rule (q9 2×2 Gauss, MITC9 assumed strains 3×3). Used by the non-linear element.
  [[nodiscard]] ElementMatrix shear_stiffness(const ElementCoordinates& xy) const;

  [[nodiscard]] ElementFormulation formulation() const { return formulation_; }

private:
  [[nodiscard]] ShearB assumed_shear_B(const ElementCoordinates& xy, double xi, double eta) const;

  Eigen::Matrix<double, 6, 6> C_mb_; ///< [[A, B], [B, D]]
  Eigen::Matrix2d F_;                ///< (yz, xz)
  std::array<double, 3> inertia_;
  ElementFormulation formulation_;
};

} // namespace plyimpact
