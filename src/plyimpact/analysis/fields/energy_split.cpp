#include "plyimpact/analysis/fields/energy_split.hpp"

namespace plyimpact {

std::optional<AbsorbedEnergySplit> absorbed_energy_split(const ImpactResult& r) {
  if (!r.absorbed_energy || !r.final_plate_energy) return std::nullopt;
  AbsorbedEnergySplit s;
  s.contact = r.contact_dissipation;
  s.ply_damage = r.progressive ? r.progressive->dissipated.sum() : 0.0;
  s.delamination = r.delamination ? r.delamination->dissipated : 0.0;
  s.plate_vibration = *r.final_plate_energy;
  s.unaccounted = *r.absorbed_energy - (s.contact + s.ply_damage + s.delamination + s.plate_vibration); // ES1
  return s;
}

} // namespace plyimpact
