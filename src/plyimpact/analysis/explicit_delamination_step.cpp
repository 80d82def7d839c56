// The explicit step policy of the stacked plate whose interfaces delaminate (fem/stacked_plate.hpp):
// central differences on the lumped mass (central_difference.hpp, CD1 to CD6), as the stacked-shell
// impact models of the literature run in LS-DYNA and Abaqus/Explicit. Each step evaluates the interface
// law once, at u_{n+1}, from the committed states (CohesiveDamage::evolve: the damage grows with the
// step's own separation and its dissipation is the law's), and
//
//   a_{n+1} = M⁻¹ (Fc_{n+1} s_load − K_plates u_{n+1} − Σ f_coh(u_{n+1}; d_{n+1}))           (CD3)
//
// Nothing is solved: faces that clap after the impactor leaves, which cost the Newton policy ~10 solves
// a step, cost one evaluation here. The stable step (CD5) comes from the elastic stack, K_plates plus the
// interfaces' penalty K (which also holds closed faces apart); softening only lowers the frequencies. The
// shear penalty usually sets it: it moves each face by its translation and its rotation times half its
// thickness, and with the Mindlin rotary inertia ρh³/12 the faces of masses per area m_u, m_l vibrate at
// ω² ≥ 4 K (1/m_u + 1/m_l) (DL9, docs/delamination.md "The explicit step").
//
// With ply damage (docs/delamination.md, "Ply damage and delamination together") each sub-laminate is a
// damaged plate (fem/damaged_plate.hpp) on its own plies: K_plates u becomes Σ_k f_k(u_k; d_k), each
// sub-laminate's law evaluated once at u_{n+1} as the explicit damage step does, and the run reports the
// plies' damage of the whole laminate (fem/stacked_damage.hpp). Damage only softens, so the elastic
// stack's stable step still holds.
#include "plyimpact/analysis/central_difference.hpp"
#include "plyimpact/analysis/stacked_plate_step.hpp"
#include "plyimpact/analysis/step_policy.hpp"
#include "plyimpact/fem/stacked_damage.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace plyimpact {

namespace {

/// The deck key that chooses this policy, for its messages.
constexpr const char* explicit_key = "[delamination] integration = \"explicit\"";

/// K_plates + the interfaces' penalty: the stack's tangent with every interface point intact.
SparseMatrix elastic_stiffness(const StackedPlateModel& stack) {
  return stack.evaluate(Eigen::VectorXd::Zero(stack.size()), stack.virgin_state()).tangent;
}

/// Sub-laminate k's first ply in the laminate's numbering.
std::vector<int> first_plies(const StackedPlateModel& stack) {
  std::vector<int> first;
  int ply = 0;
  for (int k = 0; k < stack.sublaminate_count(); ++k) {
    first.push_back(ply);
    ply += static_cast<int>(stack.sublaminate(k).laminate().ply_count());
  }
  return first;
}

class ExplicitDelaminationPolicy;

class ExplicitDelaminationStepper final : public StackedPlateStepper {
public:
  ExplicitDelaminationStepper(const ExplicitDelaminationPolicy& policy, const Impactor& impactor);
  ContactSolution advance(long step, double t, const PlateState& s, const ContactStep& contact,
                          Eigen::VectorXd& u_next) override;
  void next_acceleration(const NewmarkCoefficients& /*nc*/, const PlateState& /*s*/,
                         const Eigen::VectorXd& /*u_next*/, Eigen::VectorXd& a_next) const override {
    a_next = a_next_;
  }
  void accept(const PlateState& before, const Eigen::VectorXd& u_next) override;
  /// ½ uᵀ K_plates u from the product the accepted step made, + the interfaces' stored energy.
  [[nodiscard]] double strain_energy(const PlateState& s, double force) const override;
  /// No solve and no factorization: all zero.
  [[nodiscard]] std::optional<NewtonStatistics> statistics() const override { return NewtonStatistics{}; }
  /// The interfaces' dissipation + the plies' (with ply damage).
  [[nodiscard]] double dissipated_energy() const override;
  [[nodiscard]] const PlyDamageView* damage() const override { return plies_ ? &*plies_ : nullptr; }

private:
  /// Σ_k f_k(u_k; d_k) of the damaged sub-laminates at u into Ku_ (each law once, trial states kept).
  void damaged_plate_forces(const Eigen::VectorXd& u);

