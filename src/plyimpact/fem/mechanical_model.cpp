// The plate models behind the one interface the integrators drive (mechanical_model.hpp).
#include "plyimpact/fem/mechanical_model.hpp"

#include "plyimpact/fem/nonlinear_plate.hpp"
#include "plyimpact/fem/stacked_model.hpp"

#include <stdexcept>
#include <utility>

namespace plyimpact {

double ModelResults::dissipated_energy() const {
  return (interfaces ? interfaces->dissipated() : 0.0) + (ply_damage ? ply_damage->dissipated().sum() : 0.0);
}

EquationPlace MechanicalModel::place_of(int i) const {
  const auto& blocks = equations_.blocks;
  auto k = static_cast<int>(blocks.size()) - 1;
  while (k > 0 && i < blocks[static_cast<std::size_t>(k)].first)
    --k;
  const auto& [first, plate] = blocks[static_cast<std::size_t>(k)];
  const int local = k == 0 ? contact_equations().model_equation(i - first) : i - first;
  const auto [node, dof] = plate->dofs().node_dof(local);
  return {k, node, dof};
}

std::vector<EquationPlace> MechanicalModel::places() const {
  std::vector<EquationPlace> out;
  out.reserve(static_cast<std::size_t>(size()));
  const auto& blocks = equations_.blocks;
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    const std::vector<std::pair<int, int>> of_equation = blocks[k].second->dofs().node_dofs();
    const int end = k + 1 < blocks.size() ? blocks[k + 1].first : size();
    for (int i = blocks[k].first; i < end; ++i) {
      const int local = k == 0 ? contact_equations().model_equation(i) : i - blocks[k].first;
      const auto [node, dof] = of_equation[static_cast<std::size_t>(local)];
      out.push_back({static_cast<int>(k), node, dof});
    }
  }
  return out;
}

namespace {

/// The equations of a single plate: one block, its mass and virgin stiffness over `equations`.
ModelEquations single_plate_equations(const DiscretePlate& plate, const EquationSubset& equations,
                                      const SparseMatrix& M, const SparseMatrix& K) {
  ModelEquations e;
  e.size = equations.size();
  e.contact_plate = &plate;
  e.contact_equations = &equations;
  e.blocks = {{0, &plate}};
  e.mass = &M;
  e.initial_stiffness = &K;
  return e;
}

// --- The linear elastic plate -----------------------------------------------------------------------

class ElasticState final : public ModelState {
public:
  explicit ElasticState(const SparseMatrix& K) : K_(K) {}
  void internal_force(const Eigen::VectorXd& u, double /*dt*/, Eigen::VectorXd& f) override {
    f.noalias() = K_ * u;
  }
  void commit(const Eigen::VectorXd& u, const Eigen::VectorXd& f) override { stored_ = 0.5 * u.dot(f); }
  [[nodiscard]] double stored_energy(const Eigen::VectorXd& /*u*/) const override {
    return stored_; // ½ uᵀ K u
  }
  [[nodiscard]] SparseMatrix iteration_matrix(const Eigen::VectorXd& /*u*/) const override { return K_; }

private:
  const SparseMatrix& K_;
  double stored_ = 0.0;
};

class ElasticPlateModel final : public MechanicalModel {
public:
  explicit ElasticPlateModel(const DiscretePlate& plate) : equations_(plate.size()) {
    const SparseMatrix K = plate.stiffness(), M = plate.mass();
    equations_ = bending_equations_if_decoupled(plate, K, M);
    K_ = equations_.restrict(K);
    M_ = equations_.restrict(M);
    set_equations(single_plate_equations(plate, equations_, M_, K_));
  }
  void to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const override {
    if (equations_.all())
      out = u;
    else
      equations_.expand(u, out);
  }
  [[nodiscard]] std::unique_ptr<ModelState> virgin_state() const override {
    return std::make_unique<ElasticState>(K_);
  }

private:
  EquationSubset equations_;
  SparseMatrix K_, M_;
};

// --- The von Kármán plate ---------------------------------------------------------------------------

class VonKarmanState final : public ModelState {
public:
  explicit VonKarmanState(const NonlinearPlate& plate) : plate_(plate), work_(plate.size()) {}
  void internal_force(const Eigen::VectorXd& u, double /*dt*/, Eigen::VectorXd& f) override {
    plate_.internal_force(u, f, element_forces_);
  }
  [[nodiscard]] SparseMatrix iteration_matrix(const Eigen::VectorXd& u) const override {
    return plate_.tangent_stiffness(u); // K_T(u), consistent: quadratic convergence
  }
  void commit(const Eigen::VectorXd& u, const Eigen::VectorXd& f) override { work_.add(u, f); }
  [[nodiscard]] double stored_energy(const Eigen::VectorXd& /*u*/) const override { return work_.work(); }

private:
  const NonlinearPlate& plate_;
  WorkOfInternalForces work_;
  std::vector<ElementVector> element_forces_; ///< the element loop's places (NonlinearPlate)
};

class VonKarmanPlateModel final : public MechanicalModel {
public:
  VonKarmanPlateModel(const DiscretePlate& plate, StrainMeasure measure)
      : nonlinear_(plate, measure), equations_(plate.size()), K_(plate.stiffness()), M_(plate.mass()) {
    set_equations(single_plate_equations(nonlinear_.linear(), equations_, M_, K_)); // K_T(0) = K
  }
  void to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const override { out = u; }
  [[nodiscard]] std::unique_ptr<ModelState> virgin_state() const override {
    return std::make_unique<VonKarmanState>(nonlinear_);
  }

private:
  NonlinearPlate nonlinear_;
  EquationSubset equations_;
  SparseMatrix K_, M_;
};

// --- The plate whose plies crack ----------------------------------------------------------------------

class DamagingState final : public ModelState {
public:
  explicit DamagingState(const DamagedPlate& plate)
      : plate_(plate), field_(plate.virgin_field()), work_(plate.size()) {
    set_results({.ply_damage = &field_, .interfaces = nullptr});
  }
  /// Held damage: the matrix is that of the last trial.
  IterationMatrixFacts set_law_trials(LawTrials trials) override {
    held_ = trials != LawTrials::advance;
    return {.symmetric = true, .refresh_at_next_trial = held_};
  }
  void internal_force(const Eigen::VectorXd& u, double dt, Eigen::VectorXd& f) override {
    dt_ = dt;
    if (held_)
      plate_.frozen_internal_force_into(u, field_, f); // the damage of the last commit
    else
      plate_.internal_force_into(u, dt, field_, f);
  }
  void commit(const Eigen::VectorXd& u, const Eigen::VectorXd& f) override {
    if (held_) {
      // The law once, at u_{n+1} (elements that reached a surface there join first); its secant sections
      // are those of the next step.
      (void)plate_.activate_reached(u, field_);
      law_force_.resize(u.size());
      plate_.internal_force_into(u, dt_, field_, law_force_);
      commit_with(u, law_force_);
      return;
    }
    commit_with(u, f);
  }
  [[nodiscard]] double stored_energy(const Eigen::VectorXd& /*u*/) const override {
    if (plate_.kinematics() == Kinematics::linear) return field_.stored_energy(); // ½ uᵀ K_s(d) u
    return work_.work() - field_.dissipated().sum(); // what the internal forces did not dissipate
  }

