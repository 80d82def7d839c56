#pragma once
// What an impact run returns (SPEC §4 "Results of a run", §10 impact keys). SI units.
#include "plyimpact/analysis/impact/separation_end.hpp"
#include "plyimpact/fem/damaged_plate.hpp"
#include "plyimpact/fem/stacked_plate.hpp" // DelaminationAreas, DelaminationResult

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace plyimpact {

/// One row of the time history.
struct ImpactSample {
  double t = 0.0;               ///< [s]
  double force = 0.0;           ///< contact force Fc [N]
  double impactor_w = 0.0;      ///< impactor displacement [m] (+z)
  double impactor_v = 0.0;      ///< impactor velocity [m/s]
  double plate_w = 0.0;         ///< plate deflection at the contact point ws [m]
  double indentation = 0.0;     ///< α = wi − ws [m]
  double plate_kinetic = 0.0;   ///< ½ vᵀMv [J]
  double plate_strain = 0.0;    ///< elastic energy of the plate [J]
  double impactor_energy = 0.0; ///< ½ m vi² [J]
  double contact_work = 0.0;    ///< ∫ Fc dα (trapezoidal, as Newmark integrates it) [J]
  // Progressive damage only (zero / empty otherwise):
  double damage_dissipation = 0.0;     ///< energy dissipated by ply damage, all modes [J]
  double damage_area = 0.0;            ///< projected damaged area (union over the plies) [m²]
  std::vector<double> ply_damage_area; ///< damaged area of each ply [m²]
  // Stacked plate only (zero / empty otherwise):
  double delamination_dissipation = 0.0;          ///< energy dissipated by the interfaces [J]
  double delaminated_area = 0.0;                  ///< projected delaminated area (d = 1, any interface) [m²]
  std::vector<double> interface_delaminated_area; ///< delaminated area (d = 1) of each interface [m²]
};

/// The first load drop of a force history: the delamination threshold load F_d as a lab reads it
/// (analysis/thresholds/load_drop.hpp).
struct LoadDrop {
  double force = 0.0;    ///< F_d [N]
  double time = 0.0;     ///< when it was reached [s]
  double detected = 0.0; ///< the time of the first sample whose smoothed force fell by r [s]
};

/// When the delamination first grew (analysis/thresholds/load_drop.hpp).
struct FirstDelamination {
  double time = 0.0;  ///< [s]
  double force = 0.0; ///< contact force then [N]
};

/// What the force history says to a lab, and when the model's interfaces first cracked.
struct ForceHistoryReading {
  std::optional<LoadDrop> load_drop;                   ///< the first load drop, F_d
  std::optional<FirstDelamination> first_delamination; ///< stacked-plate runs whose interfaces cracked
};

struct ContactEpisode {
  double start = 0.0, end = 0.0, peak_force = 0.0;
};

/// The plate state (free DOFs of the DiscretePlate) at a requested time.
struct FieldSnapshot {
  double t = 0.0;
  Eigen::VectorXd u;
};

/// Newton statistics of a geometrically non-linear run.
struct NewtonStatistics {
  long iterations = 0;             ///< linear solves over all steps
  int max_iterations_per_step = 0; ///< most solves in one step
  int factorizations = 0;          ///< of K̄ = K_T + c0 M, including the first
  int factor_updates = 0;          ///< refreshes of K̄ by a rank update of its factor instead
};

/// When a damage mode first appeared (d > 0 at some point) in a run.
struct FirstDamageOfMode {
  int ply = 0;        ///< 1-based
  double time = 0.0;  ///< [s]
  double force = 0.0; ///< contact force then [N]
};

/// The plies' damage at the end of a progressive-damage run (fem/damaged_plate.hpp).
struct ProgressiveDamageResult {
  PerDamageMode dissipated;                                     ///< energy dissipated per mode [J]
  std::vector<double> ply_damage_area;                          ///< damaged area of each ply [m²]
  double projected_damage_area = 0.0;                           ///< union over the plies [m²]
  std::vector<ElementPlyDamage> element_ply_damage;             ///< largest d per mode, element and ply
  std::optional<DamageMode> first_mode;                         ///< mode of the first damage (d > 0)
  ByDamageMode<std::optional<FirstDamageOfMode>> first_by_mode; ///< each mode's first damage
  int active_elements = 0;                                      ///< elements that evaluated the law
  StrengthReduction strength_reduction; ///< strengths lowered to band limits, and where (reduce-strength)

  /// Ply, time and force of the first damage: those of the first damage of its mode, which appeared
  /// in the same step (at the same ply: the fields find both in one pass, fem/damaged_plate.hpp).
  [[nodiscard]] std::optional<FirstDamageOfMode> first() const {
    if (!first_mode) return std::nullopt;
    return first_by_mode[*first_mode];
  }
};

/// How an error-controlled run stepped (TimeStepControl, [time] adaptive = true).
struct AdaptiveStepResult {
  double tolerance = 0.0;           ///< of the local indentation error, relative to α_m
  double largest_dt = 0.0;          ///< [s]
  double smallest_allowed_dt = 0.0; ///< [s]
  double smallest_used_dt = 0.0;    ///< [s]
  long rejected_steps = 0;          ///< solved again at a finer level
  long steps_above_tolerance = 0;   ///< accepted at the finest level with the error above the bound
  double largest_error_ratio = 0.0; ///< of an accepted step's error estimate to the bound
  int factorizations = 0;           ///< of K̄, one per level used
};

/// What ended a run that reached its end: time.end, SPEC §4's re-hit rule, or the separation rule.
enum class EventEndRule { time, re_hit, separation };

struct ImpactResult {
  std::vector<ImpactSample> history; ///< every k-th step (RunRequest::history_every), first and last always
  std::vector<ContactEpisode> episodes;
  std::vector<FieldSnapshot> fields;
  double peak_force = 0.0, time_of_peak_force = 0.0;
  double contact_duration = 0.0; ///< of the first contact [s]
  double peak_contact_deflection = 0.0, max_indentation = 0.0, permanent_indentation = 0.0;
  /// Speed of the impactor away from the plate at the end [m/s]; empty while the impactor has not left
  /// the plate (still in contact, still approaching, or never touched it): it would not be a rebound.
  std::optional<double> rebound_velocity;
  std::optional<double> absorbed_energy; ///< ½ m (v0² − v_end²) [J]; empty when rebound_velocity is
  double contact_dissipation = 0.0;      ///< ∮ Fc dα at the end [J]
  /// The plate's kinetic plus strain energy at the last step [J], kept whatever the history (the absorbed
  /// energy's split, energy_split.hpp); empty where the plate was followed at the contact point alone.
  std::optional<double> final_plate_energy;
  /// The plate's first period, used by the end-of-event rule [s]; empty when it was not computed
  /// (time.end given, or a rigid target).
  std::optional<double> fundamental_period;
  double end_time = 0.0; ///< time of the last step [s]
  /// The rule that decides the end (time.end, or with time.end = "auto" / "separation" the rule that
  /// ended it or would have: re_hit while the separation rule has not)
  EventEndRule end_rule = EventEndRule::re_hit;
  std::optional<SeparationEnd> separation_end; ///< where the separation rule ended the run
  long steps = 0;
  int newton_iterations_max = 0; ///< most iterations of the scalar contact solve in one step
  /// The event is over: the end-of-event rule ended the run, or time.end came after the impactor had
  /// left the plate. False when the run stopped early (stop_reason) or ended in contact.
  bool complete = false;
  std::string stop_reason;       ///< why the run stopped before its end (step limit, interrupt)
  std::string incomplete_reason; ///< why `complete` is false (empty when it is true)
  /// The step that could not be solved, where the run was asked to keep its results (RunRequest::
  /// keep_failed_run); also its stop_reason. Empty otherwise.
  std::string failure;
  /// |½ m v0² − (impactor kinetic + plate kinetic + plate strain + damage dissipation + contact work)| at
  /// the end, as a
  /// fraction of ½ m v0² (impact_loop.hpp, energy_balance_tolerance).
  double energy_balance_error = 0.0;
  /// The largest kinetic energy of the mass that mass scaling added, ½ vᵀΔMv, over the run [J]; empty
  /// where the run scales none (analysis/impact/mass_scaling.hpp).
  std::optional<double> added_mass_kinetic_energy;
  bool suspect = false;              ///< energy_balance_error above energy_balance_tolerance
  std::string suspect_reason;        ///< why `suspect` is true (empty when it is false)
  std::vector<std::string> warnings; ///< guards.hpp: coarse Δt, mesh, cut-short or suspect run, w/h
  double wall_time = 0.0;            ///< [s]
  int dofs = 0;                      ///< equations in the time loop
  /// the plate was followed at the contact point alone, through its impulse response there
  /// (contact_point_response.hpp), instead of solved with K̄ every step
  bool contact_point_response = false;
  bool inplane_eliminated = false;
  std::optional<NewtonStatistics> newton; ///< geometrically non-linear and progressive-damage runs
  std::optional<ProgressiveDamageResult> progressive; ///< progressive-damage runs only
  std::optional<DelaminationResult> delamination;     ///< stacked-plate runs only
  std::optional<AdaptiveStepResult> time_steps;       ///< error-controlled runs only
  /// Read from the run's samples (analysis/thresholds/load_drop.hpp) where the front end kept them
  /// (io/run/impact_run.hpp); empty where it did not (a run that asks for the contact-point response keeps
  /// none).
  std::optional<ForceHistoryReading> force_history;
};

} // namespace plyimpact
