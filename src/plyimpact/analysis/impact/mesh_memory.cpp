#include "plyimpact/analysis/impact/mesh_memory.hpp"

#include "plyimpact/analysis/impact/guards.hpp"
#include "plyimpact/fem/structured_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace plyimpact {

MeshMemoryEstimate estimate_mesh_memory(long nx, long ny) {
  return estimate_mesh_memory(static_cast<double>(2 * nx + 1) * static_cast<double>(2 * ny + 1));
}

MeshMemoryEstimate estimate_mesh_memory(double nodes) {
  MeshMemoryEstimate e;
  e.nodes = nodes;
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

std::string memory_refusal_message(int elements, const MeshMemoryEstimate& e, double available_bytes) {
  return fmt::format(
      "the mesh of {} elements ({:.3g} nodes, {:.3g} equations) needs about {:.3g} GB for the stiffness, "
      "mass and factor ({:.3g} non-zeros in the factor) but this machine has {:.3g} GB available: use a "
      "coarser mesh in the file (larger element sizes in gmsh), or a larger mesh.size_at_impact or "
      "mesh.max_size for a .geo or a rig preset (docs/robustness.md)",
      elements, e.nodes, e.equations, e.bytes / 1e9, e.factor_nonzeros, available_bytes / 1e9);
}

std::array<long, 2> graded_mesh_size(const ImpactCaseDescription& d) {
  const MeshGrading& g = *d.mesh.grading;
  const double h0 = size_at_impact(d);
  // the rule of impact_mesh() (impact_case.cpp), on the element lines only: building the Mesh of
  // millions of nodes would itself take a minute
  const double h_max = std::max(h0, g.max_size.value_or(std::min(d.plate.a, d.plate.b) / 10.0));
  const auto count = [&](double L, double x0, double offset) {
    return static_cast<long>(graded_lines(L, x0, h0, g.growth, offset, h_max).size()) - 1;
  };
  return {count(d.plate.a, d.impactor.x, g.impact_offset[0]),
          count(d.plate.b, d.impactor.y, g.impact_offset[1])};
}

void check_memory_before_assembly(const ImpactCaseDescription& d) {
  const std::optional<double> available = d.memory_limit_bytes;
  if (!available || d.plate.rigid || d.mesh_from_file || !d.mesh.grading) return;
  const auto [nx, ny] = graded_mesh_size(d);
  const MeshMemoryEstimate e = estimate_mesh_memory(nx, ny);
  if (e.bytes > *available)
    throw InsufficientMemory(fmt::format(
        "a mesh graded toward the impact point of {} x {} elements ({:.3g} equations) needs about {:.3g} GB "
        "for the stiffness, mass and factor ({:.3g} non-zeros in the factor) but this machine has {:.3g} GB "
        "available: give a larger mesh.size_at_impact or mesh.max_size (docs/deck.md)",
        nx, ny, e.equations, e.bytes / 1e9, e.factor_nonzeros, *available / 1e9));
}

} // namespace plyimpact
