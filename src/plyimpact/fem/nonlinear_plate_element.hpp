#pragma once
// Geometrically non-linear 9-node Mindlin plate element, total Lagrangian (SPEC §8; thesis (2.44)–(2.103)).
//
// At a point, the displacement gradients of the element DOFs are collected in
//   g = (u,x, u,y, v,x, v,y, w,x, w,y, θx,x, θx,y, θy,x, θy,y, θx, θy)  = G uₑ
// and the eight generalized strains e = (εx, εy, γxy, κx, κy, κxy, γyz, γxz) are
//   e = L g + e_NL(g),   e_NL,i = ½ gᵀ H_i g   (quadratic, (2.47)),
// so that, with resultants S = C e ((N, M) = [[A, B], [B, D]] (ε, κ), (Qy, Qx) = F γ),
//   internal force   f = ∫ Gᵀ Eᵀ S dA,             E = ∂e/∂g = L + [gᵀ H_i]   (2.56)–(2.60)
//   tangent          K_T = ∫ Gᵀ (Eᵀ C E + Σ_i S_i H_i) G dA   = K_L + K_NL + K_σ   (2.100)–(2.103).
// Strain measures:
//   von Kármán (default): εx += ½ w,x², εy += ½ w,y², γxy += w,x w,y; κ and γ stay linear.
//   Green–Lagrange (thesis (2.53)–(2.55)): the in-plane terms of u, v and w, plus the rotation
//   gradient terms of κ (2.54) and the θ·∇(u, v) terms of γ (2.55). (2.44) prints ½ on the γxy
//   products; (2.53) has them without: the latter is the Green–Lagrange strain.
// Integration as the linear element: 3×3 Gauss for membrane/bending; transverse shear 2×2 Gauss (q9)
// or, with the von Kármán measure only, MITC9 assumed strains (linear shear, K_s uₑ).
#include "plyimpact/fem/plate_element.hpp"

#include <array>
#include <string>

namespace plyimpact {

enum class StrainMeasure { von_karman, green_lagrange };

[[nodiscard]] std::string to_string(StrainMeasure m);

/// The deck's non-linear plate: its strain measure (how an integrator iterates it is the integrator's:
/// analysis/integrators/newton_settings.hpp).
struct NonlinearImpactSettings {
  StrainMeasure measure = StrainMeasure::von_karman;
  friend bool operator==(const NonlinearImpactSettings&, const NonlinearImpactSettings&) = default;
};

/// Shape function derivatives and weight·det J at one integration point (geometry only).
struct IntegrationPoint {
  Eigen::Matrix<double, 9, 1> N, dN_dx, dN_dy;
  double weight = 0.0; ///< w_i w_j det J [m²]
};

/// What an element needs of its geometry, computed once per element shape.
struct ElementGeometry {
  std::array<IntegrationPoint, 9> membrane_bending; ///< 3×3 Gauss
  std::array<IntegrationPoint, 4> shear;            ///< 2×2 Gauss (q9)
  ElementMatrix shear_stiffness;                    ///< K_s of the linear element (MITC9 path)
  /// K_s on the deflection and rotations alone ((w, θx, θy) of the nodes in DOF order): its rows and
  /// columns of u and v are zero, so the force path multiplies this a third of the size.
  Eigen::Matrix<double, 27, 27, Eigen::RowMajor> shear_stiffness_wt;
  // The same shape-function data with one column per point, so the force path takes the gradients of
  // all points of a rule in one small matrix product (U dN) and scatters back in one (R dNᵀ).
  Eigen::Matrix<double, 9, 9> mb_dN_dx, mb_dN_dy;    ///< membrane–bending points
  Eigen::Matrix<double, 9, 4> s_dN_dx, s_dN_dy, s_N; ///< transverse-shear points
};

class NonlinearMindlinQ9 {
public:
  /// `linear` is the element whose shear interpolation the non-linear one keeps (q9 or mitc9). Throws
  /// std::invalid_argument for Green–Lagrange with MITC9 (the θ·∇(u, v) shear terms of (2.55) have no
  /// assumed-strain interpolation here).
  NonlinearMindlinQ9(const PlateElement& linear, StrainMeasure measure);

  /// The integration points of an element and, for MITC9, its linear shear stiffness with `section`.
  [[nodiscard]] ElementGeometry geometry(const ElementCoordinates& xy, const SectionStiffness& section) const;
  /// f = ∫ Gᵀ Eᵀ S dA (+ K_s uₑ for MITC9).
  [[nodiscard]] ElementVector internal_force(const ElementGeometry& geo, const SectionStiffness& section,
                                             const ElementVector& ue) const;
  /// K_T = ∂f/∂uₑ (consistent: material + initial-displacement + geometric (initial-stress) parts).
  [[nodiscard]] ElementMatrix tangent_stiffness(const ElementGeometry& geo, const SectionStiffness& section,
                                                const ElementVector& ue) const;

  [[nodiscard]] StrainMeasure measure() const { return measure_; }
  [[nodiscard]] ElementFormulation formulation() const { return linear_.formulation(); }

private:
  const PlateElement& linear_;
  StrainMeasure measure_;
};

} // namespace plyimpact
