#pragma once
// Step policies: how the plate advances one step together with the contact force. The time loop
// (impact_loop.hpp) is the same for all of them; only the solution of the step differs, by integrator
// (the one factory of them, step_policy(), picks the cell of capabilities.hpp):
//
//   linear Newmark      the linear elastic plate: K̄ = K + c0 M factored once per case, the exact scalar
//                       contact solve on the load-free predictor (SPEC §4; linear_step.cpp), and the
//                       contact point's impulse response for runs that look at nothing else;
//   Newton–Newmark      any model of fem/mechanical_model.hpp whose force is not linear in u
//                       (newton_newmark_step.cpp);
//   central differences any model with a diagonal mass (central_difference_step.cpp);
//   rigid target        no plate (closed-form checks of the contact law).
//
// A policy is built once per case (it owns what does not depend on the impactor: matrices and their
// factorization) and starts a PlateStepper for each run (what does: the contact point and load).
#include "plyimpact/analysis/contact/condensed_contact.hpp"
#include "plyimpact/analysis/contact/contact_load.hpp"
#include "plyimpact/analysis/contact/hertz_contact.hpp"
#include "plyimpact/analysis/impact/capabilities.hpp"
#include "plyimpact/analysis/impact/impact_result.hpp"
#include "plyimpact/analysis/impact/mass_scaling.hpp"
#include "plyimpact/analysis/integrators/newmark.hpp"
#include "plyimpact/analysis/integrators/newton_settings.hpp"
#include "plyimpact/fem/damaged_plate.hpp"
#include "plyimpact/fem/discrete_plate.hpp"
#include "plyimpact/fem/equation_subset.hpp"
#include "plyimpact/fem/mass_operator.hpp"
#include "plyimpact/fem/nonlinear_plate_element.hpp"
#include "plyimpact/fem/spd_solver.hpp"
#include "plyimpact/fem/stacked_model.hpp"

#include <atomic>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace plyimpact {

class MechanicalModel;

/// Displacement, velocity and acceleration of the plate at the start of a step (policy numbering).
struct PlateState {
  Eigen::VectorXd u, v, a;
};

/// What the time loop and its observers read of a stepper that does not change during its run: set once by
/// its constructor.
struct StepperFacts {
  /// The state the stepper moves is the contact point's alone, (ws, ẇs, ẅs) (contact_point_response.hpp):
  /// no field, the plate's energy all strain.
  bool contact_point_only = false;
  /// What observers read of the model after the last accepted step (the plies' damage, the interfaces, the
  /// energy their laws dissipated); null for a plate that has no model state.
  const ModelResults* results = nullptr;
  /// The counts of Newton's iterations, kept by the stepper as it steps; null where it solves none by them.
  const NewtonStatistics* statistics = nullptr;
  /// The mass that mass scaling added (mass_scaling.hpp), for ½ vᵀΔMv; null where the run scales none.
  const ScaledMass* scaled_mass = nullptr;
};

/// One run's plate: advances steps and reports energies.
class PlateStepper {
public:
  virtual ~PlateStepper() = default;
  PlateStepper() = default;
  PlateStepper(const PlateStepper&) = delete;
  PlateStepper& operator=(const PlateStepper&) = delete;

  /// Solves step `step` (ending at t) for the plate and the contact force together: u_{n+1} into u_next.
  virtual ContactSolution advance(long step, double t, const PlateState& s, const CondensedContact& contact,
                                  Eigen::VectorXd& u_next) = 0;
  /// a_{n+1} of the step advance() has just solved: Newmark's (2.11) from u_{n+1}, unless the plate
  /// has it from its equation of motion (the explicit steps of central_difference_step.cpp).
  virtual void next_acceleration(const NewmarkCoefficients& nc, const PlateState& s,
                                 const Eigen::VectorXd& u_next, Eigen::VectorXd& a_next) const {
    a_next = nc.c0 * (u_next - s.u) - nc.c2 * s.v - nc.c3 * s.a;
  }
  /// The step is accepted: u_next will become u (energy bookkeeping of path-dependent plates).
  virtual void accept(const PlateState& /*before*/, const Eigen::VectorXd& /*u_next*/) {}
  /// ½ vᵀMv.
  [[nodiscard]] virtual double kinetic_energy(const PlateState& s) const = 0;
  /// The plate's elastic energy in state s with contact force F.
  [[nodiscard]] virtual double strain_energy(const PlateState& s, double force) const = 0;
  /// ws = swᵀu.
  [[nodiscard]] virtual double contact_deflection(const Eigen::VectorXd& u) const = 0;
  /// u in the model's numbering.
  virtual void to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const = 0;
  /// The next steps are Δt/2^level long, Δt of StepPolicyOptions::newmark (error-controlled runs, only
  /// where StepPolicy::variable_time_step()); level 0 is where every run starts.
  virtual void set_time_step_level(int /*level*/) {
    throw std::logic_error("this step policy has a fixed time step");
  }

