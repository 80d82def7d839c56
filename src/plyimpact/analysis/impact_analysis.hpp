#pragma once
// Low-velocity impact of a rigid sphere on the plate (SPEC §4; thesis 2.3–2.4, 3.5).
//
// Plate M ü + K u = Fc s (2.2), impactor m ẅi = −Fc (2.4), indentation α = wi − ws (2.8), contact
// law HertzContact. Newmark with constant Δt for both. K̄ = K + M/(βΔt²) is factored once; each
// step needs one back-substitution for the load-free predictor û and a scalar Newton solve for Fc,
// because ws = sᵀû + c·Fc with c = sᵀK̄⁻¹s computed once (SPEC §4).
#include "plyimpact/analysis/hertz_contact.hpp"
#include "plyimpact/analysis/parameters.hpp"
#include "plyimpact/fem/plate_model.hpp"
#include "plyimpact/fem/spd_solver.hpp"

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace plyimpact {

struct ImpactSettings {
  Impactor impactor;
  double k = 0.0; ///< contact stiffness [N/m^1.5]
  ContactLawParameters contact;
  double dt = 1e-6;          ///< [s]
  std::optional<double> end; ///< [s]; empty: SPEC §4 end-of-event rule
  double newmark_beta = 0.25, newmark_gamma = 0.5;
  long max_steps = 2'000'000;
  bool rigid_target = false; ///< rigid, immovable target (closed-form checks)
  SparseSolverKind solver = SparseSolverKind::cholmod_simplicial; ///< factorization of K̄ (bench/README.md)
  std::vector<double> field_times; ///< displacement snapshots at these times [s]
  int history_every = 1;           ///< keep every k-th step in the history (always the first and last)
  std::optional<double> memory_limit_bytes;          ///< refuse a factor of K̄ estimated above this
  const std::atomic<bool>* cancel = nullptr;         ///< stop after the current step when set
  std::function<void(double t, long step)> progress; ///< called about every 1000 steps
};

/// One row of the time history (SI).
struct ImpactSample {
  double t = 0.0;               ///< [s]
  double force = 0.0;           ///< contact force Fc [N]
  double impactor_w = 0.0;      ///< impactor displacement [m] (+z)
  double impactor_v = 0.0;      ///< impactor velocity [m/s]
  double plate_w = 0.0;         ///< plate deflection at the contact point ws [m]
  double indentation = 0.0;     ///< α = wi − ws [m]
  double plate_kinetic = 0.0;   ///< ½ vᵀMv [J]
  double plate_strain = 0.0;    ///< ½ uᵀKu [J]
  double impactor_energy = 0.0; ///< ½ m vi² [J]
  double contact_work = 0.0;    ///< ∫ Fc dα (trapezoidal, as Newmark integrates it) [J]
};

struct ContactEpisode {
  double start = 0.0, end = 0.0, peak_force = 0.0;
};

struct FieldSnapshot {
  double t = 0.0;
  Eigen::VectorXd u; ///< free DOFs of the PlateModel
};

/// Called every step with the plate state (free DOFs of the PlateModel) after it is converged.
using ImpactObserver = std::function<void(long step, double t, double force, const Eigen::VectorXd& u)>;

struct ImpactResult {
  std::vector<ImpactSample> history;
  std::vector<ContactEpisode> episodes;
  std::vector<FieldSnapshot> fields;
  double peak_force = 0.0, time_of_peak_force = 0.0;
  double contact_duration = 0.0; ///< of the first contact [s]
  double peak_contact_deflection = 0.0, max_indentation = 0.0, permanent_indentation = 0.0;
  double rebound_velocity = 0.0;    ///< speed of the impactor away from the plate at the end [m/s]
  double absorbed_energy = 0.0;     ///< ½ m (v0² − v_end²) [J]
  double contact_dissipation = 0.0; ///< ∮ Fc dα at the end [J]
  double fundamental_period = 0.0;  ///< used by the end-of-event rule [s]
  long steps = 0;
  int newton_iterations_max = 0;
  bool complete = false;
  std::string stop_reason;
  std::vector<std::string> warnings; ///< coarse Δt, impact point on an element boundary (guards.hpp)
  double wall_time = 0.0;            ///< [s]
  int dofs = 0;                      ///< equations in the time loop
  bool inplane_eliminated = false;
};

class ImpactSolver {
public:
  /// Assembles K and M, eliminates in-plane DOFs when they are exactly decoupled (B = 0, I1 = 0),
  /// and factors K̄ once.
  ImpactSolver(const PlateModel& model, ImpactSettings settings);
  ~ImpactSolver();
  ImpactSolver(const ImpactSolver&) = delete;
  ImpactSolver& operator=(const ImpactSolver&) = delete;

  /// Runs the event with the settings' impactor; `impactor` overrides it (same factorization).
  [[nodiscard]] ImpactResult run(const ImpactObserver& observer = {}) const;
  [[nodiscard]] ImpactResult run(const Impactor& impactor, const ImpactObserver& observer = {}) const;
  /// The same with contact stiffness `k` [N/m^1.5] instead of the settings' (an impactor of another
  /// radius or material on the same plate: parameter sweeps share one factorization).
  [[nodiscard]] ImpactResult run(const Impactor& impactor, double k,
                                 const ImpactObserver& observer = {}) const;

  [[nodiscard]] const ImpactSettings& settings() const { return settings_; }
  [[nodiscard]] int equations() const;
  /// Seconds for one triangular solve pair with the factor of K̄ (median of `repeats`).
  [[nodiscard]] double time_one_solve(int repeats = 21) const;

private:
  struct Plate;
  const PlateModel& model_;
  ImpactSettings settings_;
  std::unique_ptr<Plate> plate_;
};

/// Period of the lowest elastic (non-zero) mode [s].
[[nodiscard]] double fundamental_period(const PlateModel& model);

} // namespace plyimpact
