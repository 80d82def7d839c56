#pragma once
// The discretized plate: mesh, element, equations, and the global sparse matrices over free DOFs.
#include "plyimpact/analysis/parameters.hpp"
#include "plyimpact/fem/dof_map.hpp"
#include "plyimpact/fem/mesh.hpp"
#include "plyimpact/fem/plate_element.hpp"
#include "plyimpact/laminate/laminate.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
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

class PlateModel {
public:
  PlateModel(Laminate laminate, PlateGeometry plate, MeshSpec spec, BoundaryConditions bc);

  [[nodiscard]] const Laminate& laminate() const { return laminate_; }
  [[nodiscard]] const PlateMesh& mesh() const { return mesh_; }
  [[nodiscard]] PlateMesh& mutable_mesh() { return mesh_; }
  [[nodiscard]] const DofMap& dofs() const { return dofs_; }
  [[nodiscard]] const MindlinQ9& element() const { return element_; }
  [[nodiscard]] const MeshSpec& spec() const { return spec_; }
  [[nodiscard]] const BoundaryConditions& boundary() const { return bc_; }
  [[nodiscard]] int size() const { return dofs_.free_count(); }

  /// Global matrices over the free DOFs (full symmetric storage, column-major).
  [[nodiscard]] SparseMatrix stiffness() const;
  [[nodiscard]] SparseMatrix mass() const;
  [[nodiscard]] SparseMatrix mass(MassMatrix kind) const;
  [[nodiscard]] SparseMatrix geometric_stiffness(const Eigen::Matrix2d& N) const;

  /// Throws std::invalid_argument when (x, y) is outside the plate.
  [[nodiscard]] PointSampler sampler(double x, double y) const;
  [[nodiscard]] Eigen::VectorXd point_load(double x, double y, double force) const;
  [[nodiscard]] Eigen::VectorXd pressure_load(double q) const;
  /// Uniform pressure force/(dx dy) over the rectangle centred at (x, y), clipped to the plate.
  [[nodiscard]] Eigen::VectorXd patch_load(const PatchLoad& patch) const;

  /// Nodal vector (5 per node, zeros where restrained) from free DOFs.
  [[nodiscard]] Eigen::VectorXd to_nodal(const Eigen::VectorXd& u) const;
  [[nodiscard]] ElementVector element_dofs(const Eigen::VectorXd& u, int e) const;

private:
  using ElementKernel = std::function<ElementMatrix(const ElementCoordinates&)>;
  [[nodiscard]] SparseMatrix assemble(const ElementKernel& kernel) const;
  void build_pattern();

  Laminate laminate_;
  PlateMesh mesh_;
  MeshSpec spec_;
  BoundaryConditions bc_;
  DofMap dofs_;
  MindlinQ9 element_;
  SparseMatrix pattern_;            ///< structure of every global matrix, values zero
  std::vector<int> first_equation_; ///< first free equation of each node (−1 if none)
};

/// The formulation actually used: `automatic` becomes q9 when some edge has w restrained along its
/// whole length (which suppresses q9's single spurious mode, docs/elements.md) and mitc9 otherwise
/// (free plates, plates on point supports).
[[nodiscard]] ElementFormulation resolve_formulation(ElementFormulation requested, const PlateMesh& mesh,
                                                     const BoundaryConditions& bc);

/// Rigid-body motions of the plate that the restraints leave free (empty when properly supported),
/// each described in words, e.g. "translation along z (w)".
[[nodiscard]] std::vector<std::string> unrestrained_rigid_motions(const PlateModel& model);

} // namespace plyimpact
