#pragma once
// From a deck (SPEC §10) to the plain descriptions the analyses take: the plate model of a static,
// modal or buckling deck, and the impact case of an impact or threshold deck.
#include "plyimpact/analysis/fields/damage_tracker.hpp"
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/io/deck/deck.hpp"

namespace plyimpact {

/// The deck's plate: the structured mesh of [plate] and [mesh], each element with the laminate of its
/// [[region]] (or [laminate]), the [boundary] restraints.
[[nodiscard]] DiscretePlate plate_model(const Deck& deck);

/// The impact case of the deck; `nonlinear` forces the geometrically non-linear plate (--nonlinear).
/// Throws InsufficientMemory (analysis/impact/guards.hpp) for a uniform mesh beyond the memory available
/// (io/system/memory_estimate.hpp); ImpactCase refuses a graded one (analysis/impact/mesh_memory.hpp).
[[nodiscard]] ImpactCaseDescription impact_case_description(const Deck& deck, bool nonlinear = false);

/// [damage] every and delamination_ply_n as the damage tracker takes them.
[[nodiscard]] DamageOptions damage_options_from_deck(const Deck& deck);

} // namespace plyimpact
