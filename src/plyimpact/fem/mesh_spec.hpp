#pragma once
// What the user asks of the plate and its mesh (SPEC §3, §10 [plate], [mesh]).
namespace plyimpact {

/// Rectangular plate 0 ≤ x ≤ a, 0 ≤ y ≤ b (mid-plane is z = 0).
struct PlateGeometry {
  double a = 0.0;     ///< length along x [m]
  double b = 0.0;     ///< width along y [m]
  bool rigid = false; ///< a rigid, immovable target instead of the plate (impact checks)
};

enum class MassMatrix {
  lumped,     ///< diagonal, 3-point Lobatto quadrature (thesis (3.7)/(3.8), default)
  consistent, ///< 3×3 Gauss
};

enum class ElementFormulation {
  automatic, ///< q9, unless no node has w restrained (then its spurious w–θ mode would survive): mitc9
  q9,        ///< 9-node Lagrange, 3×3 Gauss membrane/bending, 2×2 Gauss shear (thesis)
  mitc9,     ///< 9-node with mixed-interpolated tensorial shear components (Bucalem & Bathe 1993)
};

struct MeshSpec {
  int nx = 15; ///< elements along x
  int ny = 11; ///< elements along y
  MassMatrix mass = MassMatrix::lumped;
  ElementFormulation element = ElementFormulation::automatic;
};

} // namespace plyimpact
