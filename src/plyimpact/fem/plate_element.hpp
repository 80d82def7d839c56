#pragma once
// The 9-node Mindlin laminated plate element (SPEC §3; thesis 2.6–2.9): the element interface and its
// formulations.
//
// Nodal DOFs (u, v, w, θx, θy), element DOF 5a + d for local node a. Generalized strains (2.73)–(2.77):
//   membrane ε0 = (u,x, v,y, u,y + v,x), curvature κ = (θx,x, θy,y, θx,y + θy,x),
//   transverse shear γ = (γyz, γxz) = (θy + w,y, θx + w,x).
// Resultants (N, M) = [[A, B], [B, D]] (ε0, κ) and (Qy, Qx) = F γ with F in order (yz, xz), taken from
// the element's section (section.hpp).
//
// The formulations differ only in how they interpolate and integrate the transverse shear:
//   q9     (thesis): Lagrange shear strains, reduced 2×2 Gauss integration (selective integration);
//   mitc9  (Bucalem & Bathe 1993): mixed-interpolated tensorial shear components, 3×3 Gauss.
// Everything else (membrane, bending, mass, loads) is common. Stresses and damage are evaluated at the
// 3×3 Gauss points (`stress_points`), from the strains the formulation defines (`strain_operator`).
#include "plyimpact/fem/dof_map.hpp"
#include "plyimpact/fem/mesh.hpp"
#include "plyimpact/fem/mesh_spec.hpp"
#include "plyimpact/fem/quadrature.hpp"
#include "plyimpact/fem/section.hpp"
#include "plyimpact/fem/shape_functions.hpp"

#include <Eigen/Core>
#include <memory>
#include <span>

namespace plyimpact {

using MembraneBendingB = Eigen::Matrix<double, 6, q9_dofs>; ///< rows ε0 (3), κ (3)
using ShearB = Eigen::Matrix<double, 2, q9_dofs>;           ///< rows γyz, γxz
using StrainOperator = Eigen::Matrix<double, 8, q9_dofs>;   ///< rows ε0, κ, γ (yz, xz)

/// Shape functions with physical derivatives at one point of an element (2.78)–(2.82).
struct PointKinematics {
  Q9Shape shape;
  Eigen::Matrix<double, 9, 1> dN_dx, dN_dy;
  double detJ = 0.0;
};

/// Throws std::domain_error when the element is inverted or degenerate (det J ≤ 0).
[[nodiscard]] PointKinematics point_kinematics(const ElementCoordinates& xy, double xi, double eta);
[[nodiscard]] MembraneBendingB membrane_bending_B(const PointKinematics& k);
/// The Lagrange-interpolated transverse shear strains (2.77).
[[nodiscard]] ShearB shear_B(const PointKinematics& k);

/// Generalized strains at a point: ε0, κ (membrane, bending) and γ (yz, xz).
struct GeneralizedStrains {
  Eigen::Vector3d membrane;
  Eigen::Vector3d curvature;
  Eigen::Vector2d shear;
};

class PlateElement {
public:
  virtual ~PlateElement() = default;
  PlateElement() = default;
  PlateElement(const PlateElement&) = delete;
  PlateElement& operator=(const PlateElement&) = delete;

  [[nodiscard]] virtual ElementFormulation formulation() const = 0;

  /// Ke = ∫ B_Lᵀ C B_L dA (2.98) with the section at each integration point.
  [[nodiscard]] virtual ElementMatrix stiffness(const ElementCoordinates& xy,
                                                const ElementSection& s) const = 0;
  /// The transverse-shear part of `stiffness` alone, for a uniform F (the non-linear element adds it).
  [[nodiscard]] virtual ElementMatrix shear_stiffness(const ElementCoordinates& xy,
                                                      const Eigen::Matrix2d& F) const = 0;
  /// (γyz, γxz) at (ξ, η) from the element DOFs, as the formulation interpolates them.
  [[nodiscard]] virtual ShearB shear_operator(const ElementCoordinates& xy, double xi, double eta) const = 0;

  /// Where stresses and damage are evaluated: the 3×3 Gauss points (the thesis's IPGS, JPGS).
  [[nodiscard]] static std::span<const QuadraturePoint> stress_points() { return gauss3x3; }
  /// (ε0, κ, γ) = S uₑ at (ξ, η).
  [[nodiscard]] StrainOperator strain_operator(const ElementCoordinates& xy, double xi, double eta) const;
  [[nodiscard]] GeneralizedStrains strains(const ElementCoordinates& xy, const ElementVector& ue, double xi,
                                           double eta) const;

  /// Me = ∫ Nᵀ m̄ N dA with m̄ of (2.108): consistent (3×3 Gauss) or lumped (3-point Lobatto).
  [[nodiscard]] static ElementMatrix mass(const ElementCoordinates& xy, const std::array<double, 3>& inertia,
                                          MassMatrix kind);
  /// Geometric stiffness of uniform in-plane resultants N = [[Nx, Nxy], [Nxy, Ny]] on w (von Kármán
  /// part of (2.100)): ∫ ∇Nᵀ N ∇N dA on the w DOFs, 3×3 Gauss.
  [[nodiscard]] static ElementMatrix geometric_stiffness(const ElementCoordinates& xy,
                                                         const Eigen::Matrix2d& N);
  /// Consistent nodal forces of a uniform pressure q (positive along +z) on w, 3×3 Gauss.
  [[nodiscard]] static ElementVector pressure_load(const ElementCoordinates& xy, double q);
};

/// q9: 3×3 Gauss for membrane/coupling/bending, 2×2 Gauss for transverse shear (the thesis's element).
class SelectiveQ9 final : public PlateElement {
public:
  [[nodiscard]] ElementFormulation formulation() const override { return ElementFormulation::q9; }
  [[nodiscard]] ElementMatrix stiffness(const ElementCoordinates& xy, const ElementSection& s) const override;
  [[nodiscard]] ElementMatrix shear_stiffness(const ElementCoordinates& xy,
                                              const Eigen::Matrix2d& F) const override;
  [[nodiscard]] ShearB shear_operator(const ElementCoordinates& xy, double xi, double eta) const override;
};

/// MITC9: assumed covariant shear strains tied at a = 1/√3, b = √(3/5) (Bucalem & Bathe 1993), 3×3 Gauss.
class Mitc9 final : public PlateElement {
public:
  [[nodiscard]] ElementFormulation formulation() const override { return ElementFormulation::mitc9; }
  [[nodiscard]] ElementMatrix stiffness(const ElementCoordinates& xy, const ElementSection& s) const override;
  [[nodiscard]] ElementMatrix shear_stiffness(const ElementCoordinates& xy,
                                              const Eigen::Matrix2d& F) const override;
  [[nodiscard]] ShearB shear_operator(const ElementCoordinates& xy, double xi, double eta) const override;
};

/// The element of a formulation (q9 or mitc9; resolve `automatic` first, see resolve_formulation).
[[nodiscard]] std::unique_ptr<PlateElement> make_plate_element(ElementFormulation formulation);

} // namespace plyimpact
