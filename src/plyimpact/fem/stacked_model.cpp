// The stacked plate whose interfaces delaminate (stacked_plate.hpp) as a model of mechanical_model.hpp,
// with what builds it from an impact's plate (stacked_model.hpp), as the stacked-shell impact models of the
// literature run in LS-DYNA and Abaqus/Explicit. How the trials treat the laws is the integrator's choice
// (LawTrials; analysis/integrators/step_policy.cpp). Trials that advance them evaluate the interface law
// once, at u, from the committed states (CohesiveDamage::evolve: the damage grows with the step's own
// separation and its dissipation is the law's), and
//
//   f_int(u) = K_plates u + Σ f_coh(u; d(u))                                                     (CD3)
//
// With central differences nothing is solved: faces that clap after the impactor leaves, which cost an
// implicit step ~10 solves, cost one evaluation here. The stable step (CD5) comes from the elastic stack,
// K_plates plus the interfaces' penalty K (which also holds closed faces apart); softening only lowers the
// frequencies. The shear penalty usually sets it: it moves each face by its translation and its rotation
// times half its thickness, and with the Mindlin rotary inertia ρh³/12 the faces of masses per area m_u,
// m_l vibrate at ω² ≥ 4 K (1/m_u + 1/m_l) (DL9, docs/delamination.md "The explicit step").
//
// With ply damage (docs/delamination.md, "Ply damage and delamination together") each sub-laminate is a
// damaged plate (fem/damaged_plate.hpp) on its own plies: K_plates u becomes Σ_k f_k(u_k; d_k), each
// sub-laminate's law evaluated at u as the damaging plate's trial does, and the model shows the plies'
// damage of the whole laminate (fem/stacked_damage.hpp). Damage only softens, so the elastic stack's
// stable step still holds.
//
// Trials that hold the laws (LawTrials::hold_step_mean, the lagged step of docs/delamination.md) keep every
// law at the committed state (the plies' damage d_n with their cracks' modes at u, the interfaces' end
// tractions 2 τ̄ − τ(δ_n) at their held damage, DL6); the start force f(u_n) completes the trapezoidal
// two-point form (DL7), the iteration matrix is K_plates + the interfaces' held tangent + the damaged
// sections' secant difference, and the laws move once per step, at the commit.
//
// With large deflections (nonlinear = true) each sub-laminate is a von Kármán plate on its own mid-plane
// (NonlinearPlate; with ply damage DamagedPlate with Kinematics::von_karman): K_plates u becomes
// Σ_k f_k(u_k), the iteration matrix gains each sub-laminate's K_T(u_k) − K_k, and the plates' stored
// energy is the work of their internal forces, trapezoidal from commit to commit. Tied faces move as one
// laminate's: with u_k = u₀ − z_k w' the membrane strain u_k' + ½ w'² − (z − z_k) w'' of sub-laminate k is
// the whole laminate's u₀' + ½ w'² − z w'' at every height z, so a stack whose interfaces hold is the
// von Kármán laminate (tests/analysis/impact/test_stacked_von_karman.cpp).
#include "plyimpact/fem/stacked_model.hpp"

#include "plyimpact/fem/element_loop.hpp"

#include "plyimpact/fem/nonlinear_plate.hpp"
#include "plyimpact/fem/stacked_damage.hpp"

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

