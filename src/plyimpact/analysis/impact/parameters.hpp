#pragma once
// Plain parameter sets of the analyses (SPEC §4, §7, §8, §10). SI units throughout.
#include "plyimpact/fem/damaged_plate.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace plyimpact {

enum class AnalysisKind { impact, static_, modal, buckling, laminate, threshold };

/// The impactor's nose: a hemisphere (Hertz, SPEC §4), a flat-ended cylinder or a cone
/// (docs/impactor.md for the contact laws and their sources).
enum class NoseShape { hemisphere, flat, cone };

/// The deck spelling ("hemisphere", "flat", "cone").
[[nodiscard]] constexpr std::string_view to_string(NoseShape nose) {
  return nose == NoseShape::hemisphere ? "hemisphere" : nose == NoseShape::flat ? "flat" : "cone";
}

/// n of the loading law F = k α^n: 3/2 for the hemisphere (Hertz), 1 for the flat punch (Boussinesq),
/// 2 for the cone (Sneddon).
[[nodiscard]] constexpr double contact_exponent(NoseShape nose) {
  return nose == NoseShape::hemisphere ? 1.5 : nose == NoseShape::flat ? 1.0 : 2.0;
}

/// The unit of k in F = k α^n: "N/m^1.5", "N/m" or "N/m^2".
[[nodiscard]] constexpr std::string_view contact_constant_unit(NoseShape nose) {
  return nose == NoseShape::hemisphere ? "N/m^1.5" : nose == NoseShape::flat ? "N/m" : "N/m^2";
}

/// Rigid impactor (SPEC §4): a hemisphere of `radius` unless `nose` says otherwise.
struct Impactor {
  double mass = 0.0;     ///< [kg]
  double radius = 0.0;   ///< [m]: the hemisphere's, or the flat end's (flat); unused by the cone
  double E = 0.0;        ///< Young's modulus [Pa]
  double nu = 0.3;       ///< Poisson ratio [-]
  double velocity = 0.0; ///< initial velocity, positive towards the plate (+z) [m/s]
  double x = 0.0;        ///< impact point [m]
  double y = 0.0;        ///< [m]
  NoseShape nose = NoseShape::hemisphere;
  double half_angle = 0.0; ///< cone: the angle between its axis and its flank [rad]
  friend bool operator==(const Impactor&, const Impactor&) = default;
};

enum class UnloadingLaw { tan_sun, elastic };
enum class ContactLoad { point, hertz_pressure };

/// The deck spelling ("point", "hertz-pressure").
[[nodiscard]] constexpr std::string_view to_string(ContactLoad load) {
  return load == ContactLoad::point ? "point" : "hertz-pressure";
}

/// Contact law (2.5)–(2.7): loading k α^1.5, Tan–Sun unloading, Yang–Sun reloading.
struct ContactLawParameters {
  std::optional<double> k; ///< [N/m^1.5]; empty = "auto" (modified Hertz constant)
  UnloadingLaw unloading = UnloadingLaw::tan_sun;
  double q = 2.5;                                 ///< unloading exponent
  double beta = 0.094;                            ///< permanent-indentation factor
  double alpha_cr = 1.7e-4;                       ///< critical indentation [m]
  ContactLoad load = ContactLoad::hertz_pressure; ///< point: the thesis's point force
  friend bool operator==(const ContactLawParameters&, const ContactLawParameters&) = default;
};

/// Error-controlled time steps (issue 22, docs/deck.md `[time]`). The steps are dt_max/2^k, k = 0 … levels −
/// 1, each with its factor of K̄ computed when first used. A step is redone at a finer level when its error of
/// the indentation (Newmark's local error, or the error of interpolating the history between steps)
/// exceeds `tolerance` times the rigid-target Hertz indentation α_m
/// (analysis/integrators/time_step_control.hpp).
struct AdaptiveTimeStep {
  double tolerance = 1e-3; ///< of the local indentation error, relative to α_m
  int levels = 8;          ///< the smallest step is dt / 2^(levels − 1)
  friend bool operator==(const AdaptiveTimeStep&, const AdaptiveTimeStep&) = default;
};

/// How the plate moves from step to step (`[time] integration`, docs/deck.md;
/// analysis/impact/capabilities.hpp).
enum class TimeScheme {
  /// Newmark's implicit average acceleration (2.11)–(2.16): one factor of K̄ for the linear plate,
  /// Newton iterations for the others ([damage] and [delamination] choose implicit or lagged).
  newmark,
  /// Explicit central differences on the lumped mass (analysis/integrators/central_difference_step.cpp): the
  /// model's
  /// internal force once per step, nothing solved, a step below the stable one 0.9 · 2/ω_max.
  central_difference,
};