  [[nodiscard]] bool contact_point_only() const { return facts_.contact_point_only; }
  [[nodiscard]] const ModelResults* results() const { return facts_.results; }
  [[nodiscard]] std::optional<NewtonStatistics> statistics() const {
    return facts_.statistics ? std::optional(*facts_.statistics) : std::nullopt;
  }
  /// ½ vᵀΔMv of the mass that mass scaling added (mass_scaling.hpp) [J]; empty where the run scales none.
  [[nodiscard]] std::optional<double> added_mass_kinetic_energy(const PlateState& s) const {
    return facts_.scaled_mass ? std::optional(facts_.scaled_mass->added_kinetic_energy(s.v)) : std::nullopt;
  }

protected:
  /// The stepper's facts, once its constructor has built what they point to.
  void set_facts(StepperFacts facts) { facts_ = facts; }

private:
  StepperFacts facts_;
};

/// What the time loop reads of a policy that does not change during a run.
struct PolicyEquations {
  /// Equations of the time loop (0 for a rigid target).
  int equations = 0;
  /// True when the in-plane DOFs are left out (exactly decoupled from bending: B = 0, I1 = 0).
  bool inplane_eliminated = false;
  /// True when its steppers take set_time_step_level() (error-controlled time steps).
  bool variable_time_step = false;
  /// What the policy changed about the case that the user must know (e.g. strengths lowered to a band
  /// limit), for the run's warnings.
  std::vector<std::string> warnings;
  /// Where the policy holds them (the linear plate): the time loop's stiffness and mass, and the factor of
  /// K̄ that every run solves its steps with.
  const SparseMatrix* stiffness = nullptr;
  const SparseMatrix* mass = nullptr;
  const SpdSolver* shared_factor = nullptr;
  /// The count of K̄'s factorizations of the error-controlled time steps, kept by the policy.
  const std::atomic<int>* factorizations = nullptr;
};

class StepPolicy {
public:
  virtual ~StepPolicy() = default;
  StepPolicy() = default;
  StepPolicy(const StepPolicy&) = delete;
  StepPolicy& operator=(const StepPolicy&) = delete;

  [[nodiscard]] int equations() const { return equations_.equations; }
  [[nodiscard]] bool inplane_eliminated() const { return equations_.inplane_eliminated; }
  [[nodiscard]] bool variable_time_step() const { return equations_.variable_time_step; }
  [[nodiscard]] const std::vector<std::string>& warnings() const { return equations_.warnings; }

  /// A stepper for a run with `impactor`. `contact_point_suffices`: the run looks at nothing but the
  /// contact point, and the policy may follow that point alone through the plate's impulse response there
  /// (contact_point_response.hpp; PlateStepper::contact_point_only()) where that is exact: the linear plate
  /// under a point load with the trapezoidal rule.
  [[nodiscard]] virtual std::unique_ptr<PlateStepper> start(const Impactor& impactor,
                                                            bool contact_point_suffices) const = 0;

