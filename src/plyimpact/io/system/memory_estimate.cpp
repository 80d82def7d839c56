#include "plyimpact/io/system/memory_estimate.hpp"

#include "plyimpact/analysis/impact/guards.hpp"
#include "plyimpact/io/system/system_memory.hpp"

#include <fmt/format.h>

#include <optional>

namespace plyimpact {

void check_deck_fits_memory(const Deck& deck) {
  if (deck.plate && deck.plate->rigid) return;
  // a gmsh file, a .geo or a rig preset (meshed, not yet assembled), or a uniform [mesh] nx x ny; a graded
  // mesh is checked by the impact case
  const bool uniform = !deck.file_mesh && deck.mesh && !deck.mesh->grading;
  if (!deck.file_mesh && !uniform) return;
  const std::optional<double> available = available_memory_bytes();
  if (!available) return;
  const MeshMemoryEstimate e = deck.file_mesh
                                   ? estimate_mesh_memory(static_cast<double>(deck.file_mesh->node_count()))
                                   : estimate_mesh_memory(deck.mesh->nx, deck.mesh->ny);
  if (e.bytes <= *available) return;
  throw InsufficientMemory(
      fmt::format("{}: {}", deck.source,
                  deck.file_mesh ? memory_refusal_message(deck.file_mesh->element_count(), e, *available)
                                 : memory_refusal_message(deck.mesh->nx, deck.mesh->ny, e, *available)));
}

} // namespace plyimpact
