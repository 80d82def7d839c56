#include "plyimpact/io/memory_estimate.hpp"

#include "plyimpact/analysis/guards.hpp"
#include "plyimpact/io/system_memory.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace plyimpact {

MeshMemoryEstimate estimate_mesh_memory(long nx, long ny) {
  MeshMemoryEstimate e;
  e.nodes = static_cast<double>(2 * nx + 1) * static_cast<double>(2 * ny + 1);
  e.equations = 5.0 * e.nodes;
  // Nodes coupled to a node: 25 for a corner node (4 elements), 15 for a mid-side node, 9 for a
  // centre node; an element has one of each corner and centre and two mid-side: 16 on average.
  e.matrix_nonzeros = 25.0 * 16.0 * e.nodes;
  const double log_n = std::log2(std::max(2.0, e.equations));
  e.factor_nonzeros = factor_fill_constant * e.equations * log_n * log_n;
  constexpr double bytes_per_nonzero = 8.0 + 4.0; // double value + int row index
  e.bytes = bytes_per_nonzero * (e.factor_nonzeros + e.equations + 3.0 * e.matrix_nonzeros);
  return e;
}

std::string memory_refusal_message(long nx, long ny, const MeshMemoryEstimate& e, double available_bytes) {
  return fmt::format(
      "a {} x {} mesh ({:.3g} equations) needs about {:.3g} GB for the stiffness, mass and "
      "factor ({:.3g} non-zeros in the factor) but this machine has {:.3g} GB available: use a "
      "coarser mesh ([mesh] nx, ny) or leave [mesh] out for a mesh graded toward the impact "
      "point (docs/robustness.md)",
      nx, ny, e.equations, e.bytes / 1e9, e.factor_nonzeros, available_bytes / 1e9);
}

void check_memory_before_assembly(const Deck& deck) {
  if (!deck.mesh || deck.mesh->grading || (deck.plate && deck.plate->rigid)) return;
  const std::optional<double> available = available_memory_bytes();
  if (!available) return;
  const MeshMemoryEstimate e = estimate_mesh_memory(deck.mesh->nx, deck.mesh->ny);
  if (e.bytes > *available)
    throw InsufficientMemory(fmt::format(
        "{}: {}", deck.source, memory_refusal_message(deck.mesh->nx, deck.mesh->ny, e, *available)));
}

} // namespace plyimpact