  /// Factorizations of K̄ done so far for the error-controlled time steps (one per level used).
  [[nodiscard]] int factorizations() const {
    return equations_.factorizations ? equations_.factorizations->load() : 0;
  }
  /// The stiffness and mass over the time loop's equations, where the policy holds them (null: it holds
  /// none; the case assembles them, modal_analysis.hpp).
  [[nodiscard]] const SparseMatrix* stiffness() const { return equations_.stiffness; }
  [[nodiscard]] const SparseMatrix* mass() const { return equations_.mass; }
  /// The factor of K̄ that every run of the policy solves its steps with, where there is one.
  [[nodiscard]] const SpdSolver* shared_factor() const { return equations_.shared_factor; }

protected:
  /// The policy's equations, set once by its constructor.
  void set_equations(PolicyEquations equations) { equations_ = std::move(equations); }

private:
  PolicyEquations equations_;
};

/// What the policies need to know of the run besides the plate.
struct StepPolicyOptions {
  NewmarkCoefficients newmark{1e-6, 0.25, 0.5};
  ContactLoad load = ContactLoad::point;
  SparseSolverKind solver = SparseSolverKind::cholmod_simplicial;
  FillOrdering ordering = FillOrdering::amd;
  std::optional<double> memory_limit_bytes; ///< refuse a factor of K̄ estimated above this
  /// ω_max of the model that central differences move, where the case has computed it (for dt = "auto").
  std::optional<double> explicit_omega_max;
  /// The lumped mass central differences move it with, where the case has built it (scaled or not,
  /// explicit_mass); empty: the model's own.
  std::shared_ptr<const ScaledMass> explicit_mass;
};

/// K̄ = K + c0 M factored once; in-plane DOFs left out when exactly decoupled.
[[nodiscard]] std::unique_ptr<StepPolicy> linear_step_policy(const DiscretePlate& model,
                                                             const StepPolicyOptions& options);
/// Newton–Newmark on any model with an iteration matrix (newton_newmark_step.cpp): the one implicit
/// integrator of the models whose force is not linear in u. `hold_laws`: the lagged step, whose trials
/// hold the laws at the step before (LawTrials), else the laws are iterated with the step.
[[nodiscard]] std::unique_ptr<StepPolicy>
newton_newmark_step_policy(std::unique_ptr<const MechanicalModel> model, const StepPolicyOptions& options,
                           NewtonSettings settings, bool hold_laws = false);
/// CD5: the largest Δt accepted for a plate whose highest angular frequency is ω_max: 0.9 · 2/ω_max [s].
[[nodiscard]] double stable_time_step(double omega_max);
/// What sets the stable step of a model moved by central differences: ω_max and where its mode lies.
struct StableStepSource {
  double omega_max = 0.0;                       ///< [rad/s]
  EquationPlace place;                          ///< where the mode's mass-weighted amplitude is largest
  Eigen::Vector2d xy = Eigen::Vector2d::Zero(); ///< that node [m]
};
/// The lumped mass that central differences move `model` with: its own, scaled as `scaling` asks
/// (mass_scaling.hpp). Throws std::invalid_argument, naming `key`, where the model's mass is not diagonal
/// with mass on every DOF.
[[nodiscard]] ScaledMass explicit_mass(const MechanicalModel& model, const std::string& key,
                                       const MassScaling& scaling);
/// ω_max of K0 φ = ω² M φ, K0 `model`'s virgin undeformed stiffness and M the run's `mass` (diagonal, or
/// block-diagonal with selective scaling; the bound CD5 takes) [rad/s], and where its mode lies
/// (modal_analysis.hpp, highest_mode).
[[nodiscard]] StableStepSource explicit_highest_mode(const MechanicalModel& model, const ScaledMass& mass);
/// "theta_x of sub-laminate 2 at (62.5, 37.5) mm" (1-based, the top one first; only for a stack).
[[nodiscard]] std::string stable_step_place_text(const StableStepSource& source, bool stacked);
/// Central differences (CD1 to CD6) on any plate model with a diagonal mass: the one explicit integrator
/// (central_difference_step.cpp). `key` is the deck key that chose it, for its messages. Throws
/// std::invalid_argument where the mass is not diagonal or Δt of `options` is above the stable step.
[[nodiscard]] std::unique_ptr<StepPolicy>
central_difference_step_policy(std::unique_ptr<const MechanicalModel> model, const StepPolicyOptions& options,
                               std::string key);
