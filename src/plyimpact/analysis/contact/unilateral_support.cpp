#include "plyimpact/analysis/contact/unilateral_support.hpp"

#include "plyimpact/analysis/plate_analyses/static_analysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace plyimpact {

int touching_count(const std::vector<SupportContact>& contacts) {
  return static_cast<int>(
      std::ranges::count_if(contacts, [](const SupportContact& c) { return c.touching; }));
}

double largest_lift_off(const std::vector<SupportContact>& contacts) {
  double lift = 0.0;
  for (const SupportContact& c : contacts)
    lift = std::max(lift, -c.w);
  return lift;
}

double total_reaction(const std::vector<SupportContact>& contacts) {
  double sum = 0.0;
  for (const SupportContact& c : contacts)
    sum += c.reaction;
  return sum;
}

namespace {

constexpr int max_passes = 100;
constexpr std::string_view held_set = "unilateral support, in contact";

/// `model` with the nodes `touching` held in w (a node set of their own with code 00100).
DiscretePlate holding(const DiscretePlate& model, const std::vector<int>& touching) {
  Mesh mesh = model.mesh();
  mesh.add_node_set(std::string(held_set), touching);
  std::vector<int> of_element;
  if (!model.single_section())
    for (int e = 0; e < mesh.element_count(); ++e)
      of_element.push_back(model.section_index(e));
  BoundaryConditions bc = model.boundary();
  bc.set(held_set, "00100");
  return {std::move(mesh), PlateSections{model.laminates(), std::move(of_element)},
          Discretization{model.mass_kind(), model.formulation()}, std::move(bc)};
}

/// The free-DOF vector of `to` holding the nodal values of `u` (free DOFs of `from`, same mesh).
Eigen::VectorXd transfer(const DiscretePlate& from, const Eigen::VectorXd& u, const DiscretePlate& to) {
  const Eigen::VectorXd nodal = from.to_nodal(u);
  Eigen::VectorXd v = Eigen::VectorXd::Zero(to.size());
  for (int n = 0; n < to.mesh().node_count(); ++n)
    for (int d = 0; d < dofs_per_node; ++d)
      if (const int eq = to.dofs().equation(n, d); eq >= 0) v(eq) = nodal(dofs_per_node * n + d);
  return v;
}

Eigen::VectorXd solve_holding(const DiscretePlate& model, const std::vector<int>& touching,
                              const StaticLoad& load) {
  const DiscretePlate held = holding(model, touching);
  try {
    const SpdSolver solver = factor_stiffness(held, held.stiffness());
    return transfer(held, solver.solve(static_load_vector(held, load)), model);
  } catch (const InsufficientRestraint& e) {
    throw InsufficientRestraint(
        fmt::format("the plate lifts off its unilateral supports at {} nodes, and what holds it then "
                    "leaves it free: {}",
                    touching.empty() ? "all" : "most", e.what()));
  }
}

} // namespace

UnilateralSolution solve_unilateral_static(const DiscretePlate& model, const StaticLoad& load) {
  const std::vector<int> nodes = unilateral_nodes(model.mesh(), model.boundary());
  // The model leaves the support's w free: K u − f at those equations is the support's force.
  const SparseMatrix K = model.stiffness();
  const Eigen::VectorXd f = static_load_vector(model, load);
  const double force_scale = std::max(f.lpNorm<Eigen::Infinity>(), 1e-300);
  std::vector<char> touching(nodes.size(), 1);
  UnilateralSolution s;
  for (s.iterations = 1; s.iterations <= max_passes; ++s.iterations) {
    std::vector<int> held;
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (touching[i]) held.push_back(nodes[i]);
    s.u = solve_holding(model, held, load);
    const Eigen::VectorXd R = K * s.u - f;
    const double w_scale = std::max(s.u.lpNorm<Eigen::Infinity>(), 1e-300);
    bool changed = false;
    s.contacts.clear();
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const int eq = model.dofs().equation(nodes[i], 2);
      const SupportContact c{nodes[i], touching[i] != 0, touching[i] ? R(eq) : 0.0, s.u(eq)};
      const bool pulls = c.touching && c.reaction > 1e-9 * force_scale;
      const bool sinks = !c.touching && c.w > 1e-9 * w_scale;
      if (pulls || sinks) {
        touching[i] = touching[i] ? 0 : 1;
        changed = true;
      }
      s.contacts.push_back(c);
    }
    if (!changed) return s;
  }
  throw std::runtime_error(fmt::format(
      "unilateral support: the contact set of {} nodes did not settle in {} solves (a load that "
      "alternately lifts and presses the plate on the support); check the load's sign (+z is the impact "
      "direction) or hold part of the support with \"ss-soft\"",
      nodes.size(), max_passes));
}

} // namespace plyimpact
