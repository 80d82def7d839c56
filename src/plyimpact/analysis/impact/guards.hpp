#pragma once
// Numerical guards of an impact run (docs/robustness.md): non-finite states stop the run with the
// step, time and quantity named; a time step too coarse for the contact and an impact point on an
// element boundary give warnings; the factor of K̄ is estimated before it is computed and refused
// when it would not fit in the available memory. After the run: an energy balance error above
// energy_balance_tolerance marks it suspect, a linear run deflected beyond max_linear_deflection
// thicknesses warns, a time.end that comes before the impactor has left the plate leaves it incomplete.
#include "plyimpact/analysis/contact/contact_rules.hpp"
#include "plyimpact/analysis/impact/parameters.hpp"
#include "plyimpact/fem/discrete_plate.hpp"
#include "plyimpact/fem/mesh.hpp"
#include "plyimpact/fem/spd_solver.hpp"

#include <Eigen/Core>
#include <cstddef>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace plyimpact {

/// A NaN or infinity appeared in a time step. what() names the step, the time and the quantity.
class NonFiniteState : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// The factorization would need more memory than is available. what() gives the estimate.
class InsufficientMemory : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// One scalar of the step state, named with its symbol and unit for the message.
struct StepQuantity {
  std::string_view name;
  double value;
};

/// Throws NonFiniteState naming the first non-finite quantity (in the order given).
void check_finite_step(long step, double t, std::initializer_list<StepQuantity> quantities);
/// Throws NonFiniteState naming `name` and the first non-finite entry (equation index) of `v`.
void check_finite_vector(long step, double t, std::string_view name, const Eigen::VectorXd& v);

/// Fewest time steps over the Hertz contact time that resolve the force pulse.
constexpr double min_steps_per_contact = 50.0;

/// A warning with the suggested Δt when Δt > t_c / 50 (t_c = hertz_contact_time).
[[nodiscard]] std::optional<std::string> time_step_warning(double mass, double velocity, double k, double dt,
                                                           double exponent = 1.5);

/// A warning when the impact point lies on an element edge or node (|ξ| or |η| = 1): the contact
/// force and ws then sit on an element boundary, where the mesh cannot place the point inside an
/// element's interior.
[[nodiscard]] std::optional<std::string> impact_point_warning(const Mesh& mesh, double x, double y);

/// Elements larger than this many expected contact radii at the impact point: the contact is no longer
/// resolved (a Hertz pressure acts like a point force, whose result depends on where it lands).
constexpr double max_element_per_contact_radius = 4.0;

/// A warning when the element holding the impact point is larger than max_element_per_contact_radius
/// times the expected contact radius, or when the load is a point force on an element larger than it
/// (a point load on a Mindlin plate has no mesh-converged answer).
[[nodiscard]] std::optional<std::string> contact_mesh_warning(const Mesh& mesh, double x, double y,
                                                              double contact_radius, ContactLoad load);

/// time.end shorter than one time step: the first step would already pass it. Throws
/// std::invalid_argument naming both keys (the run is refused, not clamped: Δt is fixed by the
/// factorization of K̄ = K + c0(Δt) M).
void check_end_after_first_step(double dt, const std::optional<double>& end);

/// Largest |½ m v0² − (impactor kinetic + plate kinetic + plate strain + contact work)| at the end of a
/// run, as a fraction of ½ m v0², that is not suspect. The contact work is the law's exact ∫F dα
/// (HertzContact::work). Time-step errors, the Hertz pressure's varying footprint and the non-linear
/// plate leave less than 0.2 % on every shipped example (0.161 % at most, docs/robustness.md); a Δt
/// far too coarse for the contact gives hundreds of percent.
constexpr double energy_balance_tolerance = 0.01;

/// What a finished run tells about where its energy error came from (energy_balance_reason).
struct EnergyBalanceClues {
  ContactLoad load = ContactLoad::point;
  double dissipated_fraction = 0.0; ///< the plate's dissipation over the initial kinetic energy
  std::size_t contact_episodes = 1; ///< separate contacts of the impactor
};

