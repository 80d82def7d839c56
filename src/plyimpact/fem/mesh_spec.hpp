#pragma once
// What the user asks of the plate and its mesh (SPEC §3, §10 [plate], [mesh]).
#include <array>
#include <optional>
#include <string_view>

namespace plyimpact {

/// Rectangular plate 0 ≤ x ≤ a, 0 ≤ y ≤ b (mid-plane is z = 0).
struct PlateGeometry {
  double a = 0.0;     ///< length along x [m]
  double b = 0.0;     ///< width along y [m]
  bool rigid = false; ///< a rigid, immovable target instead of the plate (impact checks)
  friend bool operator==(const PlateGeometry&, const PlateGeometry&) = default;
};

enum class MassMatrix {
  lumped,     ///< diagonal, 3-point Lobatto quadrature (thesis (3.7)/(3.8), default)
  consistent, ///< 3×3 Gauss
};

enum class ElementFormulation {
  automatic, ///< mitc9: no spurious mode anywhere, placement-independent contact (docs/elements.md)
  q9,        ///< 9-node Lagrange, 3×3 Gauss membrane/bending, 2×2 Gauss shear (thesis)
  mitc9,     ///< 9-node with mixed-interpolated tensorial shear components (Bucalem & Bathe 1993)
};

/// The deck spelling ("auto", "q9", "mitc9").
[[nodiscard]] constexpr std::string_view to_string(ElementFormulation f) {
  return f == ElementFormulation::q9 ? "q9" : f == ElementFormulation::mitc9 ? "mitc9" : "auto";
}

/// A structured mesh graded toward the impact point (docs/deck.md [mesh]): elements of the size
/// `size_at_impact` there, growing by `growth` per element away from it, up to `max_size`. The impact
/// point lies at `impact_offset` within its element, in fractions of the element's sides: (0.5, 0.5) is
/// the element-centre node (default), (0, 0) a corner node, (0.5, 0) a mid-side node.
struct MeshGrading {
  std::optional<double>
      size_at_impact;             ///< [m]; empty: the largest contact radius expected (rigid-target Hertz)
  double growth = 1.25;           ///< size ratio of neighbouring elements (≥ 1)
  std::optional<double> max_size; ///< [m]; empty: a tenth of the plate's shorter side
  std::array<double, 2> impact_offset{0.5, 0.5}; ///< position of the impact point in its element, [0, 1)
  friend bool operator==(const MeshGrading&, const MeshGrading&) = default;
};

struct MeshSpec {
  int nx = 15; ///< elements along x (uniform mesh)
  int ny = 11; ///< elements along y (uniform mesh)
  MassMatrix mass = MassMatrix::lumped;
  ElementFormulation element = ElementFormulation::automatic;
  std::optional<MeshGrading> grading{}; ///< engaged: graded toward the impact point instead of nx × ny
  friend bool operator==(const MeshSpec&, const MeshSpec&) = default;
};

} // namespace plyimpact