namespace plyimpact {

namespace {

const Laminate& single_laminate(const DiscretePlate& model) {
  if (!model.single_section())
    throw std::invalid_argument("delamination: the stacked plate needs one laminate over the whole plate; "
                                "[[regions]] with other laminates are not available with [delamination] "
                                "yet (docs/delamination.md, limits)");
  return model.laminate();
}

std::optional<std::string> process_zone_warning(const ProcessZone& z, CohesiveQuadrature rule) {
  if (z.length >= 3.0 * z.point_spacing) return std::nullopt;
  return fmt::format(
      "delamination: the cohesive zone of the interfaces, E2 G_c / strength^2 = {:.3g} mm in the shorter "
      "mode, spans {:.2g} interface points ({:.3g} mm apart): fewer than 3, so the onset and growth of "
      "delaminations depend on the mesh. Refine to elements of {:.3g} mm or less, or lower both "
      "strengths (Turon et al. 2007: tau = sqrt(9 pi E2 G_c / (32 * 3 * {:.3g} mm))) "
      "(docs/delamination.md)",
      z.length * 1e3, z.length / z.point_spacing, z.point_spacing * 1e3,
      2.0 * z.length / 3.0 * 1e3 * (rule == CohesiveQuadrature::nodal ? 1.0 : 1.5), z.point_spacing * 1e3);
}

/// Turon et al. (2010): with S/N ≠ √(G_IIc/G_Ic) the mixed-mode law does not dissipate G_c(B) along a
/// crack front whose mixity changes (measured: MMB 1.23 G_c with N halved alone).
std::optional<std::string> strength_ratio_warning(const CohesiveParameters& c) {
  const double turon_S = turon_shear_strength(c.normal_strength, c.G_Ic, c.G_IIc);
  const double ratio = c.shear_strength / turon_S;
  if (std::abs(ratio - 1.0) <= 0.1) return std::nullopt;
  return fmt::format("delamination: shear_strength / normal_strength = {:.3g} while sqrt(G_IIc / G_Ic) = "
                     "{:.3g}: under mixed mode the interfaces then dissipate more or less than G_c (Turon "
                     "et al. 2010; docs/delamination.md, MMB); set S = N sqrt(G_IIc / G_Ic) = {:.3g} MPa",
                     c.shear_strength / c.normal_strength, std::sqrt(c.G_IIc / c.G_Ic), turon_S * 1e-6);
}

/// The model equation of each equation of the stack's top sub-laminate (−1: none).
std::vector<int> top_equations_in_model(const DiscretePlate& model, const StackedPlate& stack) {
  const DiscretePlate& top = stack.sublaminate(0);
  std::vector<int> of_top(static_cast<std::size_t>(top.size()), -1);
  for (int n = 0; n < model.mesh().node_count(); ++n)
    for (int dof = 0; dof < 5; ++dof)
      if (const int eq = top.dofs().equation(n, dof); eq >= 0)
        of_top[static_cast<std::size_t>(eq)] = model.dofs().equation(n, dof);
  return of_top;
}

} // namespace

StackedPlate impact_stack(const DiscretePlate& model, const DelaminationSettings& settings) {
  const int bottom = static_cast<int>(settings.stack.cuts.size());
  return {model.mesh(), single_laminate(model), settings.stack,
          Discretization{model.mass_kind(), model.formulation()}, [&](int k) {
            return settings.supports_on_all || k == bottom ? model.boundary() : BoundaryConditions{};
          }};
}

StackedImpactPlate::StackedImpactPlate(const DiscretePlate& model, const DelaminationSettings& settings)
    : model_(model), settings_(settings), stack_(impact_stack(model, settings)),
      top_equations_(stack_.sublaminate(0).size()), M_(stack_.mass()),
      model_of_top_(top_equations_in_model(model, stack_)) {}

std::vector<std::string> StackedImpactPlate::stack_warnings() const {
  std::vector<std::string> w;
  if (auto zone = process_zone_warning(process_zone(), settings_.stack.rule)) w.push_back(std::move(*zone));
  if (auto ratio = strength_ratio_warning(settings_.stack.interface)) w.push_back(std::move(*ratio));
  return w;
}

ProcessZone StackedImpactPlate::process_zone() const {
  const CohesiveParameters& c = settings_.stack.interface;
  double E2 = INFINITY;
  for (const Material& m : model_.laminate().materials())
    E2 = std::min(E2, m.E2);
  const Mesh& mesh = model_.mesh();
  const Eigen::Vector2d zone(settings_.zone_x, settings_.zone_y);
  const auto largest_side = [&](bool in_zone_only) {
    double largest = 0.0;
    for (int e = 0; e < mesh.element_count(); ++e) {
      if (in_zone_only && (mesh.map(e, 0.0, 0.0) - zone).norm() > settings_.zone_radius) continue;
      const ElementCoordinates X = mesh.element_coordinates(e);
      largest = std::max(
          {largest, X.col(0).maxCoeff() - X.col(0).minCoeff(), X.col(1).maxCoeff() - X.col(1).minCoeff()});
    }
    return largest;
  };
  double largest = settings_.zone_radius > 0.0 ? largest_side(true) : 0.0;
  if (largest == 0.0) largest = largest_side(false);
  return {std::min(cohesive_zone_length(E2, c.G_Ic, c.normal_strength),
                   cohesive_zone_length(E2, c.G_IIc, c.shear_strength)),
          settings_.stack.rule == CohesiveQuadrature::nodal ? 0.5 * largest : largest / 3.0};
}

void StackedImpactPlate::top_to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const {
  out = Eigen::VectorXd::Zero(model_.size());
  for (std::size_t i = 0; i < model_of_top_.size(); ++i)
    if (const int eq = model_of_top_[i]; eq >= 0) out(eq) = u(static_cast<Eigen::Index>(i));
}

InterfaceStates::InterfaceStates(const StackedImpactPlate& plate)
    : plate_(plate), committed_(plate.stack_.initial_state()) {}

void InterfaceStates::accept() {
  std::swap(committed_, trial_); // trial_ keeps the old states' storage for the next set_trial()
  dissipated_ += trial_dissipated_;
  trial_dissipated_ = 0.0;
}

void InterfaceStates::areas(DelaminationAreas& out) const {
  const StackedPlate& stack = plate_.stack_;
  const std::vector<std::vector<CohesiveState>>& states = committed_.interfaces;
  out.dissipated = dissipated_;
  out.delaminated_area.clear(); // keeps its capacity: no allocation after the first step
  out.delaminated_area.reserve(states.size());
  for (int i = 0; i < stack.interface_count(); ++i)
    out.delaminated_area.push_back(stack.interface(i).damaged_area(states[static_cast<std::size_t>(i)], 1.0));
  out.projected_area = 0.0;
  if (stack.interface_count() == 0) return;
  // Every interface has the same points (same mesh and rule): the union is taken point by point.
  const CohesiveInterface& points = stack.interface(0);
  for (int q = 0; q < points.point_count(); ++q)
    if (std::any_of(states.begin(), states.end(), [q](const std::vector<CohesiveState>& of_interface) {
          return of_interface[static_cast<std::size_t>(q)].damage >= 1.0;
        }))
      out.projected_area += points.point_area(q);
}

DelaminationResult InterfaceStates::result() const {
  const StackedPlate& stack = plate_.stack_;
  DelaminationResult r;
  DelaminationAreas areas;
  this->areas(areas);
  r.delaminated_area = std::move(areas.delaminated_area);
  r.projected_area = areas.projected_area;
  r.dissipated = areas.dissipated;
  const ProcessZone zone = plate_.process_zone();
  r.cohesive_zone_length = zone.length;
  r.interface_point_spacing = zone.point_spacing;
  r.interface_after_ply = interfaces_after_ply(plate_.settings_.stack.cuts);
  for (int i = 0; i < stack.interface_count(); ++i) {
    const CohesiveInterface& ci = stack.interface(i);
    const std::vector<CohesiveState>& states = committed_.interfaces[static_cast<std::size_t>(i)];
    r.angle_below_deg.push_back(stack.sublaminate(i + 1).laminate().plies().front().angle_deg);
    double softening = 0.0;
    const auto per_element = static_cast<std::size_t>(ci.points_per_element());
    std::vector<double>& of_element = r.element_damage.emplace_back(states.size() / per_element, 0.0);
    std::vector<double>& of_point = r.point_damage.emplace_back();
    for (std::size_t q = 0; q < states.size(); ++q) {
      const double d = states[q].damage;
      if (d > 0.0 && d < 1.0) softening += ci.point_area(static_cast<int>(q));
      double& largest = of_element[q / per_element];
      largest = std::max(largest, d);
      of_point.push_back(d);
    }
    r.process_zone_area.push_back(softening);
  }
  if (stack.interface_count() > 0)
    for (int q = 0; q < stack.interface(0).point_count(); ++q) {
      r.point_cells.push_back(stack.interface(0).point_cell(q));
      r.point_area.push_back(stack.interface(0).point_area(q));
    }
  return r;
}

namespace {

/// K_plates + the interfaces' penalty: the stack's tangent with every interface point intact.
SparseMatrix elastic_stiffness(const StackedPlate& stack) {
  return stack.evaluate(Eigen::VectorXd::Zero(stack.size()), stack.virgin_state()).tangent;
}

/// Sub-laminate k's first ply in the laminate's numbering.
std::vector<int> first_plies(const StackedPlate& stack) {
  std::vector<int> first;
  int ply = 0;
  for (int k = 0; k < stack.sublaminate_count(); ++k) {
    first.push_back(ply);
    ply += static_cast<int>(stack.sublaminate(k).laminate().ply_count());
  }
  return first;
}

class StackedPlateModel;

/// One run's state: the interfaces' committed states, and with ply damage each sub-laminate's field.
class StackedState final : public ModelState {
public:
  explicit StackedState(const StackedPlateModel& model);
  /// The tangent of damage iterated with the step is unsymmetric under mixed mode; the held one is not.
  /// With ply damage the matrix is that of the last trial; the linear stack's trial is one product and the
  /// interfaces' law, against a factorization. (The von Kármán stack refreshes at once: measured so, and
  /// kept so that its example's numbers stay.)
  IterationMatrixFacts set_law_trials(LawTrials trials) override;
  void internal_force(const Eigen::VectorXd& u, double dt, Eigen::VectorXd& f) override;
  void commit(const Eigen::VectorXd& u, const Eigen::VectorXd& f) override;
  /// ½ uᵀ K_plates u from the product the committed trial made, + the interfaces' stored energy.
  [[nodiscard]] double stored_energy(const Eigen::VectorXd& u) const override;
  // What an implicit integrator asks: with the laws advanced by each trial (iterated with the step), or
  // held at the committed state (plies and interfaces).
  /// K_plates, the interfaces' tangent (at their held damage where held) and the damaged sections'
  /// secant difference of the last trial, each sub-laminate on its diagonal block.
  [[nodiscard]] SparseMatrix iteration_matrix(const Eigen::VectorXd& u) const override;
  /// The sub-laminates' largest.
  [[nodiscard]] double drift_since_factorization() const override;
  [[nodiscard]] std::optional<LowRankChange> matrix_change(const Eigen::VectorXd& u) override;
  /// Factored anew: the plies' drift and the interfaces' tangents in the factor start again; updated: the
  /// last change's tangents are in it.
  void matrix_in_factor(const Eigen::VectorXd& u, FactorChange how) override;
  bool take_branch_changed() override {
    bool changed = false;
    for (DamageField& field : fields_)
      changed = field.take_modes_changed() || changed; // every field's flag taken
    return changed && held();
  }
  /// With the plies' laws advanced: false where an element has reached a Hashin surface at u (it joins,
  /// and the next trial includes it), as for one damaged plate.
  bool admit(const Eigen::VectorXd& u) override;
  void start_force(const Eigen::VectorXd& u_n, Eigen::VectorXd& f) override;

private:
  /// Σ_k f_k(u_k) into Ku_: for each sub-laminate k, its part u_k of u into u_parts_[k], then
  /// `part_force(k)` writes f_k into f_parts_[k].
  template <class PartForce>
  void sublaminate_forces(const Eigen::VectorXd& u, const PartForce& part_force);
  /// Σ_k f_k(u_k; d_k) of the damaged sub-laminates at u into Ku_, each law advanced to u (trial states
  /// kept).
  void damaged_plate_forces(const Eigen::VectorXd& u, double dt);
  /// K_plates u, or the von Kármán sub-laminates' forces, or the damaged ones' (held: the damage of the
  /// last commit), into Ku_.
  void plate_forces(const Eigen::VectorXd& u, double dt);
  /// The damaged (or von Kármán) sub-laminates' iteration matrices less their elastic K_k, each on its
  /// diagonal block.
  [[nodiscard]] SparseMatrix sublaminate_corrections(const Eigen::VectorXd& u) const;
  /// The trials hold the laws at the committed state (LawTrials::hold, hold_step_mean).
  [[nodiscard]] bool held() const { return trials_ != LawTrials::advance; }
  /// The plies' laws advanced by each trial: each evaluates them at u.
  [[nodiscard]] bool plies_advanced() const { return !fields_.empty() && !held(); }
  /// How the interfaces' trials take their damage: evolving with the step, held with the end tractions
  /// of the step's mean (the two-point form, DL6), or held with the law's own.
  [[nodiscard]] CohesiveDamage interface_damage() const {
    switch (trials_) {
    case LawTrials::advance:
      return CohesiveDamage::evolve;
    case LawTrials::hold:
      return CohesiveDamage::held;
    case LawTrials::hold_step_mean:
      return CohesiveDamage::held_step_mean;
    }
    return CohesiveDamage::evolve;
  }
  /// The held linear stack refreshes its factor by updates where few interface points changed (DL8);
  /// the sub-laminates of a stack with ply damage or large deflections change everywhere.
  [[nodiscard]] bool updates_factor() const;

