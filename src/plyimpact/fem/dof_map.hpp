#pragma once
// Equation numbering: free DOFs numbered node by node; restrained DOFs get no equation (−1).
#include "plyimpact/fem/boundary.hpp"
#include "plyimpact/fem/mesh.hpp"
#include "plyimpact/fem/plate_element.hpp"

#include <array>
#include <vector>

namespace plyimpact {

class DofMap {
public:
  DofMap(const PlateMesh& mesh, const BoundaryConditions& bc);

  [[nodiscard]] int free_count() const { return free_count_; }
  [[nodiscard]] int total_count() const { return static_cast<int>(equation_.size()); }
  /// Equation of DOF d (0..4 = u, v, w, θx, θy) of node n, or −1 when restrained.
  [[nodiscard]] int equation(int node, int dof) const {
    return equation_[static_cast<std::size_t>(dofs_per_node) * static_cast<std::size_t>(node) +
                     static_cast<std::size_t>(dof)];
  }
  [[nodiscard]] std::array<int, q9_dofs> element_equations(const PlateMesh& mesh, int e) const;
  /// Restraint actually applied at a node (edge codes, corners).
  [[nodiscard]] Restraint restraint_of(int node) const;

private:
  std::vector<int> equation_;
  int free_count_ = 0;
};

/// Restraint of node n: the union of the codes of the edges it lies on; `bc.corners` replaces it at
/// the four corners when given.
[[nodiscard]] Restraint node_restraint(const PlateMesh& mesh, const BoundaryConditions& bc, int n);

} // namespace plyimpact