/// The plate dissipated more than this fraction of the impact energy, or the impactor struck this many
/// times: the plate collapsed under it (energy_balance_reason).
constexpr double collapse_dissipated_fraction = 0.5;
constexpr std::size_t collapse_contact_episodes = 3;

/// The reason a run is suspect when energy_error (fraction of initial_energy) > energy_balance_tolerance:
/// the error, the energies, and the likely cause with what to do, in this order: a Δt too coarse for the
/// Hertz contact time t_c (lower it); a collapse of the plate under the impactor (`clues`); the Hertz
/// pressure load's own balance term (docs/progressive_damage.md: run with the point load to see the
/// integration's error); else what changes within a step (halve Δt and compare).
[[nodiscard]] std::optional<std::string> energy_balance_reason(double energy_error, double initial_energy,
                                                               double mass, double velocity, double k,
                                                               double dt, double exponent = 1.5,
                                                               const EnergyBalanceClues& clues = {});

/// Peak deflection, in laminate thicknesses h, beyond which a linear plate overestimates the deflection
/// (membrane stretching stiffens it): the usual small-deflection limit of plate theory, about 0.3 h.
constexpr double max_linear_deflection = 0.3;

/// The largest kinetic energy the added mass of a mass-scaled run may carry before the run warns, as a
/// fraction of the impact energy (docs/mass_scaling.md).
constexpr double added_mass_energy_tolerance = 0.01;

/// A warning where the added mass of a mass-scaled run carried more than added_mass_energy_tolerance of the
/// impact energy `e0` at some step (its largest kinetic energy `added_kinetic`) [J].
[[nodiscard]] std::optional<std::string> added_mass_warning(double added_kinetic, double e0);

/// A warning where a run with selective mass scaling (`interface_mass_factor` > 0: how many times heavier
/// the faces' relative motion became) delaminated an interface (`delaminated_area` [m²]) and broke plies
/// (`fibre_dissipation` [J] > 0): the faces of a cracked interface keep the added relative inertia, and on
/// the damage-trend study such runs matched the unscaled ones up to the load drop, not after it
/// (docs/validation.md §20, docs/mass_scaling.md "Limits").
[[nodiscard]] std::optional<std::string> selective_scaling_after_drop_warning(double interface_mass_factor,
                                                                              double delaminated_area,
                                                                              double fibre_dissipation);

/// A warning suggesting `nonlinear = true` when a linear run's peak deflection exceeds
/// max_linear_deflection times the laminate thickness h.
[[nodiscard]] std::optional<std::string> large_deflection_warning(double peak_deflection, double thickness);

/// Memory of a sparse LDLᵀ factorization of A, from its symbolic analysis (AMD ordering).
struct FactorMemoryEstimate {
  long equations = 0;
  long matrix_nonzeros = 0; ///< of A (both triangles)
  long factor_nonzeros = 0; ///< of L (strictly lower), from the elimination tree
  double bytes = 0.0;       ///< 12 bytes (value + row index) per non-zero of L, D, A and K, M copies
};

/// The estimate for a factor of `factor_nonzeros` entries below the diagonal.
[[nodiscard]] FactorMemoryEstimate estimate_factor_memory(const SparseMatrix& A, long factor_nonzeros);
/// The estimate from an analysis of A (Eigen's LDLᵀ, AMD), made for it alone.
[[nodiscard]] FactorMemoryEstimate estimate_factor_memory(const SparseMatrix& A);
/// The estimate from `solver`'s own analysis of A, which its factorization of A then reuses (the
/// ordering is not computed twice).
[[nodiscard]] FactorMemoryEstimate estimate_factor_memory(SpdSolver& solver, const SparseMatrix& A);

/// Throws InsufficientMemory with the estimate when estimate.bytes > available_bytes.
void check_factor_memory(const FactorMemoryEstimate& estimate, double available_bytes);

} // namespace plyimpact
