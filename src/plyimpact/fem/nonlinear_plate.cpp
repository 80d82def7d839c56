#include "plyimpact/fem/nonlinear_plate.hpp"

#include "plyimpact/fem/element_loop.hpp"

#include <algorithm>
#include <map>

namespace plyimpact {

NonlinearPlate::NonlinearPlate(const DiscretePlate& model, StrainMeasure measure)
    : model_(model), element_(model.element(), measure), pattern_(model.pattern()),
      gather_(model.size(), model.mesh().element_count(),
              [&model](int e) -> const ElementEquations& { return model.element_equations(e); }) {
  const Mesh& mesh = model.mesh();
  std::map<std::pair<int, int>, int> known; // (section, shape class) → geometry
  for (int e = 0; e < mesh.element_count(); ++e) {
    const std::pair<int, int> key{model.section_index(e), mesh.shape_class(e)};
    auto [it, added] = known.emplace(key, static_cast<int>(geometry_.size()));
    if (added)
      geometry_.push_back(element_.geometry(mesh.element_coordinates(mesh.representative(key.second)),
                                            model.section(key.first).stiffness));
    geometry_index_.push_back(it->second);
  }
  slot_ = element_slots(model, pattern_);
}

Eigen::VectorXd NonlinearPlate::internal_force(const Eigen::VectorXd& u) const {
  Eigen::VectorXd f(model_.size());
  internal_force(u, f);
  return f;
}

void NonlinearPlate::internal_force(const Eigen::VectorXd& u, Eigen::VectorXd& f) const {
  std::vector<ElementVector> element_forces;
  internal_force(u, f, element_forces);
}

void NonlinearPlate::internal_force(const Eigen::VectorXd& u, Eigen::VectorXd& f,
                                    std::vector<ElementVector>& element_forces) const {
  const int elements = model_.mesh().element_count();
  element_forces.resize(static_cast<std::size_t>(elements));
  for_each_element(elements, [&](int e) {
    element_forces[static_cast<std::size_t>(e)] =
        element_.internal_force(geometry_of(e), section_of(e), gather(u, model_.element_equations(e)));
  });
  gather_.assemble(element_forces, f); // each equation's terms in element order, as one thread adds them
}

SparseMatrix NonlinearPlate::tangent_stiffness(const Eigen::VectorXd& u) const {
  SparseMatrix K = pattern_;
  double* values = K.valuePtr();
  for (int e = 0; e < model_.mesh().element_count(); ++e) {
    const ElementMatrix Ke =
        element_.tangent_stiffness(geometry_of(e), section_of(e), gather(u, model_.element_equations(e)));
    add_element_values(values, slot_[static_cast<std::size_t>(e)], Ke);
  }
  return K;
}

} // namespace plyimpact
