#pragma once
// Where the energy the impactor lost went (issue 51: the absorbed energy split by mechanism, as a test lab
// compares it with its own energy budget). Once the impactor has left the plate, the energy balance of
// impact_loop.hpp reads
//
//   ½ m v0² − ½ m v_end² = ∮ Fc dα + D_plies + D_interfaces + (T + U)_plate + ε,            (ES1)
//
// the absorbed energy on the left; on the right the contact law's hysteresis (the indentation under the
// nose: SPEC §4, the unloading branch), the energies the plies' cracking and the interfaces dissipated, the
// kinetic and strain energy the plate still holds (it rings on after the impactor left: a lab's
// instrumented tup counts it as absorbed) and ε, the integration's error (energy_balance_error · ½ m v0²).
#include "plyimpact/analysis/impact/impact_result.hpp"

#include <optional>

namespace plyimpact {

struct AbsorbedEnergySplit {
  double contact = 0.0;         ///< ∮ Fc dα at the end [J]
  double ply_damage = 0.0;      ///< dissipated by the plies' damage, all modes [J]
  double delamination = 0.0;    ///< dissipated by the interfaces [J]
  double plate_vibration = 0.0; ///< kinetic + strain energy left in the plate at the end [J]
  double unaccounted = 0.0;     ///< ε of ES1: the absorbed energy less the four above [J]
};

/// ES1 of a run whose impactor has left the plate (absorbed_energy given) and whose plate was followed
/// (final_plate_energy given: not the contact-point response); empty otherwise.
[[nodiscard]] std::optional<AbsorbedEnergySplit> absorbed_energy_split(const ImpactResult& r);

} // namespace plyimpact