  const ExplicitDelaminationPolicy& p_;
  Eigen::VectorXd Ku_;        ///< K_plates u_{n+1} (with ply damage: Σ_k f_k) of the last advance()
  Eigen::VectorXd f_;         ///< f_int(u_{n+1}) of the last advance()
  double plate_energy_ = 0.0; ///< ½ uᵀ K_plates u of the accepted state
  Eigen::VectorXd a_next_;
  Eigen::VectorXd force_;            ///< Fc s_load − f_int of the step (CD3), sized once
  StackedPlateState trial_buffer_;   ///< storage the interfaces' trial states are written into
  double contact_flexibility_ = 0.0; ///< sᵀM⁻¹s, 1 / the mass the contact spring moves [1/kg]
  // With ply damage, per sub-laminate: its damage field, its part of u_{n+1} and its force.
  std::vector<DamageField> fields_;
  std::vector<Eigen::VectorXd> u_parts_, f_parts_;
  std::optional<StackedDamageField> plies_; ///< the fields seen as the laminate's plies
};

class ExplicitDelaminationPolicy final : public StackedPlatePolicy {
public:
  ExplicitDelaminationPolicy(const PlateModel& model, const StepPolicyOptions& options,
                             const DelaminationSettings& settings,
                             const std::optional<ProgressiveDamageSettings>& ply_damage)
      : StackedPlatePolicy(model, options, settings),
        scheme_(elastic_stiffness(stack_), M_, options.newmark, explicit_key, options.explicit_omega_max),
        K_plates_by_rows_(stack_.plate_stiffness()) {
    if (!ply_damage) return;
    for (int k = 0; k < stack_.sublaminate_count(); ++k)
      damaged_.push_back(std::make_unique<DamagedPlateModel>(stack_.sublaminate(k), *ply_damage));
  }

