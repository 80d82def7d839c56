#pragma once
// The end of an event by separation (issue 80): once the impactor has left and moves away, it cannot
// touch the plate again when it is farther above it than the plate can ever rise.
//
// Out of contact no force works on the plate, so its kinetic plus strain energy E can only fall (the laws
// dissipate, nothing feeds it). Of all the plate's states with the deflection w0 at the impact point, the
// one of least strain energy is the static response to a point force there, ½ w0²/c, c the point's
// compliance (the deflection under a unit force). So |w(t)| ≤ √(2 E c) from now on          (SE1)
// for a linear plate that keeps its stiffness. The impactor, with no force on it, moves away at its
// rebound speed; contact needs an indentation α = w_i − w above the permanent one α_p, which cannot
// happen again once
//     w_i + A ≤ α_p,   A = f √(2 E c),                                                      (SE2)
// f = separation_safety_factor: the rule takes c of the undamaged plate, and a plate that has cracked or
// delaminated is softer; f = 2 covers a compliance four times the intact one at the impact point. Each
// check also tests SE1 on the deflection reached: a plate that rises above √(2 E c) is softer than the
// bound assumes, and the rule then steps aside for the re-hit rule of SPEC §4 (with a warning).

#include <optional>
#include <string>

namespace plyimpact {

/// The amplitude bound's margin on the undamaged plate's √(2 E c) (SE2).
inline constexpr double separation_safety_factor = 2.0;

/// Where the separation rule ended a run.
struct SeparationEnd {
  double time = 0.0;            ///< [s]
  double impactor_gap = 0.0;    ///< α_p − w_i − A: how far the impactor was above the plate's reach [m]
  double amplitude_bound = 0.0; ///< A of SE2 [m]
  double plate_energy = 0.0;    ///< E [J]
  double compliance = 0.0;      ///< c [m/N]
};

/// The plate and impactor state the rule looks at, after a step out of contact.
struct SeparationState {
  double t = 0.0;                     ///< [s]
  double impactor_w = 0.0;            ///< impactor displacement, positive toward the plate [m]
  double impactor_v = 0.0;            ///< its velocity, positive toward the plate [m/s]
  double plate_w = 0.0;               ///< the plate's deflection at the impact point, same sign [m]
  double permanent_indentation = 0.0; ///< α_p of the contact law [m]
  double plate_energy = 0.0;          ///< kinetic plus strain energy [J]
};

/// SE1–SE2 checked after steps out of contact.
class SeparationRule {
public:
  /// `compliance`: w at the impact point under a unit force there, of the undamaged plate [m/N] (0 for a
  /// rigid target).
  explicit SeparationRule(double compliance) : compliance_(compliance) {}

  /// True (and end() set) once the impactor moves away above the plate's reach; false otherwise, and
  /// always after the bound failed (bound_failure()).
  bool cannot_hit_again(const SeparationState& s);

  [[nodiscard]] const std::optional<SeparationEnd>& end() const { return end_; }
  /// Why the bound was given up (the plate rose above SE1's √(2 E c)); empty while it holds.
  [[nodiscard]] const std::optional<std::string>& bound_failure() const { return failure_; }

private:
  double compliance_;
  std::optional<SeparationEnd> end_;
  std::optional<std::string> failure_;
};

} // namespace plyimpact
