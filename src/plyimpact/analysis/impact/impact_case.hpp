#pragma once
// The impact engine's facade: one impact case, built once, run any number of times. Every entry point
// (the impact and threshold commands, sweeps on threads and MPI ranks, Python) describes a case as
// plain data, builds an ImpactCase and calls run(); none of them owns a time loop, a factorization or
// the wiring of an observer.
//
//   ImpactCaseDescription ──► ImpactCase: mesh → sections → DiscretePlate → step policy (factorization)
//                                 └─ run(RunRequest: impactor, observers) → ImpactResult
//
// The model (linear or geometrically non-linear), the contact law, the contact load and the time step
// are chosen here, once. Runs that change only the impactor (velocity, mass, radius, contact stiffness)
// reuse the plate and its factorization.
#include "plyimpact/analysis/impact/capabilities.hpp"
#include "plyimpact/analysis/impact/impact_loop.hpp"
#include "plyimpact/analysis/impact/impact_observer.hpp"
#include "plyimpact/analysis/impact/mass_scaling.hpp"
#include "plyimpact/analysis/impact/parameters.hpp"
#include "plyimpact/analysis/integrators/step_policy.hpp"
#include "plyimpact/fem/boundary.hpp"
#include "plyimpact/fem/discrete_plate.hpp"
#include "plyimpact/fem/regions.hpp"
#include "plyimpact/fem/spd_solver.hpp"

#include <atomic>
#include <memory>
#include <optional>
#include <vector>

