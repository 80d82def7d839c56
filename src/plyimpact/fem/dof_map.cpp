#include "plyimpact/fem/dof_map.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace plyimpact {

DofMap::DofMap(const Mesh& mesh, const BoundaryConditions& bc)
    : equation_(static_cast<std::size_t>(dofs_per_node) * static_cast<std::size_t>(mesh.node_count()), -1) {
  const std::vector<Restraint> restraints = node_restraints(mesh, bc);
  for (int n = 0; n < mesh.node_count(); ++n)
    for (int d = 0; d < dofs_per_node; ++d)
      if (!restraints[static_cast<std::size_t>(n)].fixed[static_cast<std::size_t>(d)])
        equation_[static_cast<std::size_t>(dofs_per_node) * static_cast<std::size_t>(n) +
                  static_cast<std::size_t>(d)] = free_count_++;
}

std::pair<int, int> DofMap::node_dof(int equation) const {
  const auto at = std::find(equation_.begin(), equation_.end(), equation);
  if (equation < 0 || at == equation_.end())
    throw std::out_of_range(fmt::format("DofMap::node_dof: no free equation {}", equation));
  const auto slot = static_cast<int>(at - equation_.begin());
  return {slot / dofs_per_node, slot % dofs_per_node};
}

std::vector<std::pair<int, int>> DofMap::node_dofs() const {
  std::vector<std::pair<int, int>> out(static_cast<std::size_t>(free_count_));
  for (std::size_t slot = 0; slot < equation_.size(); ++slot)
    if (const int eq = equation_[slot]; eq >= 0)
      out[static_cast<std::size_t>(eq)] = {static_cast<int>(slot) / dofs_per_node,
                                           static_cast<int>(slot) % dofs_per_node};
  return out;
}

ElementEquations DofMap::element_equations(const Mesh& mesh, int e) const {
  ElementEquations eq{};
  const ElementNodes& conn = mesh.element_nodes(e);
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
