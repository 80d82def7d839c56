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
#include "plyimpact/analysis/central_difference.hpp"
#include "plyimpact/analysis/stacked_plate_step.hpp"
#include "plyimpact/analysis/step_policy.hpp"

namespace plyimpact {

namespace {

/// The deck key that chooses this policy, for its messages.
constexpr const char* explicit_key = "[delamination] integration = \"explicit\"";

/// K_plates + the interfaces' penalty: the stack's tangent with every interface point intact.
SparseMatrix elastic_stiffness(const StackedPlateModel& stack) {
  return stack.evaluate(Eigen::VectorXd::Zero(stack.size()), stack.virgin_state()).tangent;
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

private:
  const ExplicitDelaminationPolicy& p_;
  Eigen::VectorXd Ku_;        ///< K_plates u_{n+1} of the last advance()
  Eigen::VectorXd f_;         ///< f_int(u_{n+1}) of the last advance()
  double plate_energy_ = 0.0; ///< ½ uᵀ K_plates u of the accepted state
  Eigen::VectorXd a_next_;
  double contact_flexibility_ = 0.0; ///< sᵀM⁻¹s, 1 / the mass the contact spring moves [1/kg]
};

class ExplicitDelaminationPolicy final : public StackedPlatePolicy {
public:
  ExplicitDelaminationPolicy(const PlateModel& model, const StepPolicyOptions& options,
                             const DelaminationSettings& settings)
      : StackedPlatePolicy(model, options, settings),
        scheme_(elastic_stiffness(stack_), M_, options.newmark, explicit_key, options.explicit_omega_max),
        K_plates_by_rows_(stack_.plate_stiffness()) {}

  [[nodiscard]] int factorizations() const override { return 0; }
  [[nodiscard]] std::unique_ptr<PlateStepper> start(const Impactor& impactor) const override {
    return std::make_unique<ExplicitDelaminationStepper>(*this, impactor);
  }

  CentralDifference scheme_;
  /// K_plates stored by rows for the step's product: each entry of K u is one sequential sum over its row,
  /// in the order (and so with the bits) of the column-wise product, without scattering into K u
  Eigen::SparseMatrix<double, Eigen::RowMajor> K_plates_by_rows_;
};

ExplicitDelaminationStepper::ExplicitDelaminationStepper(const ExplicitDelaminationPolicy& policy,
                                                         const Impactor& impactor)
    : StackedPlateStepper(policy, impactor), p_(policy), Ku_(Eigen::VectorXd::Zero(policy.equations())),
      f_(Eigen::VectorXd::Zero(policy.equations())), a_next_(Eigen::VectorXd::Zero(policy.equations())),
      contact_flexibility_(policy.scheme_.flexibility(loading_.sampler())) {}

ContactSolution ExplicitDelaminationStepper::advance(long step, double t, const PlateState& s,
                                                     const ContactStep& contact, Eigen::VectorXd& u_next) {
  p_.scheme_.predict(s, u_next);                                                 // CD1
  const ContactSolution cs = contact.solve(loading_.sampler().dot(u_next), 0.0); // CD2
  p_.scheme_.check_contact(step, t, cs, contact, contact_flexibility_);          // CD6
  Ku_.noalias() = p_.K_plates_by_rows_ * u_next;
  f_ = Ku_;
  StackedPlateState trial;
  const double dissipated =
      p_.stack_.add_interface_forces(u_next, committed(), f_, trial, CohesiveDamage::evolve);
  p_.scheme_.accelerate(cs.force * loading_.load(cs.alpha) - f_, step, t, a_next_); // CD3
  set_trial(std::move(trial), dissipated);
  return cs;
}

void ExplicitDelaminationStepper::accept(const PlateState& before, const Eigen::VectorXd& u_next) {
  StackedPlateStepper::accept(before, u_next);
  plate_energy_ = 0.5 * u_next.dot(Ku_);
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

std::unique_ptr<StepPolicy> explicit_delamination_step_policy(const PlateModel& model,
                                                              const StepPolicyOptions& options,
                                                              const DelaminationSettings& settings) {
  return std::make_unique<ExplicitDelaminationPolicy>(model, options, settings);
}

} // namespace plyimpact
