#pragma once
// Observers of an impact run: damage tracking, stress probes, histories, ParaView frames, progress.
// They see a read-only view of each converged step and cannot change the run, except by asking it to
// stop (a threshold search stops at the first failure).
#include "plyimpact/analysis/impact/impact_result.hpp"
#include "plyimpact/fem/damaged_plate.hpp"

#include <Eigen/Core>
#include <optional>

namespace plyimpact {

/// The plate's part of a step's state, computed by the time loop on demand.
class PlateStateAccess {
public:
  virtual ~PlateStateAccess() = default;
  PlateStateAccess() = default;
  PlateStateAccess(const PlateStateAccess&) = delete;
  PlateStateAccess& operator=(const PlateStateAccess&) = delete;
  [[nodiscard]] virtual const Eigen::VectorXd& displacement() const = 0;
  [[nodiscard]] virtual double kinetic_energy() const = 0;
  [[nodiscard]] virtual double strain_energy() const = 0;
  /// Energy dissipated inside the plate (ply damage) [J].
  [[nodiscard]] virtual double dissipated_energy() const { return 0.0; }
  /// The plies' damage (progressive damage only).
  [[nodiscard]] virtual const PlyDamageView* damage() const { return nullptr; }
  /// The interfaces' areas and dissipation (stacked plate only).
  [[nodiscard]] virtual const DelaminationAreas* delamination_areas() const { return nullptr; }
  /// The interfaces' whole state (stacked plate only), computed at each call: for occasional outputs.
  [[nodiscard]] virtual std::optional<DelaminationResult> delamination() const { return std::nullopt; }
};

/// The state after a converged step (or the initial state, step 0).
class StepView {
public:
  long step = 0;
  double t = 0.0, dt = 0.0;     ///< [s]
  double force = 0.0;           ///< contact force [N]
  double indentation = 0.0;     ///< α [m]
  double plate_w = 0.0;         ///< plate deflection at the contact point [m]
  double impactor_w = 0.0;      ///< [m]
  double impactor_v = 0.0;      ///< [m/s]
  double impactor_energy = 0.0; ///< [J]
  double contact_work = 0.0;    ///< [J]
  /// The energy balance error as a fraction of ½ m v0² at the latest check (every energy_check_every
  /// steps, impact_loop.hpp); empty before the first.
  std::optional<double> energy_balance_error;

  const PlateStateAccess* plate = nullptr; ///< null for a rigid target

  /// Plate displacements over the free DOFs of the DiscretePlate (expanded once per step, on demand).
  [[nodiscard]] const Eigen::VectorXd& plate_displacement() const { return plate->displacement(); }
  /// ½ vᵀMv and the plate's elastic energy [J] (0 for a rigid target).
  [[nodiscard]] double plate_kinetic_energy() const { return plate ? plate->kinetic_energy() : 0.0; }
  [[nodiscard]] double plate_strain_energy() const { return plate ? plate->strain_energy() : 0.0; }
  /// Energy dissipated by ply damage [J] (0 without progressive damage).
  [[nodiscard]] double plate_dissipated_energy() const { return plate ? plate->dissipated_energy() : 0.0; }
  /// The plies' damage, or null without progressive damage.
  [[nodiscard]] const PlyDamageView* damage() const { return plate ? plate->damage() : nullptr; }
  /// The interfaces' whole state, or nothing unless the plate is stacked (computed at each call).
  [[nodiscard]] std::optional<DelaminationResult> delamination() const {
    return plate ? plate->delamination() : std::nullopt;
  }
  /// The interfaces' areas and dissipation, or null unless the plate is stacked.
  [[nodiscard]] const DelaminationAreas* delamination_areas() const {
    return plate ? plate->delamination_areas() : nullptr;
  }
};

/// The history row of a step view.
[[nodiscard]] ImpactSample history_sample(const StepView& v);
/// The same sample into `out`, whose per-ply and per-interface vectors keep their storage (no allocation
/// when their sizes do not change: a writer that formats a row per step).
void history_sample(const StepView& v, ImpactSample& out);

class ImpactObserver {
public:
  virtual ~ImpactObserver() = default;
  ImpactObserver() = default;
  ImpactObserver(const ImpactObserver&) = delete;
  ImpactObserver& operator=(const ImpactObserver&) = delete;

  /// Before the first step, with the initial state (step 0).
  virtual void on_start(const StepView& /*initial*/) {}
  /// After every converged step.
  virtual void on_step(const StepView& view) = 0;
  /// After the last step (which on_step has seen), with the run's summary values filled in.
  virtual void on_finish(const StepView& /*last*/, const ImpactResult& /*result*/) {}
  /// True to end the run after this step (stop_reason says the observer stopped it).
  [[nodiscard]] virtual bool wants_stop() const { return false; }
};

} // namespace plyimpact
