#include "plyimpact/io/memory_estimate.hpp"

#include "plyimpact/analysis/guards.hpp"
#include "plyimpact/io/system_memory.hpp"

#include <fmt/format.h>

#include <optional>

namespace plyimpact {

void check_memory_before_assembly(const Deck& deck) {
  if (deck.plate && deck.plate->rigid) return;
  if (deck.file_mesh) { // a gmsh file, a .geo or a rig preset: meshed, not yet assembled
    const std::optional<double> available = available_memory_bytes();
    const MeshMemoryEstimate e = estimate_mesh_memory(static_cast<double>(deck.file_mesh->node_count()));
    if (available && e.bytes > *available)
      throw InsufficientMemory(fmt::format(
          "{}: {}", deck.source, memory_refusal_message(deck.file_mesh->element_count(), e, *available)));
    return;
  }
  if (!deck.mesh || deck.mesh->grading) return;
  const std::optional<double> available = available_memory_bytes();
  if (!available) return;
  const MeshMemoryEstimate e = estimate_mesh_memory(deck.mesh->nx, deck.mesh->ny);
  if (e.bytes > *available)
    throw InsufficientMemory(fmt::format(
        "{}: {}", deck.source, memory_refusal_message(deck.mesh->nx, deck.mesh->ny, e, *available)));
}

} // namespace plyimpact
