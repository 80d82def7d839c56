#pragma once
// Damage results: damage_onsets.csv (every failed Gauss point, Tables 4.4–4.7 columns),
// damage_area.csv (failed area per layer over time), probes.csv, and the JSON of SPEC §10.
#include "plyimpact/analysis/fields/damage_tracker.hpp"
#include "plyimpact/analysis/fields/stress_probe.hpp"
#include "plyimpact/analysis/thresholds/threshold_search.hpp"
#include "plyimpact/io/results/results.hpp"

#include <string>

namespace plyimpact {

/// {criterion, mode, ply, interface, element, ipgs, jpgs, x, y, time, force, sigma22, tau23, index}
/// with ply or interface null where it does not apply.
[[nodiscard]] nlohmann::json onset_json(const DamageOnset& o);
[[nodiscard]] std::string damage_onsets_csv(const std::vector<DamageOnset>& onsets);
[[nodiscard]] std::string damage_area_csv(const std::vector<DamageAreaSample>& areas);
[[nodiscard]] std::string probes_csv(const StressProbes& probes);
/// Table of first onsets for stdout (engineering units).
[[nodiscard]] std::string first_failures_text(const std::vector<DamageOnset>& first);
[[nodiscard]] std::string threshold_text(const std::string& criterion, const ThresholdResult& r);

} // namespace plyimpact