  const StackedPlateModel& m_;
  InterfaceStates interfaces_;
  Eigen::VectorXd Ku_; ///< K_plates u (with ply damage or large deflections: Σ_k f_k) of the last trial
  double plate_energy_ = 0.0;       ///< ½ uᵀ K_plates u of the committed state (linear kinematics)
  WorkOfInternalForces plate_work_; ///< ∫ Σ_k f_kᵀ du_k up to the committed state (large deflections;
                                    ///< sized 0 otherwise)
  StackedPlateState trial_buffer_;  ///< storage the interfaces' trial states are written into
  /// the interfaces' per-point buffers, reused by every evaluation (stored_energy's too: scratch, not state)
  mutable CohesiveWorkspace interface_work_;
  // With ply damage, per sub-laminate: its damage field, its part of u and its force.
  std::vector<DamageField> fields_;
  std::vector<Eigen::VectorXd> u_parts_, f_parts_;
  std::vector<std::vector<ElementVector>> element_forces_; ///< per part: the von Kármán element loop's places
  std::optional<StackedDamageField> plies_;                ///< the fields seen as the laminate's plies
  double dt_ = 0.0;                       ///< of the last trial (the laws' viscous time at a commit)
  LawTrials trials_ = LawTrials::advance; ///< what the trials do with the laws (the integrator's choice)
  // The held linear stack's factor updates (DL8): each interface point's tangent in the factor, the
  // changes of the last matrix_change(), the rank-one terms since the factorization.
  std::vector<std::vector<Eigen::Matrix3d>> factored_tangents_;
  struct TangentChange {
    std::size_t interface, point;
    Eigen::Matrix3d tangent;
  };
  std::vector<TangentChange> pending_;
  Eigen::Index update_rank_ = 0, pending_rank_ = 0;
};

class StackedPlateModel final : public MechanicalModel {
public:
  StackedPlateModel(const DiscretePlate& model, const DelaminationSettings& settings,
                    const std::optional<ProgressiveDamageSettings>& ply_damage,
                    std::optional<StrainMeasure> large_deflection)
      : plate_(model, settings), initial_(elastic_stiffness(plate_.stack_)),
        interfaces_(SparseMatrix(initial_ - plate_.stack_.plate_stiffness()).pruned()),
        K_plates_by_rows_(plate_.stack_.plate_stiffness()), large_deflection_(large_deflection) {
    const Kinematics kinematics = large_deflection ? Kinematics::von_karman : Kinematics::linear;
    for (int k = 0; k < plate_.stack_.sublaminate_count(); ++k) {
      const DiscretePlate& part = plate_.stack_.sublaminate(k);
      if (ply_damage)
        damaged_.push_back(std::make_unique<DamagedPlate>(part, *ply_damage, kinematics));
      else if (large_deflection)
        von_karman_.push_back(std::make_unique<NonlinearPlate>(part, *large_deflection));
    }
    set_equations(stack_equations());
  }

