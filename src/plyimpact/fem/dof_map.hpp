#pragma once
// Equation numbering: free DOFs numbered node by node; restrained DOFs get no equation (−1). And the
// two moves between element and global vectors that every assembly and every recovery makes: gather an
// element's DOFs from a global vector, scatter-add an element vector into one.
#include "plyimpact/fem/boundary.hpp"
#include "plyimpact/fem/mesh.hpp"

#include <Eigen/Core>
#include <array>
#include <utility>
#include <vector>

namespace plyimpact {

inline constexpr int dofs_per_node = 5;
inline constexpr int q9_dofs = 45;

/// Name of nodal DOF d (0..4): "u", "v", "w", "theta_x", "theta_y" — the one table that messages and
/// summaries use (output files add their units). Throws std::out_of_range outside 0..4.
[[nodiscard]] inline const char* dof_name(int dof) {
  static constexpr std::array<const char*, dofs_per_node> names{"u", "v", "w", "theta_x", "theta_y"};
  return names.at(static_cast<std::size_t>(dof));
}

/// The plate element's DOF of field f (0 u, 1 v, 2 w, 3 θx, 4 θy) at its local node a: 5a + f.
[[nodiscard]] constexpr Eigen::Index plate_dof(Eigen::Index a, Eigen::Index f) {
  return dofs_per_node * a + f;
}
/// Element DOF of entry j of the 27 (w, θx, θy) DOFs in node order: the only DOFs that the transverse
/// shear strains read, and the compact form the shear rows and stiffness are stored in.
[[nodiscard]] constexpr Eigen::Index transverse_dof(Eigen::Index j) {
  return plate_dof(j / 3, 2 + j % 3);
}

using ElementMatrix = Eigen::Matrix<double, q9_dofs, q9_dofs>;
using ElementVector = Eigen::Matrix<double, q9_dofs, 1>;
/// Global equation of each element DOF 5a + d (−1 when restrained).
using ElementEquations = std::array<int, q9_dofs>;

class DofMap {
public:
  DofMap(const Mesh& mesh, const BoundaryConditions& bc);

  [[nodiscard]] int free_count() const { return free_count_; }
  [[nodiscard]] int total_count() const { return static_cast<int>(equation_.size()); }
  /// Equation of DOF d (0..4 = u, v, w, θx, θy) of node n, or −1 when restrained.
  [[nodiscard]] int equation(int node, int dof) const {
    return equation_[static_cast<std::size_t>(dofs_per_node) * static_cast<std::size_t>(node) +
                     static_cast<std::size_t>(dof)];
  }
  /// The node and DOF (0..4 = u, v, w, θx, θy) of a free equation (a search: for messages, not loops).
  /// Throws std::out_of_range for an equation outside 0..free_count() − 1.
  [[nodiscard]] std::pair<int, int> node_dof(int equation) const;
  /// The node and DOF of every free equation, in equation order (one pass: for tables over all equations).
  [[nodiscard]] std::vector<std::pair<int, int>> node_dofs() const;
  [[nodiscard]] ElementEquations element_equations(const Mesh& mesh, int e) const;
  /// Restraint actually applied at a node.
  [[nodiscard]] Restraint restraint_of(int node) const;

private:
  std::vector<int> equation_;
  int free_count_ = 0;
};

/// uₑ from the global vector of free DOFs (zero where restrained).
[[nodiscard]] inline ElementVector gather(const Eigen::VectorXd& u, const ElementEquations& eq) {
  ElementVector ue;
  for (int i = 0; i < q9_dofs; ++i)
    ue(i) = eq[static_cast<std::size_t>(i)] >= 0 ? u(eq[static_cast<std::size_t>(i)]) : 0.0;
  return ue;
}

/// f += fₑ on the free DOFs.
inline void scatter_add(Eigen::VectorXd& f, const ElementEquations& eq, const ElementVector& fe) {
  for (int i = 0; i < q9_dofs; ++i)
    if (eq[static_cast<std::size_t>(i)] >= 0) f(eq[static_cast<std::size_t>(i)]) += fe(i);
}

} // namespace plyimpact
