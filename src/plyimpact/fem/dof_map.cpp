#include "plyimpact/fem/dof_map.hpp"

namespace plyimpact {

Restraint node_restraint(const PlateMesh& mesh, const BoundaryConditions& bc, int n) {
  Restraint r;
  int edges = 0;
  for (const Edge e : {Edge::x0, Edge::xa, Edge::y0, Edge::yb}) {
    if (!mesh.on_edge(n, e)) continue;
    ++edges;
    for (std::size_t d = 0; d < 5; ++d)
      r.fixed[d] = r.fixed[d] || bc.edge(e).fixed[d];
  }
  if (edges == 2 && bc.corners) return *bc.corners;
  return r;
}

DofMap::DofMap(const PlateMesh& mesh, const BoundaryConditions& bc)
    : equation_(static_cast<std::size_t>(dofs_per_node) * static_cast<std::size_t>(mesh.node_count()), -1) {
  for (int n = 0; n < mesh.node_count(); ++n) {
    const Restraint r = node_restraint(mesh, bc, n);
    for (int d = 0; d < dofs_per_node; ++d)
      if (!r.fixed[static_cast<std::size_t>(d)])
        equation_[static_cast<std::size_t>(dofs_per_node) * static_cast<std::size_t>(n) +
                  static_cast<std::size_t>(d)] = free_count_++;
  }
}

std::array<int, q9_dofs> DofMap::element_equations(const PlateMesh& mesh, int e) const {
  std::array<int, q9_dofs> eq{};
  const auto& conn = mesh.element_nodes(e);
  for (int a = 0; a < 9; ++a)
    for (int d = 0; d < dofs_per_node; ++d)
      eq[static_cast<std::size_t>(dofs_per_node) * static_cast<std::size_t>(a) +
         static_cast<std::size_t>(d)] = equation(conn[static_cast<std::size_t>(a)], d);
  return eq;
}

Restraint DofMap::restraint_of(int node) const {
  Restraint r;
  for (int d = 0; d < dofs_per_node; ++d)
    r.fixed[static_cast<std::size_t>(d)] = equation(node, d) < 0;
  return r;
}

} // namespace plyimpact