namespace plyimpact {

/// A whole impact case (SI; "auto" where the deck says so).
struct ImpactCaseDescription {
  PlateGeometry plate; ///< the rectangle of the structured mesh (unused with mesh_from_file)
  MeshSpec mesh;
  /// a mesh read from a file (io/mesh/gmsh_mesh.hpp): the plate's shape and elements, instead of the
  /// rectangle and MeshSpec's counts and grading
  std::shared_ptr<const Mesh> mesh_from_file;
  std::vector<Laminate> laminates; ///< [0] is the plate's own; regions refer to the others
  std::vector<Region> regions;
  BoundaryConditions boundary;
  Impactor impactor;
  ContactLawParameters contact;
  TimeStepping time;
  std::optional<NonlinearImpactSettings> nonlinear; ///< engaged: the geometrically non-linear plate
  /// engaged: the plies lose stiffness as they crack (fem/damaged_plate.hpp, docs/progressive_damage.md)
  std::optional<ProgressiveDamageSettings> progressive_damage;
  /// engaged: the laminate cut into sub-laminates tied by cohesive interfaces that may delaminate
  /// (fem/stacked_model.cpp, docs/delamination.md)
  std::optional<DelaminationSettings> delamination;
  /// Newton–Newmark's iterations, for an expert (tests give two runs the same); empty: the defaults of the
  /// model's row of the table of what runs (analysis/integrators/newton_settings.hpp).
  std::optional<NewtonSettings> newton;
  SparseSolverKind solver = SparseSolverKind::cholmod_simplicial;
  FillOrdering ordering = FillOrdering::amd; ///< of the factor of K̄ (bench/README.md, "Orderings")
  std::optional<double> memory_limit_bytes;  ///< refuse a factor of K̄ estimated above this
  /// Equal in every input (mesh_from_file: the same mesh object; same_plate compares its content).
  friend bool operator==(const ImpactCaseDescription&, const ImpactCaseDescription&) = default;
};

/// True when `a` and `b` make the same plate, step policy and factors, so that the runs of one may use the
/// ImpactCase of the other (RunRequest): they differ at most in what a run may change, the impactor and
/// the contact stiffness, and not in what the impactor sets of the case (the resolved time step, and on a
/// graded mesh its element size and its impact point). The memory limit, measured when each deck is read,
/// is a guard of the build and is not compared. Sweeps share factorizations between such cases.
[[nodiscard]] bool same_plate(const ImpactCaseDescription& a, const ImpactCaseDescription& b);

/// The settings of a case with every "auto" resolved (SPEC §4 rules, contact_rules.hpp).
/// The mesh a case runs on, for the report (issue 16: the output says which mesh was used).
struct MeshUsed {
  int elements = 0;
  ElementFormulation element = ElementFormulation::q9; ///< resolved (never `automatic`)
  bool graded = false;                                 ///< graded toward the impact point
  double smallest_element = 0.0;                       ///< longest side of the smallest element [m]
  double largest_element = 0.0;                        ///< longest side of the largest element [m]
};

/// The mesh `model` runs on; `graded`: built graded toward the impact point.
[[nodiscard]] MeshUsed mesh_used(const DiscretePlate& model, bool graded);

struct ImpactSettings {
  Impactor impactor;
  MeshUsed mesh; ///< filled by ImpactCase
  /// What sets the stable step of an explicit run (filled by ImpactCase; empty for implicit steps)
  std::optional<StableStepSource> stable_step;
  /// What mass scaling added (filled by ImpactCase; empty without, and for implicit steps)
  std::optional<MassScalingReport> mass_scaling;
  double k = 0.0; ///< contact stiffness [N/m^1.5]
  ContactLawParameters contact;
  double dt = 1e-6;          ///< [s]
  std::optional<double> end; ///< [s]; empty: end_rule
  EventEnd end_rule = EventEnd::re_hit;
  double newmark_beta = 0.25, newmark_gamma = 0.5;
  long max_steps = 2'000'000;
  std::optional<double> stop_at_energy_error;    ///< [time] stop_at_energy_error (fraction of ½ m v0²)
  std::optional<AdaptiveTimeStep> adaptive;      ///< engaged: dt is the largest of the error-controlled steps
  Integrator integration = Integrator::implicit; ///< the one integrator of the plate (capabilities.hpp)
  bool rigid_target = false;
  std::optional<NonlinearImpactSettings> nonlinear;
  std::optional<ProgressiveDamageSettings> progressive_damage;
  std::optional<DelaminationSettings> delamination;
};

/// k (given or the modified Hertz constant of the impactor on the impacted ply at the impact point).
[[nodiscard]] double resolved_contact_stiffness(const ImpactCaseDescription& d);
[[nodiscard]] ImpactSettings resolved_settings(const ImpactCaseDescription& d);
/// ω_max of what an explicit step policy of `d` moves on `model` ([damage] or [delamination] integration =
/// "explicit": the undamaged plate, or the elastic stack; step_policy.hpp) [rad/s]; empty otherwise.
[[nodiscard]] std::optional<double> explicit_highest_frequency(const ImpactCaseDescription& d,
                                                               const DiscretePlate& model);
/// The same with the rules that need the plate: with an explicit step, dt = "auto" is at most the stable
/// step 0.9 · 2/ω_max of `explicit_omega_max` (explicit_highest_frequency). What ImpactCase runs with.
[[nodiscard]] ImpactSettings resolved_settings(const ImpactCaseDescription& d,
                                               std::optional<double> explicit_omega_max);
/// resolved_settings with explicit_highest_frequency(d, model).
[[nodiscard]] ImpactSettings resolved_settings(const ImpactCaseDescription& d, const DiscretePlate& model);
/// The largest contact radius expected: the rigid-target Hertz estimate √(R α_m) (contact_rules.hpp) [m].
[[nodiscard]] double expected_contact_radius(const ImpactCaseDescription& d);
/// The element size at the impact point of a graded mesh [m] (0 for a uniform one): the deck's
/// size_at_impact, or the expected contact radius rounded down to a step of 2^(1/4) from 1 mm.
[[nodiscard]] double size_at_impact(const ImpactCaseDescription& d);
/// The case's mesh: nx × ny uniform, or graded toward the impact point (MeshSpec::grading).
[[nodiscard]] Mesh impact_mesh(const ImpactCaseDescription& d);
/// The plate of a case: the mesh with its regions' laminates, or a single element when the target is
/// rigid (it only carries the impact point).
[[nodiscard]] DiscretePlate impact_plate_model(const ImpactCaseDescription& d);

/// What one run asks for besides the case.
struct RunRequest {
  std::optional<Impactor> impactor;          ///< replaces the case's (same plate and Δt)
  std::optional<double> contact_stiffness;   ///< replaces the case's k [N/m^1.5]
  std::vector<ImpactObserver*> observers;    ///< see every step
  int history_every = 1;                     ///< ImpactResult::history every k-th step; 0: none
  std::vector<double> field_times;           ///< ImpactResult::fields at these times [s]
  const std::atomic<bool>* cancel = nullptr; ///< stop after the current step when set
  /// Follow the plate at the contact point alone, through its impulse response there (computed once per
  /// impact point and shared by the case's runs; contact_point_response.hpp), where that is exact: the
  /// linear plate under a point load, the trapezoidal rule, fixed Δt. Only when nothing looks at the
  /// plate: no observers, no history, no fields. ImpactResult::contact_point_response says whether it was.
  bool contact_point_response = false;
  /// A step that cannot be solved (NewtonFailure: the iterations stop converging, the explicit step turns
  /// unstable) or that a ply law refuses (BandLimitError: a mode starts in an element above its band
  /// limit) ends the run with what it has computed, ImpactResult::failure saying why, instead of
  /// throwing: for io/run/impact_run.cpp, which writes the results and then reports the failure.
  bool keep_failed_run = false;
  /// Threads of the run's element loops (fem/element_loop.hpp; the same bits for any number); 0: the
  /// calling thread's OpenMP setting, all cores unless OMP_NUM_THREADS says otherwise (a sweep's workers
  /// run theirs on one).
  int threads = 0;
};

class ImpactCase {
public:
  /// Builds the plate, chooses the step policy and factors K̄. Throws std::invalid_argument for a case
  /// that cannot run (non-positive Δt or mass, options the policy does not support), InsufficientMemory.
  explicit ImpactCase(ImpactCaseDescription description);
  ~ImpactCase();
  ImpactCase(const ImpactCase&) = delete;
  ImpactCase& operator=(const ImpactCase&) = delete;

