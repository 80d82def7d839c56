#pragma once
// The one interface through which a time integrator drives a plate model (issue 49; docs/architecture.md,
// "Models and integrators"). After OOFEM's split of an engineering model from its elements: the model is
// built once per case and shared by the runs (matrices, the laws' constants); each run holds a
// ModelState, the committed state of the model's integration points, from which a trial is evaluated at
// any displacement and then either committed or dropped.
//
//   MechanicalModel   what does not change during a run: the equations it moves (model numbering ↔ the
//                     integrator's), the mass over them, the stiffness of the virgin undeformed model (the
//                     bound of its highest frequency), the warnings its construction raised.
//   ModelState        one run's state: the trial internal force f_int(u) from the committed state, the
//                     commit, the stored energy, and the results observers read (ModelResults: the
//                     plies' damage, the interfaces, the dissipated energy).
//
// Behind it: the elastic plate (f_int = K u), the von Kármán plate (NonlinearPlate) and the plate
// whose plies crack (DamagedPlate with its DamageField).
#include "plyimpact/fem/damaged_plate.hpp"
#include "plyimpact/fem/discrete_plate.hpp"
#include "plyimpact/fem/equation_subset.hpp"
#include "plyimpact/fem/nonlinear_plate_element.hpp"
#include "plyimpact/fem/stacked_plate.hpp"

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace plyimpact {

class InterfaceStates;

/// What observers read of a model's committed state: pointers into a run's ModelState, set once by its
/// constructor; null where the model has no such part.
struct ModelResults {
  /// The plies' damage, for a model whose plies crack.
  const PlyDamageView* ply_damage = nullptr;
  /// The interfaces of a stack: their areas, dissipation and whole result (fem/stacked_model.hpp).
  const InterfaceStates* interfaces = nullptr;
  /// Energy the model's laws have dissipated up to the committed state: the interfaces' and the plies'
  /// [J].
  [[nodiscard]] double dissipated_energy() const;
};

/// A low-rank change of a symmetric matrix in a factor: + C₊C₊ᵀ − C₋C₋ᵀ (columns of the matrix's rows).
struct LowRankChange {
  SparseMatrix up, down;
  [[nodiscard]] Eigen::Index rank() const { return up.cols() + down.cols(); }
};

/// What a run's trials do with the laws' state: the integrator's choice
/// (analysis/integrators/step_policy.cpp), which the model follows. A model without laws (the elastic and the
/// von Kármán plate) ignores it.
enum class LawTrials {
  /// Each trial advances every law from the committed state to u; the commit keeps the last trial's.
  advance,
  /// Each trial holds the laws at the committed state (their secant or tangent there; open or closed
  /// cracks follow the trial's strain); the laws advance once, at the commit, to its u.
  hold,
  /// As hold, the held laws giving the end tractions of the step's mean (DL6): the trials are the end
  /// forces of the trapezoidal rule's two-point form, with start_force().
  hold_step_mean,
};

/// How the iteration matrix came into the integrator's factor (ModelState::matrix_in_factor).
enum class FactorChange { factorized, updated };

/// What the iteration matrix of a run's trials is, once the integrator has said what the trials do with
/// the laws (ModelState::set_law_trials).
struct IterationMatrixFacts {
  /// False where iteration_matrix() may be unsymmetric (the tangent of interfaces that soften under mixed
  /// mode with their damage iterated): the integrator then factors it by sparse LU instead of Cholesky.
  bool symmetric = true;
  /// True where a refresh of the iteration matrix waits for the trial at the next iterate instead of
  /// being made at once: the matrix of held damage is that of the last trial, and where a trial costs
  /// little against a factorization (the stacked plate) the next iterate may converge without one.
  bool refresh_at_next_trial = false;
};

/// One run's state of a model's integration points.
class ModelState {
public:
  virtual ~ModelState() = default;
  ModelState() = default;
  ModelState(const ModelState&) = delete;
  ModelState& operator=(const ModelState&) = delete;

  /// What the trials do with the laws' state; `advance` until told otherwise (before the first trial).
  /// Returns what their iteration matrix then is.
  virtual IterationMatrixFacts set_law_trials(LawTrials /*trials*/) { return {}; }
  /// What observers read of the committed state.
  [[nodiscard]] const ModelResults& results() const { return results_; }
  /// f_int(u) of a trial state from the committed one at u, over a step of dt (the viscous
  /// regularisation's time), into `f` (sized by the caller; no allocation). Does not commit.
  virtual void internal_force(const Eigen::VectorXd& u, double dt, Eigen::VectorXd& f) = 0;
  /// The trial state of the last internal_force() at u, whose force was f, becomes the committed one
  /// (with held laws: the laws advanced to u first).
  virtual void commit(const Eigen::VectorXd& u, const Eigen::VectorXd& f) = 0;
  /// Energy stored in the plate in the committed state, whose displacement is u [J].
  [[nodiscard]] virtual double stored_energy(const Eigen::VectorXd& u) const = 0;

  // What an implicit integrator asks of the state (analysis/integrators/newton_newmark_step.cpp).
  /// The stiffness of an iteration at u, in the pattern of initial_stiffness(): the tangent K_T(u)
  /// of the von Kármán plate, the secant of the damage of the last trial, K of the elastic plate, the
  /// stack's K_plates plus its interfaces' tangent.
  [[nodiscard]] virtual SparseMatrix iteration_matrix(const Eigen::VectorXd& u) const = 0;
  /// After a trial at u whose laws advanced: false where it left out a part that must join (an element
  /// whose plies have reached a failure surface at u), which joins now; the next trial includes it. True
  /// after a trial with held laws (their commit admits what has reached a surface).
  virtual bool admit(const Eigen::VectorXd& /*u*/) { return true; }
  /// How far the committed state has drifted from that of the last factored matrix: the largest growth of
  /// a law's state variable since the matrix was last factored (a ply's damage); the integrator refactors
  /// before a step beyond its tolerance.
  [[nodiscard]] virtual double drift_since_factorization() const { return 0.0; }
  /// The iteration matrix at u as a low-rank change of the one in the factor (the last factored, with the
  /// changes since), K̄(u) = K̄_f + C₊C₊ᵀ − C₋C₋ᵀ, for an update of the factor instead of a new one (DL8,
  /// SpdSolver::modify); empty where it is not one, and the matrix is factored anew.
  [[nodiscard]] virtual std::optional<LowRankChange> matrix_change(const Eigen::VectorXd& /*u*/) {
    return std::nullopt;
  }
  /// The iteration matrix at u is in the factor now: factored anew, or the last matrix_change() applied.
  virtual void matrix_in_factor(const Eigen::VectorXd& /*u*/, FactorChange /*how*/) {}
  /// True once after a trial that changed which branch of a law holds at some point (a crack opened or
  /// closed under held damage): its matrix is then factored before the next correction.
  virtual bool take_branch_changed() { return false; }
  /// With ModelEquations::two_point_form: the force at the step's start u_n with the laws held at the
  /// committed state, into `f` (sized by the caller).
  virtual void start_force(const Eigen::VectorXd& /*u_n*/, Eigen::VectorXd& /*f*/) {}

protected:
  /// The state's results, once its constructor has built what they point to.
  void set_results(ModelResults results) { results_ = results; }

private:
  ModelResults results_;
};

/// The stored energy of a plate whose forces are not linear in u: the internal forces' work, trapezoidal
/// from commit to commit.
class WorkOfInternalForces {
public:
  explicit WorkOfInternalForces(int size)
      : u_(Eigen::VectorXd::Zero(size)), f_(Eigen::VectorXd::Zero(size)) {}
  void add(const Eigen::VectorXd& u, const Eigen::VectorXd& f) {
    work_ += 0.5 * (f + f_).dot(u - u_);
    u_ = u;
    f_ = f;
  }
  [[nodiscard]] double work() const { return work_; }

private:
  Eigen::VectorXd u_, f_; ///< the committed displacement and its internal force
  double work_ = 0.0;
};

/// Where an equation of a model lies: its sub-laminate (0, the top one, for a single plate), and the node
/// and DOF (0..4 = u, v, w, θx, θy) on the mesh the sub-laminates share.
struct EquationPlace {
  int sublaminate = 0;
  int node = -1;
  int dof = -1;
};

/// What an integrator and its observers read of a model, which does not change during a run: the
/// equations it moves and where they lie, the matrices it starts from, what building it changed about the
/// case. Pointers into the model that holds it.
struct ModelEquations {
  /// Equations the integrator moves.
  int size = 0;
  /// The plate the impactor touches, whose mesh and numbering the contact samples (the top sub-laminate
  /// of a stack).
  const DiscretePlate* contact_plate = nullptr;
  /// The equations of contact_plate that the integrator moves, the leading block of `size` (the in-plane
  /// DOFs are left out where they are exactly decoupled from bending).
  const EquationSubset* contact_equations = nullptr;
  /// Where the sub-laminates' blocks of equations start, in order (one, at 0, for a single plate), each
  /// in its sub-laminate's own numbering (the first through contact_equations).
  std::vector<std::pair<int, const DiscretePlate*>> blocks;
  /// The mass matrix over the integrator's equations.
  const SparseMatrix* mass = nullptr;
  /// The stiffness of the virgin, undeformed model: the highest frequency of the model is bounded with it
  /// (damage only lowers the stiffness; membrane tension adds little at w ~ h).
  const SparseMatrix* initial_stiffness = nullptr;
  /// The part of initial_stiffness that ties the faces of neighbouring sub-laminates (a stack's intact
  /// interfaces); null for a plate without: what selective mass scaling scales
  /// (analysis/impact/mass_scaling.hpp).
  const SparseMatrix* interface_stiffness = nullptr;
  /// What building the model changed about the case that the user must know (strengths lowered to a band
  /// limit).
  std::vector<std::string> warnings;
  /// True where held trials may be the end forces of the step's mean (LawTrials::hold_step_mean), to be
  /// solved in the trapezoidal rule's two-point form with ModelState::start_force() (DL7,
  /// docs/delamination.md): the stack, whose delaminated faces clapping under the law's end tractions
  /// create energy otherwise.
  bool two_point_form = false;
};

/// A plate model as an integrator sees it (built once per case, shared by the runs): its equations
/// (ModelEquations, set once by the model's constructor), the displacement in the case's numbering, and a
/// run's state.
class MechanicalModel {
public:
  virtual ~MechanicalModel() = default;
  MechanicalModel() = default;
  MechanicalModel(const MechanicalModel&) = delete;
  MechanicalModel& operator=(const MechanicalModel&) = delete;

  [[nodiscard]] int size() const { return equations_.size; }
  [[nodiscard]] const DiscretePlate& contact_plate() const { return *equations_.contact_plate; }
  [[nodiscard]] const EquationSubset& contact_equations() const { return *equations_.contact_equations; }
  /// True where the in-plane DOFs are left out.
  [[nodiscard]] bool inplane_eliminated() const { return !contact_equations().all(); }
  /// Where equation `i` (the integrator's numbering) lies (a search: for messages, not loops).
  [[nodiscard]] EquationPlace place_of(int i) const;
  /// place_of(i) of every equation i, in one pass (for tables over all equations).
  [[nodiscard]] std::vector<EquationPlace> places() const;
  [[nodiscard]] const SparseMatrix& mass() const { return *equations_.mass; }
  [[nodiscard]] const SparseMatrix& initial_stiffness() const { return *equations_.initial_stiffness; }
  [[nodiscard]] const SparseMatrix* interface_stiffness() const { return equations_.interface_stiffness; }
  [[nodiscard]] const std::vector<std::string>& warnings() const { return equations_.warnings; }
  [[nodiscard]] bool two_point_form() const { return equations_.two_point_form; }

  /// The displacement u (the integrator's numbering) in the numbering of the case's plate, for observers
  /// (the top sub-laminate of a stack).
  virtual void to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const = 0;
  /// A run's state: virgin and undeformed.
  [[nodiscard]] virtual std::unique_ptr<ModelState> virgin_state() const = 0;

protected:
  /// The model's equations, once its constructor has built what they point to.
  void set_equations(ModelEquations equations) { equations_ = std::move(equations); }

private:
  ModelEquations equations_;
};

/// The linear elastic plate: f_int = K u, over its bending equations when the in-plane DOFs are exactly
/// decoupled (bending_equations_if_decoupled), else over all.
[[nodiscard]] std::unique_ptr<MechanicalModel> elastic_plate_model(const DiscretePlate& plate);
/// The geometrically non-linear plate of SPEC §8 (NonlinearPlate), over all equations. Its stored
/// energy is the work of the internal forces, ∫ f_intᵀ du, trapezoidal from commit to commit.
[[nodiscard]] std::unique_ptr<MechanicalModel> von_karman_plate_model(const DiscretePlate& plate,
                                                                      StrainMeasure measure);
/// The plate whose plies crack (DamagedPlate, docs/progressive_damage.md), over all equations, with
/// `kinematics` (linear, or von Kármán: a composition). Trials that advance the law evaluate it at u and
/// admit u once no element the screen had left out has reached a Hashin surface there; held trials keep
/// the committed damage, and the commit evaluates the law once, at u.
[[nodiscard]] std::unique_ptr<MechanicalModel>
damaging_plate_model(const DiscretePlate& plate, const ProgressiveDamageSettings& settings,
                     Kinematics kinematics = Kinematics::linear);

} // namespace plyimpact
