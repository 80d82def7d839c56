// The plate models behind the one interface the integrators drive (mechanical_model.hpp).
#include "plyimpact/fem/mechanical_model.hpp"

#include "plyimpact/fem/nonlinear_plate_model.hpp"

#include <utility>

namespace plyimpact {

namespace {

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

private:
  const SparseMatrix& K_;
  double stored_ = 0.0;
};

class ElasticPlate final : public MechanicalModel {
public:
  explicit ElasticPlate(const PlateModel& plate) : plate_(plate), equations_(plate.size()) {
    const SparseMatrix K = plate.stiffness(), M = plate.mass();
    equations_ = bending_equations_if_decoupled(plate, K, M);
    K_ = equations_.restrict(K);
    M_ = equations_.restrict(M);
  }
  [[nodiscard]] int size() const override { return equations_.size(); }
  [[nodiscard]] const PlateModel& contact_plate() const override { return plate_; }
  [[nodiscard]] const EquationSubset& contact_equations() const override { return equations_; }
  [[nodiscard]] bool inplane_eliminated() const override { return !equations_.all(); }
  void to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const override {
    if (equations_.all())
      out = u;
    else
      equations_.expand(u, out);
  }
  [[nodiscard]] const SparseMatrix& mass() const override { return M_; }
  [[nodiscard]] const SparseMatrix& initial_stiffness() const override { return K_; }
  [[nodiscard]] std::unique_ptr<ModelState> virgin_state() const override {
    return std::make_unique<ElasticState>(K_);
  }

private:
  const PlateModel& plate_;
  EquationSubset equations_;
  SparseMatrix K_, M_;
};

// --- The von Kármán plate ---------------------------------------------------------------------------

class VonKarmanState final : public ModelState {
public:
  explicit VonKarmanState(const NonlinearPlateModel& plate)
      : plate_(plate), u_(Eigen::VectorXd::Zero(plate.size())), f_(Eigen::VectorXd::Zero(plate.size())) {}
  void internal_force(const Eigen::VectorXd& u, double /*dt*/, Eigen::VectorXd& f) override {
    plate_.internal_force(u, f);
  }
  void commit(const Eigen::VectorXd& u, const Eigen::VectorXd& f) override {
    stored_ += 0.5 * (f + f_).dot(u - u_); // the internal forces' work, trapezoidal
    u_ = u;
    f_ = f;
  }
  [[nodiscard]] double stored_energy(const Eigen::VectorXd& /*u*/) const override { return stored_; }

private:
  const NonlinearPlateModel& plate_;
  Eigen::VectorXd u_, f_; ///< the committed displacement and its internal force
  double stored_ = 0.0;
};

class VonKarmanPlate final : public MechanicalModel {
public:
  VonKarmanPlate(const PlateModel& plate, StrainMeasure measure)
      : nonlinear_(plate, measure), equations_(plate.size()), K_(plate.stiffness()), M_(plate.mass()) {}
  [[nodiscard]] int size() const override { return equations_.size(); }
  [[nodiscard]] const PlateModel& contact_plate() const override { return nonlinear_.linear(); }
  [[nodiscard]] const EquationSubset& contact_equations() const override { return equations_; }
  void to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const override { out = u; }
  [[nodiscard]] const SparseMatrix& mass() const override { return M_; }
  [[nodiscard]] const SparseMatrix& initial_stiffness() const override { return K_; } // K_T(0) = K
  [[nodiscard]] std::unique_ptr<ModelState> virgin_state() const override {
    return std::make_unique<VonKarmanState>(nonlinear_);
  }

private:
  NonlinearPlateModel nonlinear_;
  EquationSubset equations_;
  SparseMatrix K_, M_;
};

// --- The plate whose plies crack ----------------------------------------------------------------------

class DamagingState final : public ModelState {
public:
  explicit DamagingState(const DamagedPlateModel& plate) : plate_(plate), field_(plate.virgin_field()) {}
  void internal_force(const Eigen::VectorXd& u, double dt, Eigen::VectorXd& f) override {
    plate_.explicit_internal_force(u, dt, field_, f);
  }
  void commit(const Eigen::VectorXd& u, const Eigen::VectorXd& f) override { plate_.commit(u, f, field_); }
  [[nodiscard]] double stored_energy(const Eigen::VectorXd& /*u*/) const override {
    return field_.stored_energy(); // ½ uᵀ K_s(d) u
  }
  [[nodiscard]] double dissipated_energy() const override { return field_.dissipated().sum(); }
  [[nodiscard]] const PlyDamageView* ply_damage() const override { return &field_; }

private:
  const DamagedPlateModel& plate_;
  DamageField field_;
};

class DamagingPlate final : public MechanicalModel {
public:
  DamagingPlate(const PlateModel& plate, const ProgressiveDamageSettings& settings)
      : damaged_(plate, settings), equations_(plate.size()), M_(plate.mass()) {}
  [[nodiscard]] int size() const override { return equations_.size(); }
  [[nodiscard]] const PlateModel& contact_plate() const override { return damaged_.model(); }
  [[nodiscard]] const EquationSubset& contact_equations() const override { return equations_; }
  void to_model(const Eigen::VectorXd& u, Eigen::VectorXd& out) const override { out = u; }
  [[nodiscard]] const SparseMatrix& mass() const override { return M_; }
  [[nodiscard]] const SparseMatrix& initial_stiffness() const override {
    return damaged_.undamaged_stiffness();
  }
  [[nodiscard]] std::unique_ptr<ModelState> virgin_state() const override {
    return std::make_unique<DamagingState>(damaged_);
  }
  [[nodiscard]] std::vector<std::string> warnings() const override {
    if (auto w = damaged_.strength_reduction_warning()) return {std::move(*w)};
    return {};
  }

private:
  DamagedPlateModel damaged_;
  EquationSubset equations_;
  SparseMatrix M_;
};

} // namespace

std::unique_ptr<MechanicalModel> elastic_plate_model(const PlateModel& plate) {
  return std::make_unique<ElasticPlate>(plate);
}

std::unique_ptr<MechanicalModel> von_karman_plate_model(const PlateModel& plate, StrainMeasure measure) {
  return std::make_unique<VonKarmanPlate>(plate, measure);
}

std::unique_ptr<MechanicalModel> damaging_plate_model(const PlateModel& plate,
                                                      const ProgressiveDamageSettings& settings) {
  return std::make_unique<DamagingPlate>(plate, settings);
}

} // namespace plyimpact