  [[nodiscard]] ImpactResult run(const RunRequest& request = {}) const;

  [[nodiscard]] const ImpactCaseDescription& description() const { return description_; }
  [[nodiscard]] const ImpactSettings& settings() const { return settings_; }
  /// T1 of the plate for the end-of-event rule [s]; 0 where time.end is given or the target is rigid.
  [[nodiscard]] double fundamental_period() const { return fundamental_period_; }
  [[nodiscard]] const DiscretePlate& model() const { return *model_; }
  [[nodiscard]] bool nonlinear() const { return settings_.nonlinear.has_value(); }
  /// explicit_highest_frequency of the case, computed once: its policy and its runs' settings share it.
  [[nodiscard]] std::optional<double> explicit_omega_max() const { return explicit_omega_max_; }
  /// Equations of the time loop.
  [[nodiscard]] int equations() const { return policy_->equations(); }
  /// Seconds for one triangular solve pair with the factor of K̄ (median of `repeats`; benchmarks).
  [[nodiscard]] double time_one_solve(int repeats = 21) const {
    const SpdSolver* factor = policy_->shared_factor();
    return factor && policy_->equations() > 0 ? factor->median_solve_seconds(policy_->equations(), repeats)
                                              : 0.0;
  }

private:
  ImpactCaseDescription description_;
  ImpactSettings settings_;
  std::unique_ptr<DiscretePlate> model_;
  std::optional<double> explicit_omega_max_;
  std::unique_ptr<StepPolicy> policy_;
  double fundamental_period_ = 0.0;
};

} // namespace plyimpact