  /// The sub-laminates' force is not linear in u: their stored energy is the work of their forces.
  [[nodiscard]] bool large_deflection() const { return large_deflection_.has_value(); }

  /// Sub-laminate k holds the stacked equations offset(k) … offset(k + 1) − 1, in its own numbering; the
  /// impactor touches the top one, all of whose equations move.
  [[nodiscard]] ModelEquations stack_equations() const {
    const StackedPlate& stack = plate_.stack_;
    ModelEquations e;
    e.size = stack.size();
    e.contact_plate = &stack.sublaminate(0);
    e.contact_equations = &plate_.top_equations_;
    for (int k = 0; k < stack.sublaminate_count(); ++k)
      e.blocks.emplace_back(stack.offset(k), &stack.sublaminate(k));
    e.mass = &plate_.M_;
    e.initial_stiffness = &initial_;
    e.interface_stiffness = &interfaces_;
    e.warnings = stack_warnings();
    e.two_point_form = true;
    return e;
  }

  /// The stack's warnings and the damaged sub-laminates' lowered strengths: once when every sub-laminate
  /// says the same, otherwise each with its sub-laminate.
  [[nodiscard]] std::vector<std::string> stack_warnings() const {
    std::vector<std::string> w = plate_.stack_warnings();
    std::vector<std::optional<std::string>> lowered;
    for (const auto& part : damaged_)
      lowered.push_back(part->strength_reduction_warning());
    if (!lowered.empty() && lowered.front() &&
        std::all_of(lowered.begin(), lowered.end(), [&](const auto& l) { return l == lowered.front(); })) {
      w.push_back(*lowered.front());
      return w;
    }
    for (std::size_t k = 0; k < lowered.size(); ++k)
      if (lowered[k]) w.push_back(fmt::format("sub-laminate {}: {}", k, *lowered[k]));
    return w;
  }

