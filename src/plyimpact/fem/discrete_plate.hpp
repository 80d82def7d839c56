#pragma once
// The discretized plate: a mesh, the section (laminate) of every element, the element formulation, the
// equations left free by the boundary conditions, and the global sparse matrices over the free DOFs.
#include "plyimpact/fem/dof_map.hpp"
#include "plyimpact/fem/mesh.hpp"
#include "plyimpact/fem/plate_element.hpp"
#include "plyimpact/fem/section.hpp"
#include "plyimpact/laminate/laminate.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace plyimpact {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// A point of the plate tied to the free DOFs: w(x, y) = sᵀ u, and a point force F gives F s.
struct PointSampler {
  PointLocation location;
  std::vector<std::pair<int, double>> w_terms; ///< (equation, N_a) for the free w DOFs of the element
  [[nodiscard]] double value(const Eigen::VectorXd& u) const;
  [[nodiscard]] Eigen::VectorXd as_vector(int size) const;
};

/// The laminates of the plate and which one each element has.
struct PlateSections {
  std::vector<Laminate> laminates; ///< [0] is the plate's own ([laminate] of a deck)
  std::vector<int> of_element;     ///< index into `laminates` per element; empty: all elements use [0]
};

/// How the plate is discretized, besides its mesh.
struct Discretization {
  MassMatrix mass = MassMatrix::lumped;
  ElementFormulation element = ElementFormulation::automatic;
};

class DiscretePlate {
public:
  /// Throws std::invalid_argument for inconsistent sections or boundary conditions.
  DiscretePlate(Mesh mesh, PlateSections sections, Discretization discretization, BoundaryConditions bc);
  /// One laminate on the structured nx × ny mesh of an a × b rectangle.
  DiscretePlate(Laminate laminate, PlateGeometry plate, MeshSpec spec, BoundaryConditions bc);

  [[nodiscard]] const Mesh& mesh() const { return mesh_; }
  /// The mesh, to move nodes after the model is built (tests of distorted elements).
  [[nodiscard]] Mesh& mutable_mesh() { return mesh_; }
  [[nodiscard]] const DofMap& dofs() const { return dofs_; }
  [[nodiscard]] const PlateElement& element() const { return *element_; }
  [[nodiscard]] ElementFormulation formulation() const { return element_->formulation(); }
  [[nodiscard]] MassMatrix mass_kind() const { return discretization_.mass; }
  [[nodiscard]] const BoundaryConditions& boundary() const { return bc_; }
  [[nodiscard]] int size() const { return dofs_.free_count(); }

  /// The plate's own laminate (section 0), and the laminate of element e.
  [[nodiscard]] const Laminate& laminate() const { return sections_.laminates.front(); }
  [[nodiscard]] const Laminate& laminate_of(int e) const {
    return sections_.laminates[static_cast<std::size_t>(section_index(e))];
  }
  [[nodiscard]] int section_index(int e) const {
    return sections_.of_element.empty() ? 0 : sections_.of_element[static_cast<std::size_t>(e)];
  }
  [[nodiscard]] const std::vector<Laminate>& laminates() const { return sections_.laminates; }
  [[nodiscard]] const Section& section(int index) const {
    return section_data_[static_cast<std::size_t>(index)];
  }
  /// True when every element has the same laminate.
  [[nodiscard]] bool single_section() const { return sections_.laminates.size() == 1; }

  /// Global matrices over the free DOFs (full symmetric storage, column-major).
  [[nodiscard]] SparseMatrix stiffness() const;
  /// Stiffness with element e's section given by `section_of_element(e)` (sections that evolve).
  [[nodiscard]] SparseMatrix stiffness(const std::function<ElementSection(int)>& section_of_element) const;
  [[nodiscard]] SparseMatrix mass() const;
  [[nodiscard]] SparseMatrix mass(MassMatrix kind) const;
  [[nodiscard]] SparseMatrix geometric_stiffness(const Eigen::Matrix2d& N) const;
  /// The zero-valued sparsity pattern shared by every global matrix.
  [[nodiscard]] const SparseMatrix& pattern() const { return pattern_; }

  /// Throws std::invalid_argument when (x, y) is outside the plate.
  [[nodiscard]] PointSampler sampler(double x, double y) const;

  [[nodiscard]] const ElementEquations& element_equations(int e) const {
    return equations_[static_cast<std::size_t>(e)];
  }
  [[nodiscard]] ElementVector element_dofs(const Eigen::VectorXd& u, int e) const {
    return gather(u, element_equations(e));
  }
  /// Nodal vector (5 per node, zeros where restrained) from free DOFs.
  [[nodiscard]] Eigen::VectorXd to_nodal(const Eigen::VectorXd& u) const;

private:
  /// Assembles Σₑ Kₑ in element order, computing Kₑ once per (element shape, section).
  using ElementKernel = std::function<ElementMatrix(int representative, int section)>;
  [[nodiscard]] SparseMatrix assemble(const ElementKernel& kernel) const;
  void add_element(SparseMatrix& K, int e, const ElementMatrix& Ke) const;
  void build_pattern();

  Mesh mesh_;
  PlateSections sections_;
  std::vector<Section> section_data_;
  Discretization discretization_;
  BoundaryConditions bc_;
  DofMap dofs_;
  std::unique_ptr<PlateElement> element_;
  std::vector<ElementEquations> equations_;
  SparseMatrix pattern_;            ///< structure of every global matrix, values zero
  std::vector<int> first_equation_; ///< first free equation of each node (−1 if none)
};

/// Where entry (i, j) of element e's matrix lands in the values of a matrix with the model's sparsity
/// pattern (index j·45 + i; −1 where a DOF is restrained): matrices that change every step (tangent,
/// secant) are assembled by index into a copy of the pattern, without searching it.
using ElementSlots = std::array<int, q9_dofs * q9_dofs>;
[[nodiscard]] std::vector<ElementSlots> element_slots(const DiscretePlate& model,
                                                      const SparseMatrix& pattern);
/// values[slot] += Ke(i, j) for every unrestrained entry.
void add_element_values(double* values, const ElementSlots& slots, const ElementMatrix& Ke);

/// The formulation actually used: `automatic` becomes mitc9 (no spurious mode; docs/elements.md).
[[nodiscard]] ElementFormulation resolve_formulation(ElementFormulation requested, const Mesh& mesh,
                                                     const BoundaryConditions& bc);

/// Rigid-body motions of the plate that the restraints leave free (empty when properly supported),
/// each described in words, e.g. "translation along z (w)".
[[nodiscard]] std::vector<std::string> unrestrained_rigid_motions(const DiscretePlate& model);

} // namespace plyimpact
