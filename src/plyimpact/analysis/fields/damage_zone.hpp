#pragma once
// The elements a progressive or stacked impact needs where damage happens (issue 50; docs/mesh.md,
// "Meshes for damage"). Two rules, each with a margin of 10 %:
//
//   plies       L_c = √(element area) ≤ min over the modes of 2 G E / σ₀²,                       (DZ1)
//               the band limit of the crack-band law (Bažant & Oh 1983; PlyDamageLaw::
//               max_characteristic_length): a larger element either stops the run (BandLimitError) or
//               has its strengths lowered to soften without snap-back (Maimí et al. 2007);
//   interfaces  three interface points in the cohesive zone l = E2 G_c / τ⁰² (Hillerborg, M = 1;       (DZ2)
//               Turon et al. 2007), points half an element side apart with the nodal rule and a third
//               with Gauss's: side ≤ 2l/3 (nodal) or l (Gauss), the shorter of mode I and mode II.
//
// The zone in which the elements keep that size is a radius of five laminate thicknesses about the
// impact point (DZ3): the delaminations of drop-weight tests on coupons reach a few thicknesses from the
// impact point at the energies of barely visible damage (docs/mesh.md says what this rests on).
#include "plyimpact/fem/damaged_plate.hpp"
#include "plyimpact/fem/stacked_model.hpp"
#include "plyimpact/laminate/laminate.hpp"

#include <optional>
#include <string>

namespace plyimpact {

/// The margin of DZ1 and DZ2: the element size is this fraction of what the rule allows.
inline constexpr double damage_size_margin = 0.9;
/// DZ3: the zone's radius in laminate thicknesses.
inline constexpr double damage_zone_thicknesses = 5.0;

/// The largest element the damage zone may hold, and what sets it.
struct DamageElementSize {
  double size = 0.0;  ///< largest √(element area) [m]
  std::string reason; ///< "the band limit of matrix-compression of T700 (0.812 mm)"
};

/// DZ1 over the laminate's ply materials (with `plies`) and DZ2 (with `interfaces`), the smaller, times
/// damage_size_margin; empty with neither.
[[nodiscard]] std::optional<DamageElementSize>
damage_element_size(const Laminate& laminate, const std::optional<ProgressiveDamageSettings>& plies,
                    const std::optional<DelaminationSettings>& interfaces);

/// DZ3 [m].
[[nodiscard]] double damage_zone_radius(const Laminate& laminate);

} // namespace plyimpact
