#pragma once
// Standard drop-weight set-ups ([rig] preset, docs/mesh.md "Test rigs"): the plate, its mesh, its
// supports and the impactor's nose that a test lab's rig gives, built from a few numbers.
//
//   astm-d7136  the 150 × 100 mm coupon on a 125 × 75 mm window (ASTM D7136/D7136M, Airbus AITM 1-0010),
//               held by four clamp tips at (75 ± 50, 50 ± 43.75) mm; a 16 mm hemispherical impactor;
//               the impact energy C_E · h with C_E = 6.7 J/mm unless the deck gives one.
//   aitm-1-0010 the same coupon, window, clamp tips and nose on the same commercial stand (Airbus AITM
//   1-0010,
//               the standard of the Rivallant tests); no energy rule: the deck gives the impact energy.
//   circular    a plate clamped between rings with a circular opening of the given diameter: the disk
//               of the opening, clamped at its rim.
// Sources and what could not be checked are in docs/mesh.md.
#include "plyimpact/fem/boundary.hpp"
#include "plyimpact/fem/mesh.hpp"
#include "plyimpact/io/mesh/gmsh_mesh.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace plyimpact {

enum class RigKind { astm_d7136, aitm_1_0010, circular };

struct RigSpec {
  RigKind kind = RigKind::astm_d7136;
  double diameter = 0.0;   ///< circular: the clamped opening [m]
  GeometryMeshing meshing; ///< sizes toward the impact point (defaults: rig_meshing)
};

/// What a rig builds.
struct Rig {
  Mesh mesh;
  /// The supports by the mesh's named sets. The ASTM window is "unilateral" for a static analysis and
  /// "ss-soft" (held both ways) for the others, which do not solve lift-off (docs/mesh.md).
  BoundaryConditions boundary;
  double impactor_radius = 0.0;               ///< the rig's nose [m]
  std::optional<double> energy_per_thickness; ///< the standard's impact energy rule [J/m]
  std::string description;                    ///< what was built, for the reports
};

/// What the maps of a run on a rig draw of it [m]: the window's edge (a closed polygon, empty where the
/// rig has none) and the clamp tips. The tips hold u, v, w at single nodes: point supports, whose
/// stresses are singular, so failure criteria and ply damage light up around them whatever the impact
/// does (docs/mesh.md, "Test rigs"). The maps mark them, with clamp_tip_note, so that they are not read
/// as impact damage.
struct RigOutline {
  std::vector<Eigen::Vector2d> window;
  std::vector<Eigen::Vector2d> clamp_tips;
};
inline constexpr const char* clamp_tip_note = "clamp tips (point supports: their stresses are singular)";
/// The outline of `spec`'s rig; empty for none (no rig, or the circular rig, whose support is the mesh's
/// edge).
[[nodiscard]] RigOutline rig_outline(const std::optional<RigSpec>& spec);
/// The elements, numbered from 1 as DamageOnset::element, that hold one of `tips` at a node: each tip holds
/// the node of `mesh` nearest it, a point support whose stresses are singular, so that a criterion reaching 1
/// in these elements says nothing of the laminate. Sorted; empty without tips.
[[nodiscard]] std::vector<int> clamp_tip_elements(const Mesh& mesh, const std::vector<Eigen::Vector2d>& tips);

/// C_E of ASTM D7136 (6.7 J/mm, docs/mesh.md for the source) [J/m].
inline constexpr double astm_d7136_energy_per_thickness = 6.7e3;

/// The rig's default mesh sizes when the deck gives none: 2 mm at the impact point, growing by 1.25
/// per element to 5 mm (ASTM), or to a twentieth of the opening's diameter (circular).
[[nodiscard]] GeometryMeshing rig_meshing(const RigSpec& spec);

/// Builds the rig's plate (meshed by gmsh) and supports; `static_analysis` chooses the window's
/// support as above. Throws MeshFileError when gmsh fails.
[[nodiscard]] Rig build_rig(const RigSpec& spec, bool static_analysis);

/// The plate's extent on the rig [m]: the coupon (ASTM, AITM), or the circular rig's disk.
[[nodiscard]] BoundingBox rig_bounds(const RigSpec& spec);

/// Refuses, before gmsh meshes anything (build_rig calls it first), a rig whose size field would make a mesh
/// larger than the memory available (a single laminate's estimate, mesh_memory.hpp): `size_at_impact = 2e-4,
/// growth = 1` meshed for 341 s before its assembly was refused for 126 GB (issue 77). Throws MeshFileError
/// with the count, the estimate and the memory.
void require_rig_mesh_fits_memory(const RigSpec& spec);

[[nodiscard]] std::string_view to_string(RigKind kind);

} // namespace plyimpact
