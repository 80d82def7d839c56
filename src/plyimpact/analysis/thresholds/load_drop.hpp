#pragma once
// What a test lab reads from the force history of a drop-weight test (issue 51): the delamination
// threshold load F_d, "the first load drop" (the incipient damage force of drop-weight test reports).
//
// The rule (stated, so that a run and a lab read the same number): the loading phase of the first contact
// runs from its start to the largest impactor displacement, where the force of an undamaged plate struck by
// a heavy impactor only rises. The force is smoothed as a lab filters its load cell's signal — the median of
// the samples within a centred window of a tenth of the loading phase — and the drop is the first sample
// whose smoothed force lies below the largest smoothed force so far by more than a fraction r (5 % by
// default). F_d is the largest force (unsmoothed) up to that sample: the smoothing finds the drop, and
// does not blunt the force before it. Without the window the plate's vibration gives elastic runs 5 % drops
// (the ASTM D7136 coupon at 12.2 kN of a 13.8 kN peak); with it none of the heavy-impactor elastic examples
// (§3.6, the ASTM D7136 coupon, the clamped circular plate) has one.
// A light impactor's force may still fall while it penetrates (the wave-controlled response: thesis
// §4.3's 8.4 g ball), so a drop is the lab's reading, not a proof of damage: the model's own first
// delamination (first_delamination) tells which.
#include "plyimpact/analysis/impact/impact_result.hpp"

#include <optional>
#include <vector>

namespace plyimpact {

inline constexpr double default_load_drop_fraction = 0.05;
inline constexpr double load_drop_window = 0.1; ///< of the loading phase's duration

/// The first load drop of `history` by the rule above, with r = `fraction`; empty where the force never
/// falls by that fraction in the loading phase (or there is no contact). A median per sample of the loading
/// phase: meant for a thinned history (io/run/impact_run keeps at most 4 096 samples), not every step's.
[[nodiscard]] std::optional<LoadDrop> first_load_drop(const std::vector<ImpactSample>& history,
                                                      double fraction = default_load_drop_fraction);

/// When the delamination first grew: the first sample whose projected delaminated area exceeds the first
/// sample's (a seed's, or none), and the contact force then. Empty where it never grew.
[[nodiscard]] std::optional<FirstDelamination> first_delamination(const std::vector<ImpactSample>& history);

} // namespace plyimpact
