#include "plyimpact/fem/nonlinear_plate_model.hpp"

#include <algorithm>

namespace plyimpact {

NonlinearPlateModel::NonlinearPlateModel(const PlateModel& model, StrainMeasure measure)
    : model_(model), element_(model.laminate(), model.element().formulation(), measure),
      pattern_(model.stiffness()) {
  const PlateMesh& mesh = model.mesh();
  if (mesh.is_regular()) {
    geometry_.push_back(element_.geometry(mesh.element_coordinates(0))); // congruent elements
  } else {
    for (int e = 0; e < mesh.element_count(); ++e)
      geometry_.push_back(element_.geometry(mesh.element_coordinates(e)));
  }
  std::fill(pattern_.valuePtr(), pattern_.valuePtr() + pattern_.nonZeros(), 0.0);
  const int* outer = pattern_.outerIndexPtr();
  const int* inner = pattern_.innerIndexPtr();
  for (int e = 0; e < mesh.element_count(); ++e) {
    equations_.push_back(model.dofs().element_equations(mesh, e));
    const auto& eq = equations_.back();
    std::array<int, q9_dofs * q9_dofs> slot{};
    for (int j = 0; j < q9_dofs; ++j)
      for (int i = 0; i < q9_dofs; ++i) {
        const int row = eq[static_cast<std::size_t>(i)], col = eq[static_cast<std::size_t>(j)];
        int s = -1;
        if (row >= 0 && col >= 0)
          s = static_cast<int>(std::lower_bound(inner + outer[col], inner + outer[col + 1], row) - inner);
        slot[static_cast<std::size_t>(j) * q9_dofs + static_cast<std::size_t>(i)] = s;
      }
    slot_.push_back(slot);
  }
}

const ElementGeometry& NonlinearPlateModel::geometry_of(int e) const {
  return geometry_.size() == 1 ? geometry_.front() : geometry_[static_cast<std::size_t>(e)];
}

Eigen::VectorXd NonlinearPlateModel::internal_force(const Eigen::VectorXd& u) const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model_.size());
  ElementVector ue;
  for (std::size_t e = 0; e < equations_.size(); ++e) {
    const auto& eq = equations_[e];
    for (int i = 0; i < q9_dofs; ++i)
      ue(i) = eq[static_cast<std::size_t>(i)] >= 0 ? u(eq[static_cast<std::size_t>(i)]) : 0.0;
    const ElementVector fe = element_.internal_force(geometry_of(static_cast<int>(e)), ue);
    for (int i = 0; i < q9_dofs; ++i)
      if (eq[static_cast<std::size_t>(i)] >= 0) f(eq[static_cast<std::size_t>(i)]) += fe(i);
  }
  return f;
}

SparseMatrix NonlinearPlateModel::tangent_stiffness(const Eigen::VectorXd& u) const {
  SparseMatrix K = pattern_;
  double* values = K.valuePtr();
  ElementVector ue;
  for (std::size_t e = 0; e < equations_.size(); ++e) {
    const auto& eq = equations_[e];
    for (int i = 0; i < q9_dofs; ++i)
      ue(i) = eq[static_cast<std::size_t>(i)] >= 0 ? u(eq[static_cast<std::size_t>(i)]) : 0.0;
    const ElementMatrix Ke = element_.tangent_stiffness(geometry_of(static_cast<int>(e)), ue);
    const auto& slot = slot_[e];
    for (int j = 0; j < q9_dofs; ++j)
      for (int i = 0; i < q9_dofs; ++i)
        if (const int s = slot[static_cast<std::size_t>(j) * q9_dofs + static_cast<std::size_t>(i)]; s >= 0)
          values[s] += Ke(i, j);
  }
  return K;
}

} // namespace plyimpact