  [[nodiscard]] SparseMatrix iteration_matrix(const Eigen::VectorXd& u) const override {
    return plate_.iteration_matrix(u, field_);
  }
  bool admit(const Eigen::VectorXd& u) override { return held_ || !plate_.activate_reached(u, field_); }
  [[nodiscard]] double drift_since_factorization() const override {
    return field_.growth_since_factorization();
  }
  void matrix_in_factor(const Eigen::VectorXd& /*u*/, FactorChange how) override {
    if (how == FactorChange::factorized) field_.mark_factorized();
  }
  bool take_branch_changed() override { return held_ && field_.take_modes_changed(); }

private:
  void commit_with(const Eigen::VectorXd& u, const Eigen::VectorXd& f) {
    plate_.commit(u, f, field_);
    if (plate_.kinematics() != Kinematics::linear) work_.add(u, f);
  }

  const DamagedPlate& plate_;
  DamageField field_;
  WorkOfInternalForces work_;
  Eigen::VectorXd law_force_; ///< with held laws: the force of the law at the commit
  double dt_ = 0.0;           ///< of the last trial: the viscous regularisation's time at the commit
  bool held_ = false;         ///< the trials hold the committed damage (LawTrials)
};

class DamagingPlateModel final : public MechanicalModel {
public:
  DamagingPlateModel(const DiscretePlate& plate, const ProgressiveDamageSettings& settings,
                     Kinematics kinematics)
      : damaged_(plate, settings, kinematics), equations_(plate.size()), M_(plate.mass()) {
    ModelEquations e =
        single_plate_equations(damaged_.model(), equations_, M_, damaged_.undamaged_stiffness());
    if (auto w = damaged_.strength_reduction_warning()) e.warnings.push_back(std::move(*w));
    set_equations(std::move(e));
  }
  void to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const override { out = u; }
  [[nodiscard]] std::unique_ptr<ModelState> virgin_state() const override {
    return std::make_unique<DamagingState>(damaged_);
  }

private:
  DamagedPlate damaged_;
  EquationSubset equations_;
  SparseMatrix M_;
};

} // namespace

std::unique_ptr<MechanicalModel> elastic_plate_model(const DiscretePlate& plate) {
  return std::make_unique<ElasticPlateModel>(plate);
}

std::unique_ptr<MechanicalModel> von_karman_plate_model(const DiscretePlate& plate, StrainMeasure measure) {
  return std::make_unique<VonKarmanPlateModel>(plate, measure);
}

std::unique_ptr<MechanicalModel> damaging_plate_model(const DiscretePlate& plate,
                                                      const ProgressiveDamageSettings& settings,
                                                      Kinematics kinematics) {
  return std::make_unique<DamagingPlateModel>(plate, settings, kinematics);
}

} // namespace plyimpact
