#pragma once
// The memory check of a deck's uniform mesh or of the mesh it read from gmsh
// (analysis/impact/mesh_memory.hpp), for every analysis of the deck (static, modal, buckling as well as
// impacts), its refusal naming the deck's file. An impact case checks its own mesh, uniform or graded, when
// it is built (ImpactCase).
#include "plyimpact/analysis/impact/mesh_memory.hpp"
#include "plyimpact/io/deck/deck.hpp"

namespace plyimpact {

/// For a deck with a uniform [mesh] nx × ny, or a mesh from a gmsh file, a .geo or a rig preset (estimated
/// from its node count): throws InsufficientMemory (analysis/impact/guards.hpp) when the estimate exceeds the
/// available memory (io/system/system_memory.hpp).
void check_deck_fits_memory(const Deck& deck);

} // namespace plyimpact