  void to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const override {
    plate_.top_to_model(u, out);
  }
  [[nodiscard]] std::unique_ptr<ModelState> virgin_state() const override {
    return std::make_unique<StackedState>(*this);
  }

  StackedImpactPlate plate_;
  SparseMatrix initial_;    ///< K_plates + K_penalty, every interface point intact
  SparseMatrix interfaces_; ///< K_penalty alone
  /// K_plates stored by rows for the step's product: each entry of K u is one sequential sum over its row,
  /// in the order (and so with the bits) of the column-wise product, without scattering into K u
  Eigen::SparseMatrix<double, Eigen::RowMajor> K_plates_by_rows_;
  std::optional<StrainMeasure> large_deflection_;
  /// With ply damage: sub-laminate k as a damaged plate (empty without)
  std::vector<std::unique_ptr<DamagedPlate>> damaged_;
  /// Without ply damage but with large deflections: sub-laminate k as a von Kármán plate (empty without)
  std::vector<std::unique_ptr<NonlinearPlate>> von_karman_;
};

StackedState::StackedState(const StackedPlateModel& model)
    : m_(model), interfaces_(model.plate_), Ku_(Eigen::VectorXd::Zero(model.size())),
      plate_work_(model.large_deflection() ? model.size() : 0) {
  set_results({.ply_damage = nullptr, .interfaces = &interfaces_});
  const StackedPlate& stack = m_.plate_.stack_;
  for (const auto& part : m_.von_karman_) {
    u_parts_.emplace_back(Eigen::VectorXd::Zero(part->size()));
    f_parts_.emplace_back(Eigen::VectorXd::Zero(part->size()));
    element_forces_.emplace_back();
  }
  if (m_.damaged_.empty()) return;
  for (int k = 0; k < stack.sublaminate_count(); ++k) {
    const DamagedPlate& part = *m_.damaged_[static_cast<std::size_t>(k)];
    fields_.push_back(part.virgin_field());
    u_parts_.emplace_back(Eigen::VectorXd::Zero(part.size()));
    f_parts_.emplace_back(Eigen::VectorXd::Zero(part.size()));
  }
  plies_.emplace(first_plies(stack), static_cast<int>(m_.plate_.model_.laminate().ply_count()),
                 m_.plate_.model_.mesh().element_count());
  plies_->gather(fields_);
  set_results({.ply_damage = &*plies_, .interfaces = &interfaces_});
}

IterationMatrixFacts StackedState::set_law_trials(LawTrials trials) {
  trials_ = trials;
  return {.symmetric = held(), .refresh_at_next_trial = !fields_.empty() || !m_.large_deflection()};
}

template <class PartForce>
void StackedState::sublaminate_forces(const Eigen::VectorXd& u, const PartForce& part_force) {
  for (std::size_t k = 0; k < u_parts_.size(); ++k) {
    const Eigen::Index first = m_.plate_.stack_.offset(static_cast<int>(k));
    u_parts_[k] = u.segment(first, u_parts_[k].size());
    part_force(k);
    Ku_.segment(first, f_parts_[k].size()) = f_parts_[k];
  }
}

void StackedState::damaged_plate_forces(const Eigen::VectorXd& u, double dt) {
  sublaminate_forces(u, [&](std::size_t k) {
    m_.damaged_[k]->internal_force_into(u_parts_[k], dt, fields_[k], f_parts_[k]);
  });
}

bool StackedState::updates_factor() const {
  return held() && fields_.empty() && !m_.large_deflection();
}

void StackedState::plate_forces(const Eigen::VectorXd& u, double dt) {
  if (!m_.von_karman_.empty())
    sublaminate_forces(u, [&](std::size_t k) {
      m_.von_karman_[k]->internal_force(u_parts_[k], f_parts_[k], element_forces_[k]);
    });
  else if (fields_.empty())
    parallel_rows_product(m_.K_plates_by_rows_, u, Ku_);
  else if (held())
    sublaminate_forces(u, [&](std::size_t k) {
      m_.damaged_[k]->frozen_internal_force_into(u_parts_[k], fields_[k], f_parts_[k]);
    });
  else
    damaged_plate_forces(u, dt);
}

bool StackedState::admit(const Eigen::VectorXd& u) {
  if (!plies_advanced()) return true;
  bool joined = false;
  for (std::size_t k = 0; k < fields_.size(); ++k) {
    const DamagedPlate& part = *m_.damaged_[k];
    u_parts_[k] = u.segment(m_.plate_.stack_.offset(static_cast<int>(k)), part.size());
    joined = part.activate_reached(u_parts_[k], fields_[k]) || joined; // every sub-laminate's elements
  }
  return !joined;
}

void StackedState::internal_force(const Eigen::VectorXd& u, double dt, Eigen::VectorXd& f) {
  dt_ = dt;
  plate_forces(u, dt);
  f = Ku_;
  // Held in the two-point form: the end tractions 2 τ̄ − τ(δ_n) of the step's mean τ̄ at the held damage
  // (DL6)
  const double dissipated = m_.plate_.stack_.add_interface_forces(
      u, interfaces_.committed(), f, trial_buffer_, interface_damage(), interface_work_);
  interfaces_.set_trial(trial_buffer_, dissipated);
}

void StackedState::start_force(const Eigen::VectorXd& u_n, Eigen::VectorXd& f) {
  // K_s(d_n) u_n of the plies and the interfaces' tractions at u_n, every law held at the committed state;
  // the trial buffers are overwritten by the step's first trial.
  if (fields_.empty() && m_.von_karman_.empty()) {
    f.noalias() = m_.K_plates_by_rows_ * u_n;
  } else {
    plate_forces(u_n, dt_); // the damage held
    f = Ku_;
    for (DamageField& field : fields_)
      (void)field.take_modes_changed(); // the start's modes are not a trial's
  }
  (void)m_.plate_.stack_.add_interface_forces(u_n, interfaces_.committed(), f, trial_buffer_,
                                              CohesiveDamage::held_step_mean, interface_work_);
}

SparseMatrix StackedState::iteration_matrix(const Eigen::VectorXd& u) const {
  SparseMatrix K = m_.plate_.stack_.evaluate(u, interfaces_.committed(), interface_damage()).tangent;
  if (fields_.empty() && m_.von_karman_.empty()) return K;
  return K + sublaminate_corrections(u);
}

SparseMatrix StackedState::sublaminate_corrections(const Eigen::VectorXd& u) const {
  const StackedPlate& stack = m_.plate_.stack_;
  std::vector<Eigen::Triplet<double>> entries;
  const auto add_block = [&](int k, const SparseMatrix& dK) {
    const Eigen::Index first = stack.offset(k);
    for (int j = 0; j < dK.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(dK, j); it; ++it)
        if (it.value() != 0.0)
          entries.emplace_back(static_cast<int>(first + it.row()), static_cast<int>(first + it.col()),
                               it.value());
  };
  for (std::size_t k = 0; k < fields_.size(); ++k) {
    const DamagedPlate& part = *m_.damaged_[k];
    const Eigen::Index first = stack.offset(static_cast<int>(k));
    add_block(static_cast<int>(k),
              part.iteration_matrix(u.segment(first, part.size()), fields_[k]) - part.undamaged_stiffness());
  }
  for (std::size_t k = 0; k < m_.von_karman_.size(); ++k) { // K_T(u_k) − K_k
    const NonlinearPlate& part = *m_.von_karman_[k];
    const Eigen::Index first = stack.offset(static_cast<int>(k));
    add_block(static_cast<int>(k),
              part.tangent_stiffness(u.segment(first, part.size())) - part.linear().stiffness());
  }
  SparseMatrix dK(stack.size(), stack.size());
  dK.setFromTriplets(entries.begin(), entries.end());
  return dK;
}

double StackedState::drift_since_factorization() const {
  double drift = 0.0;
  for (const DamageField& field : fields_)
    drift = std::max(drift, field.growth_since_factorization());
  return drift;
}

void StackedState::matrix_in_factor(const Eigen::VectorXd& u, FactorChange how) {
  if (how == FactorChange::updated) {
    for (const TangentChange& c : pending_)
      factored_tangents_[c.interface][c.point] = c.tangent;
    update_rank_ += pending_rank_;
    return;
  }
  for (DamageField& field : fields_)
    field.mark_factorized();
  if (!updates_factor()) return;
  const StackedPlate& stack = m_.plate_.stack_;
  factored_tangents_.resize(static_cast<std::size_t>(stack.interface_count()));
  for (int i = 0; i < stack.interface_count(); ++i)
    stack.interface(i).point_tangents(u, interfaces_.committed().interfaces[static_cast<std::size_t>(i)],
                                      interface_damage(), factored_tangents_[static_cast<std::size_t>(i)]);
  update_rank_ = 0;
}

// With held laws the step's matrix is K̄ = K_plates + c0 M + Σ_p J_pᵀ T_p J_p, T_p the point's 3 × 3 tangent
// at the held damage: a refresh compares each point's T_p with the one in the factor and splits each change
// ΔT_p = V Λ Vᵀ by the signs of its eigenvalues into the columns √|λ| J_pᵀ v of C₊ or C₋ (DL8,
// docs/delamination.md). More than max_update_rank terms, more than max_total_update_rank since the
// factorization (their round-off adds up) or an unsymmetric change: no update.
std::optional<LowRankChange> StackedState::matrix_change(const Eigen::VectorXd& u) {
  constexpr Eigen::Index max_update_rank = 1000, max_total_update_rank = 20000;
  if (!updates_factor() || factored_tangents_.empty()) return std::nullopt;
  const StackedPlate& stack = m_.plate_.stack_;
  pending_.clear();
  std::vector<Eigen::Triplet<double>> up, down; // the columns of C₊ and C₋
  std::vector<std::pair<int, double>> rows[3];
  std::vector<Eigen::Matrix3d> now;
  for (int i = 0; i < stack.interface_count(); ++i) {
    const CohesiveInterface& face = stack.interface(i);
    const auto ii = static_cast<std::size_t>(i);
    face.point_tangents(u, interfaces_.committed().interfaces[ii], interface_damage(), now);
    for (int p = 0; p < face.point_count(); ++p) {
      const Eigen::Matrix3d& held = factored_tangents_[ii][static_cast<std::size_t>(p)];
      const Eigen::Matrix3d D = now[static_cast<std::size_t>(p)] - held;
      const double scale = now[static_cast<std::size_t>(p)].norm() + held.norm();
      if (D.norm() <= 1e-12 * scale) continue;
      if ((D - D.transpose()).norm() > 1e-12 * scale) return std::nullopt; // an unsymmetric tangent
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> split(0.5 * (D + D.transpose()));
      for (int k = 0; k < 3; ++k) {
        rows[k].clear();
        face.jump_row(p, k, rows[k]);
      }
      for (int e = 0; e < 3; ++e) {
        const double lambda = split.eigenvalues()(e);
        if (std::abs(lambda) <= 1e-12 * scale) continue;
        std::vector<Eigen::Triplet<double>>& side = lambda > 0.0 ? up : down;
        const int column = side.empty() ? 0 : side.back().col() + 1;
        for (int k = 0; k < 3; ++k)
          for (const auto& [eq, c] : rows[k])
            side.emplace_back(eq, column, std::sqrt(std::abs(lambda)) * split.eigenvectors()(k, e) * c);
      }
      pending_.push_back({ii, static_cast<std::size_t>(p), now[static_cast<std::size_t>(p)]});
    }
  }
  const auto columns = [n = stack.size()](const std::vector<Eigen::Triplet<double>>& t) {
    SparseMatrix C(n, t.empty() ? 0 : t.back().col() + 1);
    C.setFromTriplets(t.begin(), t.end());
    return C;
  };
  LowRankChange change{columns(up), columns(down)};
  pending_rank_ = change.rank();
  if (pending_rank_ > max_update_rank || update_rank_ + pending_rank_ > max_total_update_rank)
    return std::nullopt;
  return change;
}

void StackedState::commit(const Eigen::VectorXd& u, const Eigen::VectorXd& /*f*/) {
  if (held() && !fields_.empty()) {
    // The plies' laws once, at u_{n+1} (elements that reached a surface there join first).
    for (std::size_t k = 0; k < fields_.size(); ++k) {
      const DamagedPlate& part = *m_.damaged_[k];
      u_parts_[k] = u.segment(m_.plate_.stack_.offset(static_cast<int>(k)), part.size());
      (void)part.activate_reached(u_parts_[k], fields_[k]);
    }
    damaged_plate_forces(u, dt_); // held laws' commit: each sub-laminate's law once, at u, as one plate's
  }
  interfaces_.accept();
  if (m_.large_deflection())
    plate_work_.add(u, Ku_);
  else
    plate_energy_ = 0.5 * u.dot(Ku_);
  if (fields_.empty()) return;
  for (std::size_t k = 0; k < fields_.size(); ++k)
    m_.damaged_[k]->commit(u_parts_[k], f_parts_[k], fields_[k]);
  plies_->gather(fields_);
  set_results({.ply_damage = &*plies_, .interfaces = &interfaces_});
}

double StackedState::stored_energy(const Eigen::VectorXd& u) const {
  // Large deflections: what the plates' forces did not dissipate in their plies
  const double plates = m_.large_deflection()
                            ? plate_work_.work() - (plies_ ? plies_->dissipated().sum() : 0.0)
                            : plate_energy_;
  return plates + m_.plate_.stack_.interface_energy(u, interfaces_.committed(), interface_work_);
}

} // namespace

std::unique_ptr<MechanicalModel>
stacked_plate_model(const DiscretePlate& model, const DelaminationSettings& settings,
                    const std::optional<ProgressiveDamageSettings>& ply_damage,
                    std::optional<StrainMeasure> large_deflection) {
  return std::make_unique<StackedPlateModel>(model, settings, ply_damage, large_deflection);
}

SofteningMode fastest_softening(const Laminate& laminate, const StackSettings& stack) {
  const CohesiveParameters& p = stack.interface;
  const auto slope = [K = p.penalty_stiffness](double strength, double G_c) {
    return strength / (2.0 * G_c / strength - strength / K);
  };
  SofteningMode mode;
  mode.slope = std::max(slope(p.normal_strength, p.G_Ic), slope(p.shear_strength, p.G_IIc));
  const std::vector<Laminate> parts = split_laminate(laminate, stack.cuts, stack.shear_correction);
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    const double m_u = parts[i].inertia()[0], m_l = parts[i + 1].inertia()[0];
    mode.reduced_mass = std::min(mode.reduced_mass, m_u * m_l / (m_u + m_l));
  }
  return mode;
}

} // namespace plyimpact