/// Which DOFs of an explicit run may take mass so that they stop setting its stable step (`[time]
/// mass_scaling`, docs/mass_scaling.md; analysis/impact/mass_scaling.hpp).
enum class MassScalingKind {
  none,   ///< the model's lumped mass as it is
  rotary, ///< the rotary inertia of the nodes (θx, θy) only: the thin-shell remedy of explicit codes
  nodal,  ///< any node, translations too: conventional target-step mass scaling, which adds real mass
  /// a stack's interfaces: mass K_c/ω_t² on the faces' relative motion only (Olovsson et al. 2005), none on
  /// the plate's motion, and the rotations as rotary
  selective,
};

/// `[time] mass_scaling` and `target_dt`.
struct MassScaling {
  MassScalingKind kind = MassScalingKind::none;
  /// The stable step the scaled DOFs are brought up to [s]; empty for rotary: the step of the translations
  /// (the rotations then never set the step).
  std::optional<double> target_dt;
  friend bool operator==(const MassScaling&, const MassScaling&) = default;
};

/// The time integrator of a case (the whole plate steps with one: capabilities.hpp). The laws' trials
/// follow it (fem/mechanical_model.hpp, LawTrials): implicit and central differences advance the laws
/// with each trial, lagged holds them at the step before and advances them once, at the commit.
enum class Integrator {
  implicit,           ///< Newmark: linear (one factor) or Newton–Newmark, the laws iterated with the step
  lagged,             ///< Newton–Newmark with the laws' state of the step before held fixed
  central_difference, ///< explicit central differences on the lumped mass
};

/// The deck spelling: "implicit", "lagged", "explicit".
[[nodiscard]] std::string_view to_string(Integrator i);

/// How a run without a given end time knows the event is over.
enum class EventEnd {
  re_hit,     ///< "auto": out of contact for the longer of the first contact and two periods T1 (SPEC §4)
  separation, ///< "separation": the impactor moves away above the plate's reach (separation_end.hpp)
};

/// Newmark time stepping (2.11)–(2.16).
struct TimeStepping {
  std::optional<double> dt;             ///< [s]; empty = "auto"
  std::optional<double> end;            ///< [s]; empty = "auto" or "separation" (end_rule)
  EventEnd end_rule = EventEnd::re_hit; ///< where `end` is empty
  double newmark_beta = 0.25;
  double newmark_gamma = 0.5;
  long max_steps = 2'000'000;
  /// Stop the run where its energy balance error passes this fraction of the impact energy (checked every
  /// energy_check_every steps, impact_loop.hpp); empty: run on and report the error at the end.
  std::optional<double> stop_at_energy_error;
  TimeScheme integration = TimeScheme::newmark;
  /// engaged: error-controlled steps (impact_loop.hpp): dt is the largest step, halved where the
  /// estimated local error of the indentation exceeds the tolerance
  std::optional<AdaptiveTimeStep> adaptive;
  MassScaling mass_scaling; ///< explicit runs only
  /// [damage] / [delamination] integration: how the laws step, one value for both (the plate steps with
  /// one integrator); empty: explicit where `integration` is, else lagged with interfaces, else implicit
  /// (case_integrator, capabilities.hpp).
  std::optional<Integrator> laws;
  friend bool operator==(const TimeStepping&, const TimeStepping&) = default;
};

struct ModalSettings {
  int count = 10;
};

struct BucklingSettings {
  double Nx = 0.0, Ny = 0.0, Nxy = 0.0; ///< reference in-plane loads [N/m], compression negative
  int count = 5;
};

struct DamageSettings {
  /// [damage] model = "progressive": the plies lose stiffness as they crack (docs/progressive_damage.md);
  /// empty = "onset" (criteria evaluated on the undamaged plate, today's default).
  std::optional<ProgressiveDamageSettings> progressive;
  /// [damage] refactor_tolerance where given: Newton–Newmark's NewtonSettings::refactor_tolerance for the
  /// case (case_from_deck); empty: the default of the table of what runs.
  std::optional<double> refactor_tolerance;
  std::vector<std::string> criteria; ///< deck names, e.g. "choi-chang-matrix"
  int every = 1;
  bool delamination_ply_n_lower = false; ///< (2.43): ply k+1 plays "n" (thesis wording) instead of ply k
};

/// Threshold-velocity search (SPEC §7).
struct ThresholdSettings {
  std::string criterion;     ///< empty: the first of [damage] criteria
  double tolerance = 0.01;   ///< [m/s]
  double max_velocity = 500; ///< [m/s]
  /// criterion "damage-area": the projected damaged area to exceed [m²]
  std::optional<double> damage_area;
};

/// A point where stress histories are written: ply (1-based) at z = top | bottom | average, or an
/// interface (1-based, stresses from both adjacent plies).
struct StressProbeSpec {
  std::string name;
  double x = 0.0, y = 0.0;
  int ply = 0, interface = 0;
  std::string position = "average";
};

} // namespace plyimpact