/// The largest time step for which the step of the stacked plate stays solvable where an interface point
/// softens (docs/delamination.md, "Impact on the stacked plate"). The step's matrix for the opening of
/// two neighbouring sub-laminates at a point is c0 m + K_T with c0 = 1/(β Δt²), m their reduced mass per
/// area and K_T ≥ −k_s, k_s the softening slope of the law (fastest_softening, fem/stacked_model.hpp). It
/// stays positive, and the step's solution unique, for
///
///   Δt < √(m / (β k_s))   (2 √(m/k_s) for the trapezoidal rule),                              (DL5)
///
/// the smallest over the interfaces. Above it a point that starts softening snaps through within one
/// step and the iterations cannot converge (measured: the §3.6 plate at 1 µs, bound 0.75 µs).
[[nodiscard]] double largest_delamination_time_step(const Laminate& laminate, const StackSettings& stack,
                                                    double newmark_beta);

/// ρ of the cracked faces' closing penalty under central differences (DL10, docs/delamination.md, "Cracked
/// faces that close"): a quarter of K puts the contact mode of two faces that clap at half the frequency
/// of the intact interface's, so that at the full stable step it runs at the ω Δt the half step gave it.
/// With the plies cracking under the interfaces, faces clap and the full penalty's ω Δt ≈ 0.9 made central
/// differences create energy (balance error 0.78 % over 1.2 ms on the shipped example at the full step):
/// before it, dt = "auto" took half the stable step. Intact points keep K, so the answer is the same
/// bits until an interface point damages.
inline constexpr double cracked_faces_closing_fraction = 0.25;
/// What a plate is made of and how it steps: the laws of a cell of the table of what runs
/// (capabilities.hpp) with their settings, and its one integrator.
struct PlatePhysics {
  std::optional<NonlinearImpactSettings> large_deflection; ///< von Kármán kinematics (SPEC §8)
  std::optional<ProgressiveDamageSettings> ply_damage;     ///< plies that crack
  std::optional<DelaminationSettings> interfaces;          ///< sub-laminates tied by cohesive interfaces
  Integrator integrator = Integrator::implicit;
  /// Newton–Newmark's iterations (an expert's choice); empty: the defaults of the model's row of the table
  /// of what runs (newton_newmark_defaults).
  std::optional<NewtonSettings> newton;
};
/// The interfaces as `integrator` runs them: central differences close cracked faces on ρ K
/// (cracked_faces_closing_fraction), the implicit steps on K.
[[nodiscard]] DelaminationSettings interfaces_for(DelaminationSettings interfaces, Integrator integrator);
/// The model of `plate` that `physics` makes (fem/mechanical_model.hpp): elastic, von Kármán, with plies
/// that crack (either kinematics), or the laminate cut into sub-laminates tied by cohesive interfaces (one
/// laminate, no regions), which may be any of those. Throws std::invalid_argument with the table's reason
/// where the cell does not run, and for a large-deflection measure other than von Kármán's with ply damage.
[[nodiscard]] std::unique_ptr<MechanicalModel> mechanical_model(const DiscretePlate& plate,
                                                                const PlatePhysics& physics);
/// The deck key that chose central differences for `physics`, for the messages of the explicit step.
[[nodiscard]] std::string explicit_key(const PlatePhysics& physics);
/// The one factory of step policies (step_policy.cpp): the linear elastic plate under implicit Newmark
/// takes linear_step_policy; every other cell its mechanical_model (`model`, where the caller has built
/// it) under Newton–Newmark (implicit, lagged) or central differences, with the iterations and messages
/// of its laws. Throws std::invalid_argument where the cell does not run, where Δt is above the explicit
/// stable step, or for a stack without ply damage above (DL5).
[[nodiscard]] std::unique_ptr<StepPolicy> step_policy(const DiscretePlate& plate,
                                                      const StepPolicyOptions& options,
                                                      const PlatePhysics& physics,
                                                      std::unique_ptr<const MechanicalModel> model = nullptr);
/// A rigid, immovable target: ws = 0.
[[nodiscard]] std::unique_ptr<StepPolicy> rigid_target_policy();

} // namespace plyimpact
