#include "plyimpact/analysis/fields/damage_zone.hpp"

#include "plyimpact/laminate/cohesive_law.hpp"
#include "plyimpact/laminate/ply_law.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace plyimpact {
namespace {

/// DZ1: the smallest band limit of the run's ply law over the laminate's materials and the four modes.
DamageElementSize ply_band_limit(const Laminate& laminate, const ProgressiveDamageSettings& plies) {
  DamageElementSize best{INFINITY, ""};
  for (const Material& m : laminate.materials()) {
    const std::unique_ptr<PlyLaw> law = make_ply_law(m, plies.law);
    for (const DamageMode mode : {DamageMode::fibre_tension, DamageMode::fibre_compression,
                                  DamageMode::matrix_tension, DamageMode::matrix_compression}) {
      const double limit = law->band_limit(mode);
      if (limit < best.size)
        best = {limit,
                fmt::format("the band limit of {} of {} ({:.3g} mm)", to_string(mode), m.name, limit * 1e3)};
    }
  }
  return best;
}

/// DZ2: the element side that puts three interface points in the shorter cohesive zone.
DamageElementSize cohesive_zone_side(const Laminate& laminate, const DelaminationSettings& interfaces) {
  const CohesiveParameters& c = interfaces.stack.interface;
  double E2 = INFINITY;
  for (const Material& m : laminate.materials())
    E2 = std::min(E2, m.E2);
  const double l = std::min(cohesive_zone_length(E2, c.G_Ic, c.normal_strength),
                            cohesive_zone_length(E2, c.G_IIc, c.shear_strength));
  const bool nodal = interfaces.stack.rule == CohesiveQuadrature::nodal;
  const double side = nodal ? 2.0 * l / 3.0 : l; // three points in l
  return {side, fmt::format("three interface points in the cohesive zone ({:.3g} mm)", l * 1e3)};
}

} // namespace

std::optional<DamageElementSize> damage_element_size(const Laminate& laminate,
                                                     const std::optional<ProgressiveDamageSettings>& plies,
                                                     const std::optional<DelaminationSettings>& interfaces) {
  std::optional<DamageElementSize> best;
  if (plies) best = ply_band_limit(laminate, *plies);
  if (interfaces) {
    DamageElementSize zone = cohesive_zone_side(laminate, *interfaces);
    if (!best || zone.size < best->size) best = std::move(zone);
  }
  if (best) best->size *= damage_size_margin;
  return best;
}

double damage_zone_radius(const Laminate& laminate) {
  return damage_zone_thicknesses * laminate.thickness(); // DZ3
}

} // namespace plyimpact
