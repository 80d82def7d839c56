#include "plyimpact/analysis/impact/guards.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <string>

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

std::optional<std::string> time_step_warning(double mass, double velocity, double k, double dt,
                                             double exponent) {
  const double t_c = hertz_contact_time(mass, velocity, k, exponent);
  const double steps = t_c / dt;
  if (steps >= min_steps_per_contact) return std::nullopt;
  // One decimal, or three digits below one step (0.0168, not 0.0).
  const std::string count = steps >= 1.0 ? fmt::format("{:.1f}", steps) : fmt::format("{:.3g}", steps);
  return fmt::format(
      "time.dt = {:.4g} s gives only {} steps over the Hertz contact time estimate "
      "t_c = {:.4g} s (rigid target, docs/robustness.md): the force pulse is not resolved; use time.dt "
      "<= {:.4g} s (t_c/{:.0f})",
      dt, count, t_c, t_c / min_steps_per_contact, min_steps_per_contact);
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

void check_end_after_first_step(double dt, const std::optional<double>& end) {
  if (!end || *end >= dt * (1.0 - 1e-9)) return;
  throw std::invalid_argument(fmt::format(
      "impact: time.end = {:.6g} s is shorter than one time step, time.dt = {:.6g} s: the first step would "
      "end past time.end. Set [time] end to at least {:.6g} s (or \"auto\"), or lower [time] dt",
      *end, dt, dt));
}

std::optional<std::string> energy_balance_reason(double energy_error, double initial_energy, double mass,
                                                 double velocity, double k, double dt, double exponent,
                                                 const EnergyBalanceClues& clues) {
  if (!(energy_error > energy_balance_tolerance)) return std::nullopt;
  const double t_c = hertz_contact_time(mass, velocity, k, exponent);
  const std::string what = fmt::format(
      "energy balance error {:.3g} J, {:.3g} % of the initial kinetic energy {:.4g} J (tolerance {:.3g} %): "
      "the time integration created or lost energy and the results are not trustworthy. The Hertz contact "
      "time estimate is t_c = {:.4g} s, {:.3g} steps of time.dt = {:.4g} s",
      energy_error * initial_energy, 100.0 * energy_error, initial_energy, 100.0 * energy_balance_tolerance,
      t_c, t_c / dt, dt);
  if (t_c / dt < min_steps_per_contact)
    return fmt::format("{}: lower [time] dt to t_c/{:.0f} = {:.4g} s or less, or set dt = \"auto\"", what,
                       min_steps_per_contact, t_c / min_steps_per_contact);
  if (clues.dissipated_fraction > collapse_dissipated_fraction ||
      clues.contact_episodes >= collapse_contact_episodes)
    return fmt::format(
        "{}, enough for the contact. Likely cause: the plate collapsed under the impactor ({:.3g} % of the "
        "impact energy dissipated in the plate; contact episodes: {}): plies cracked through the thickness "
        "soften faster than a step follows, and past a perforation the model has no answer. Read the "
        "results up to the first large load drop, or lower the impact energy",
        what, 100.0 * clues.dissipated_fraction, clues.contact_episodes);
  if (clues.load == ContactLoad::hertz_pressure)
    return fmt::format(
        "{}, enough for the contact. Likely cause: the Hertz pressure load's own balance term (the contact "
        "law's work uses the deflection at the contact point, the pressure works on the pressure-weighted "
        "deflection; it does not shrink with Δt and grows as damage softens the plate under the impactor: "
        "docs/progressive_damage.md). Run the deck with [contact] load = \"point\" to see the integration's "
        "own error; if that one is small, the answer stands within this term",
        what);
  // The contact is resolved: the error comes from what changes within a step (damage, interfaces,
  // contact episodes), which a shorter step resolves too.
  return fmt::format("{}, enough for the contact: what changes within a step (ply damage, interfaces that "
                     "break, repeated contacts) made the error; run again with [time] dt = {:.4g} s (half) "
                     "and compare",
                     what, 0.5 * dt);
}

std::optional<std::string> added_mass_warning(double added_kinetic, double e0) {
  if (!(e0 > 0.0) || !(added_kinetic > added_mass_energy_tolerance * e0)) return std::nullopt;
  return fmt::format(
      "the mass added by [time] mass_scaling carried up to {:.4g} J of kinetic energy, {:.3g} % "
      "of the impact energy (more than {:.0f} %): the scaled plate's inertia may have changed "
      "the answer. Give a shorter [time] target_dt, which adds less (docs/mass_scaling.md)",
      added_kinetic, 100.0 * added_kinetic / e0, 100.0 * added_mass_energy_tolerance);
}

std::optional<std::string> selective_scaling_after_drop_warning(double interface_mass_factor,
                                                                double delaminated_area,
                                                                double fibre_dissipation) {
  if (!(interface_mass_factor > 0.0) || !(delaminated_area > 0.0) || !(fibre_dissipation > 0.0))
    return std::nullopt;
  return fmt::format(
      "selective mass scaling, and interfaces delaminated ({:.4g} mm^2) where plies broke (fibre damage): "
      "the faces of a cracked interface keep the added relative inertia ({:.3g} times the unscaled), so "
      "what follows the first load drop may not be the unscaled answer (on the damage-trend study: the "
      "same within 0.2 % up to the drop, absorbed energy -21 to +18 % after it, docs/validation.md §20). "
      "Read the results up to the load drop (F_d), or compare with a run without mass_scaling",
      delaminated_area * 1e6, interface_mass_factor);
}

std::optional<std::string> large_deflection_warning(double peak_deflection, double thickness) {
  if (!(thickness > 0.0) || !(peak_deflection > max_linear_deflection * thickness)) return std::nullopt;
  return fmt::format(
      "the peak deflection {:.4g} mm is {:.3g} times the laminate thickness h = {:.4g} mm in a "
      "linear run: beyond about {:.1f} h membrane stretching stiffens the plate and the "
      "linear model overestimates the deflection and underestimates the force. Set "
      "nonlinear = true at the top of the deck (or run with --nonlinear; docs/nonlinear.md)",
      peak_deflection * 1e3, peak_deflection / thickness, thickness * 1e3, max_linear_deflection);
}

FactorMemoryEstimate estimate_factor_memory(const SparseMatrix& A, long factor_nonzeros) {
  FactorMemoryEstimate e;
  e.equations = A.rows();
  e.matrix_nonzeros = A.nonZeros();
  e.factor_nonzeros = factor_nonzeros;
  constexpr double bytes_per_nonzero = 8.0 + 4.0; // double value + int row index
  // L and D, plus A and the K, M it is made of (three matrices of A's pattern).
  e.bytes = bytes_per_nonzero * static_cast<double>(e.factor_nonzeros + e.equations + 3 * e.matrix_nonzeros);
  return e;
}

FactorMemoryEstimate estimate_factor_memory(const SparseMatrix& A) {
  return estimate_factor_memory(A, SpdSolver(SparseSolverKind::simplicial_ldlt).analyse(A));
}

FactorMemoryEstimate estimate_factor_memory(SpdSolver& solver, const SparseMatrix& A) {
  return estimate_factor_memory(A, solver.analyse(A));
}

void check_factor_memory(const FactorMemoryEstimate& e, double available_bytes) {
  if (e.bytes <= available_bytes) return;
  throw InsufficientMemory(fmt::format(
      "the factorization of K̄ ({} equations, {} non-zeros in the factor) needs about {:.3g} MB but only "
      "{:.3g} MB are available: use a coarser mesh (mesh.nx, mesh.ny) or free memory",
      e.equations, e.factor_nonzeros, e.bytes / 1e6, available_bytes / 1e6));
}

} // namespace plyimpact