  /// The stack's warnings and the damaged sub-laminates' lowered strengths: once when every sub-laminate
  /// says the same, otherwise each with its sub-laminate.
  [[nodiscard]] std::vector<std::string> warnings() const override {
    std::vector<std::string> w = StackedPlatePolicy::warnings();
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

  [[nodiscard]] int factorizations() const override { return 0; }
  [[nodiscard]] std::unique_ptr<PlateStepper> start(const Impactor& impactor) const override {
    return std::make_unique<ExplicitDelaminationStepper>(*this, impactor);
  }

  CentralDifference scheme_;
  /// K_plates stored by rows for the step's product: each entry of K u is one sequential sum over its row,
  /// in the order (and so with the bits) of the column-wise product, without scattering into K u
  Eigen::SparseMatrix<double, Eigen::RowMajor> K_plates_by_rows_;
  /// With ply damage: sub-laminate k as a damaged plate (empty without)
  std::vector<std::unique_ptr<DamagedPlateModel>> damaged_;
};

ExplicitDelaminationStepper::ExplicitDelaminationStepper(const ExplicitDelaminationPolicy& policy,
                                                         const Impactor& impactor)
    : StackedPlateStepper(policy, impactor), p_(policy), Ku_(Eigen::VectorXd::Zero(policy.equations())),
      f_(Eigen::VectorXd::Zero(policy.equations())), a_next_(Eigen::VectorXd::Zero(policy.equations())),
      force_(Eigen::VectorXd::Zero(policy.equations())),
      contact_flexibility_(policy.scheme_.flexibility(loading_.sampler())) {
  if (p_.damaged_.empty()) return;
  const StackedPlateModel& stack = p_.stack_;
  for (int k = 0; k < stack.sublaminate_count(); ++k) {
    const DamagedPlateModel& part = *p_.damaged_[static_cast<std::size_t>(k)];
    fields_.push_back(part.virgin_field());
    u_parts_.emplace_back(Eigen::VectorXd::Zero(part.size()));
    f_parts_.emplace_back(Eigen::VectorXd::Zero(part.size()));
  }
  plies_.emplace(first_plies(stack), static_cast<int>(p_.model_.laminate().ply_count()),
                 p_.model_.mesh().element_count());
  plies_->gather(fields_);
}

void ExplicitDelaminationStepper::damaged_plate_forces(const Eigen::VectorXd& u) {
  const double dt = p_.scheme_.time_step();
  for (std::size_t k = 0; k < fields_.size(); ++k) {
    const DamagedPlateModel& part = *p_.damaged_[k];
    const Eigen::Index first = p_.stack_.offset(static_cast<int>(k));
    u_parts_[k] = u.segment(first, part.size());
    part.explicit_internal_force(u_parts_[k], dt, fields_[k], f_parts_[k]);
    Ku_.segment(first, part.size()) = f_parts_[k];
  }
}

ContactSolution ExplicitDelaminationStepper::advance(long step, double t, const PlateState& s,
                                                     const ContactStep& contact, Eigen::VectorXd& u_next) {
  p_.scheme_.predict(s, u_next);                                                 // CD1
  const ContactSolution cs = contact.solve(loading_.sampler().dot(u_next), 0.0); // CD2
  p_.scheme_.check_contact(step, t, cs, contact, contact_flexibility_);          // CD6
  if (fields_.empty())
    Ku_.noalias() = p_.K_plates_by_rows_ * u_next;
  else
    damaged_plate_forces(u_next);
  f_ = Ku_;
  const double dissipated =
      p_.stack_.add_interface_forces(u_next, committed(), f_, trial_buffer_, CohesiveDamage::evolve);
  loading_.scaled_load(cs.alpha, cs.force, force_);
  force_ -= f_;
  p_.scheme_.accelerate(force_, step, t, a_next_); // CD3
  set_trial(trial_buffer_, dissipated);
  return cs;
}

void ExplicitDelaminationStepper::accept(const PlateState& before, const Eigen::VectorXd& u_next) {
  StackedPlateStepper::accept(before, u_next);
  plate_energy_ = 0.5 * u_next.dot(Ku_);
  if (fields_.empty()) return;
  for (std::size_t k = 0; k < fields_.size(); ++k)
    p_.damaged_[k]->commit(u_parts_[k], f_parts_[k], fields_[k]);
  plies_->gather(fields_);
}

double ExplicitDelaminationStepper::dissipated_energy() const {
  return StackedPlateStepper::dissipated_energy() + (plies_ ? plies_->dissipated().sum() : 0.0);
}

double ExplicitDelaminationStepper::strain_energy(const PlateState& s, double /*force*/) const {
  return plate_energy_ + p_.stack_.interface_energy(s.u, committed());
}

} // namespace

double explicit_delamination_highest_frequency(const PlateModel& model,
                                               const DelaminationSettings& settings) {
  const StackedPlateModel stack = impact_stack(model, settings);
  return explicit_highest_frequency(elastic_stiffness(stack), MassOperator(stack.mass(), 1e-14),
                                    explicit_key);
}

double explicit_delamination_time_step(const PlateModel& model, const DelaminationSettings& settings) {
  return stable_time_step(explicit_delamination_highest_frequency(model, settings));
}

std::unique_ptr<StepPolicy>
explicit_delamination_step_policy(const PlateModel& model, const StepPolicyOptions& options,
                                  const DelaminationSettings& settings,
                                  const std::optional<ProgressiveDamageSettings>& ply_damage) {
  return std::make_unique<ExplicitDelaminationPolicy>(model, options, settings, ply_damage);
}

} // namespace plyimpact
