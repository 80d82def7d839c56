#pragma once
// The cross-section between the plate element and the plies (OOFEM's term): what an element needs of
// the laminate at an integration point — the resultant stiffnesses of (1.24)/(1.25),
//   (N, M) = [[A, B], [B, D]] (ε0, κ),   (Qy, Qx) = F (γyz, γxz),
// and the mass moments I0, I1, I2 of (2.109). Every element refers to its own section (regions of a
// panel with different laminates); a section whose state evolves (ply damage) gives one per 3×3 Gauss
// point of the element.
#include "plyimpact/laminate/laminate.hpp"

#include <Eigen/Core>
#include <array>
#include <span>
#include <vector>

namespace plyimpact {

struct SectionStiffness {
  Eigen::Matrix<double, 6, 6> C_mb; ///< [[A, B], [B, D]]
  Eigen::Matrix2d F;                ///< transverse shear, order (yz, xz), shear correction included
};

struct Section {
  SectionStiffness stiffness;
  std::array<double, 3> inertia{}; ///< I0 [kg/m²], I1 [kg/m], I2 [kg]
};

[[nodiscard]] SectionStiffness section_stiffness(const Laminate& laminate);
[[nodiscard]] Section section_of(const Laminate& laminate);

/// The section of one element at its integration points: one for the whole element, or one per point
/// of the 3×3 Gauss rule (gauss3x3 order). Refers to storage owned elsewhere.
class ElementSection {
public:
  /// The same section at every point.
  explicit ElementSection(const SectionStiffness& uniform) : uniform_(&uniform) {}
  /// One section per 3×3 Gauss point.
  explicit ElementSection(std::span<const SectionStiffness, 9> at_points) : points_(at_points) {}

  [[nodiscard]] bool uniform() const { return uniform_ != nullptr; }
  /// The section at point `p` of gauss3x3.
  [[nodiscard]] const SectionStiffness& at(std::size_t p) const { return uniform_ ? *uniform_ : points_[p]; }
  /// F for integration rules other than 3×3 Gauss (q9's 2×2 shear rule): the uniform F, or the
  /// Gauss-weighted mean of the nine points' F.
  [[nodiscard]] Eigen::Matrix2d shear_for_other_rules() const;

private:
  const SectionStiffness* uniform_ = nullptr;
  std::span<const SectionStiffness, 9> points_{static_cast<const SectionStiffness*>(nullptr), 9};
};

} // namespace plyimpact
