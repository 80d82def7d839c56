#include "plyimpact/analysis/guards.hpp"

#include <Eigen/SparseCholesky>
#include <fmt/format.h>

#include <cmath>

namespace plyimpact {

void check_finite_step(long step, double t, std::initializer_list<StepQuantity> quantities) {
  for (const StepQuantity& q : quantities)
    if (!std::isfinite(q.value))
      throw NonFiniteState(fmt::format("impact: non-finite {} at step {} (t = {:.6g} s): {} = {}; the run is "
                                       "stopped. Check the deck's magnitudes (impactor velocity and mass, "
                                       "contact.k, material moduli) and time.dt",
                                       q.name, step, t, q.name, q.value));
}

void check_finite_vector(long step, double t, std::string_view name, const Eigen::VectorXd& v) {
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (!std::isfinite(v(i)))
      throw NonFiniteState(
          fmt::format("impact: non-finite {} at step {} (t = {:.6g} s): entry {} of {} is {}; "
                      "the run is stopped. Check the deck's magnitudes (impactor velocity "
                      "and mass, contact.k, material moduli) and time.dt",
                      name, step, t, i, v.size(), v(i)));
}

std::optional<std::string> time_step_warning(double mass, double velocity, double k, double dt) {
  const double t_c = hertz_contact_time(mass, velocity, k);
  const double steps = t_c / dt;
  if (steps >= min_steps_per_contact) return std::nullopt;
  return fmt::format("time.dt = {:.4g} s gives only {:.1f} steps over the Hertz contact time estimate "
                     "t_c = {:.4g} s (rigid target, SPEC §4): the force pulse is not resolved; use time.dt "
                     "<= {:.4g} s (t_c/{:.0f})",
                     dt, steps, t_c, t_c / min_steps_per_contact, min_steps_per_contact);
}

std::optional<std::string> impact_point_warning(const Mesh& mesh, double x, double y) {
  const auto loc = mesh.locate(x, y);
  if (!loc) return std::nullopt; // outside: refused by the deck reader
  constexpr double edge = 1.0 - 1e-9;
  const bool on_xi = std::abs(loc->xi) >= edge, on_eta = std::abs(loc->eta) >= edge;
  if (!on_xi && !on_eta) return std::nullopt;
  const std::string grid = mesh.grid() ? fmt::format("the {} x {} mesh", mesh.grid()->nx, mesh.grid()->ny)
                                       : std::string("the mesh");
  return fmt::format("the impact point ({:.6g}, {:.6g}) m lies on an element {} of {}, not inside "
                     "an element: the contact force and deflection sit on an element boundary. Change "
                     "mesh.nx/mesh.ny so that the point falls inside an element (an odd count for a "
                     "central impact)",
                     x, y, on_xi && on_eta ? "corner" : "edge", grid);
}

std::optional<std::string> contact_mesh_warning(const Mesh& mesh, double x, double y, double contact_radius,
                                                ContactLoad load) {
  const auto loc = mesh.locate(x, y);
  if (!loc || !(contact_radius > 0.0)) return std::nullopt;
  const double size = std::sqrt(mesh.element_area(loc->element));
  const double ratio = size / contact_radius;
  if (ratio <= max_element_per_contact_radius) return std::nullopt;
  return fmt::format("the element under the impactor is {:.3g} mm, {:.1f} times the largest contact radius "
                     "expected ({:.3g} mm): the contact is not resolved{}; refine the mesh there (leave out "
                     "mesh.nx and mesh.ny for a mesh graded toward the impact point, docs/deck.md)",
                     size * 1e3, ratio, contact_radius * 1e3,
                     load == ContactLoad::point
                         ? " and the point load's peak force depends on the mesh and on where the impactor "
                           "lands (contact.load = \"hertz-pressure\" converges)"
                         : ", the pressure acts like a point force");
}

namespace {

/// SimplicialLDLT whose symbolic analysis (column counts of L) is readable before factorization.
class SymbolicLDLT : public Eigen::SimplicialLDLT<SparseMatrix> {
public:
  explicit SymbolicLDLT(const SparseMatrix& A) { analyzePattern(A); }
  [[nodiscard]] long factor_nonzeros() const { return m_matrix.outerIndexPtr()[m_matrix.outerSize()]; }
};

} // namespace

FactorMemoryEstimate estimate_factor_memory(const SparseMatrix& A) {
  FactorMemoryEstimate e;
  e.equations = A.rows();
  e.matrix_nonzeros = A.nonZeros();
  e.factor_nonzeros = SymbolicLDLT(A).factor_nonzeros();
  constexpr double bytes_per_nonzero = 8.0 + 4.0; // double value + int row index
  // L and D, plus A and the K, M it is made of (three matrices of A's pattern).
  e.bytes = bytes_per_nonzero * static_cast<double>(e.factor_nonzeros + e.equations + 3 * e.matrix_nonzeros);
  return e;
}

void check_factor_memory(const FactorMemoryEstimate& e, double available_bytes) {
  if (e.bytes <= available_bytes) return;
  throw InsufficientMemory(fmt::format(
      "the factorization of K̄ ({} equations, {} non-zeros in the factor) needs about {:.3g} MB but only "
      "{:.3g} MB are available: use a coarser mesh (mesh.nx, mesh.ny) or free memory",
      e.equations, e.factor_nonzeros, e.bytes / 1e6, available_bytes / 1e6));
}

} // namespace plyimpact
