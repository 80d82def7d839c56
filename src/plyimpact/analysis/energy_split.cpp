#include "plyimpact/analysis/energy_split.hpp"

namespace plyimpact {

std::optional<AbsorbedEnergySplit> absorbed_energy_split(const ImpactResult& r) {
  if (!r.absorbed_energy || r.history.empty()) return std::nullopt;
  const ImpactSample& end = r.history.back();
  AbsorbedEnergySplit s;
  s.contact = r.contact_dissipation;
  s.ply_damage = r.progressive ? r.progressive->dissipated.sum() : 0.0;
  s.delamination = r.delamination ? r.delamination->dissipated : 0.0;
  s.plate_vibration = end.plate_kinetic + end.plate_strain;
  s.unaccounted = *r.absorbed_energy - (s.contact + s.ply_damage + s.delamination + s.plate_vibration); // ES1
  return s;
}

} // namespace plyimpact
