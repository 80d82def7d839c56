#pragma once
// The plate's non-linear internal force vector and tangent stiffness over the free DOFs (SPEC §8),
// assembled from NonlinearMindlinQ9 into the sparsity pattern of the linear DiscretePlate.
#include "plyimpact/fem/discrete_plate.hpp"
#include "plyimpact/fem/equation_gather.hpp"
#include "plyimpact/fem/nonlinear_plate_element.hpp"

#include <vector>

namespace plyimpact {

class NonlinearPlate {
public:
  /// Throws std::invalid_argument when the strain measure is not available with the model's element.
  NonlinearPlate(const DiscretePlate& model, StrainMeasure measure);

  [[nodiscard]] const DiscretePlate& linear() const { return model_; }
  [[nodiscard]] const NonlinearMindlinQ9& element() const { return element_; }
  [[nodiscard]] int size() const { return model_.size(); }

  /// f_int(u) = Σₑ ∫ Gᵀ Eᵀ S dA over the free DOFs.
  [[nodiscard]] Eigen::VectorXd internal_force(const Eigen::VectorXd& u) const;
  /// internal_force(u) into `f` (sized once by the caller): the same numbers without a new vector.
  void internal_force(const Eigen::VectorXd& u, Eigen::VectorXd& f) const;
  /// … with the elements on the run's threads, `element_forces` (one per element, sized here on first use)
  /// their places, added in element order equation by equation, also on threads (EquationGather): the
  /// same bits for any number of threads (element_loop.hpp).
  void internal_force(const Eigen::VectorXd& u, Eigen::VectorXd& f,
                      std::vector<ElementVector>& element_forces) const;
  /// K_T(u) = ∂f_int/∂u, same pattern as DiscretePlate::stiffness().
  [[nodiscard]] SparseMatrix tangent_stiffness(const Eigen::VectorXd& u) const;

private:
  [[nodiscard]] const ElementGeometry& geometry_of(int e) const {
    return geometry_[static_cast<std::size_t>(geometry_index_[static_cast<std::size_t>(e)])];
  }
  [[nodiscard]] const SectionStiffness& section_of(int e) const {
    return model_.section(model_.section_index(e)).stiffness;
  }

  const DiscretePlate& model_;
  NonlinearMindlinQ9 element_;
  std::vector<ElementGeometry> geometry_; ///< one per (element shape, section)
  std::vector<int> geometry_index_;       ///< per element
  SparseMatrix pattern_;                  ///< structure of K_T, values zero
  std::vector<ElementSlots> slot_;        ///< (i, j) of Kₑ → index in pattern_ values
  EquationGather gather_;                 ///< f_int from the element forces, equation by equation
};

} // namespace plyimpact
