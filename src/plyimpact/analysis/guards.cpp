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

double hertz_contact_time(double mass, double velocity, double k) {
  const double alpha_max = std::pow(5.0 * mass * velocity * velocity / (4.0 * k), 0.4); // energy balance
  const double beta_2_5_1_2 = std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);   // B(2/5, 1/2)
  return 0.8 * beta_2_5_1_2 * alpha_max / velocity;                                     // 2.9432 α_m/v0
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

std::optional<std::string> impact_point_warning(const PlateMesh& mesh, double x, double y) {
  const auto loc = mesh.locate(x, y);
  if (!loc) return std::nullopt; // outside: refused by the deck reader
  constexpr double edge = 1.0 - 1e-9;
  const bool on_xi = std::abs(loc->xi) >= edge, on_eta = std::abs(loc->eta) >= edge;
  if (!on_xi && !on_eta) return std::nullopt;
  return fmt::format(
      "the impact point ({:.6g}, {:.6g}) m lies on an element {} of the {} x {} mesh, not inside "
      "an element: the contact force and deflection sit on an element boundary. Change "
      "mesh.nx/mesh.ny so that the point falls inside an element (an odd count for a "
      "central impact)",
      x, y, on_xi && on_eta ? "corner" : "edge", mesh.nx(), mesh.ny());
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
