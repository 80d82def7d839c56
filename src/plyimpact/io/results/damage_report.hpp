#pragma once
// Damage results: damage_onsets.csv (every failed Gauss point, Tables 4.4–4.7 columns),
// damage_area.csv (failed area per layer over time), probes.csv, and the JSON of SPEC §10.
#include "plyimpact/analysis/fields/damage_tracker.hpp"
#include "plyimpact/analysis/fields/stress_probe.hpp"
#include "plyimpact/analysis/thresholds/threshold_search.hpp"
#include "plyimpact/io/results/results.hpp"

#include <optional>
#include <string>
#include <vector>

namespace plyimpact {

/// {criterion, mode, ply, interface, element, ipgs, jpgs, x, y, time, force, sigma22, tau23, index}
/// with ply or interface null where it does not apply.
[[nodiscard]] nlohmann::json onset_json(const DamageOnset& o);
[[nodiscard]] std::string damage_onsets_csv(const std::vector<DamageOnset>& onsets);
[[nodiscard]] std::string damage_area_csv(const std::vector<DamageAreaSample>& areas);
[[nodiscard]] std::string probes_csv(const StressProbes& probes);
/// True where `o` lies in one of `clamp_tip_elements` (sorted, io/mesh/test_rigs.hpp's clamp_tip_elements).
[[nodiscard]] bool at_clamp_tip(const DamageOnset& o, const std::vector<int>& clamp_tip_elements);
/// The laminate's first failure: the earliest of `onsets` away from the clamp tips (the first of them where
/// two share a time); none where no criterion reached 1 elsewhere. A point support's singular stresses
/// reach every criterion at its elements early whatever the impact does (issue 82: 20 of the 49 first
/// failures of bench/decks/coupon-onset.toml at one clamp tip).
[[nodiscard]] std::optional<DamageOnset> laminate_first_failure(const std::vector<DamageOnset>& onsets,
                                                                const std::vector<int>& clamp_tip_elements);
/// Table of first onsets for stdout (engineering units). With `clamp_tip_elements`, the rows there are
/// marked "clamp tip", and lines after the table count them and give `laminate_first`.
[[nodiscard]] std::string
first_failures_text(const std::vector<DamageOnset>& first, const std::vector<int>& clamp_tip_elements = {},
                    const std::optional<DamageOnset>& laminate_first = std::nullopt);
[[nodiscard]] std::string threshold_text(const std::string& criterion, const ThresholdResult& r);

} // namespace plyimpact
