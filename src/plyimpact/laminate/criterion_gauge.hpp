#pragma once
// Lipschitz gauges of the failure criteria: upper bounds of a criterion's index that change by no more
// than a known constant times the change of the stresses, so that a tracker can prove that a point
// cannot fail (or raise the peak index) before its stresses have moved by a given amount, and skip it
// (analysis/fields/damage_tracker.hpp; docs/failure_criteria.md, "Skipping points that cannot fail").
//
// Every criterion of chapter 2.5 is, mode by mode, a quadratic form plus a linear term of the
// stresses, with the sign of a stress choosing the mode (Tsai–Hill: the strengths inside its form).
// Completing the square,
//   σᵀQσ + gᵀσ = ‖Lᵀσ + h‖² − ‖h‖²,   Q = LLᵀ, h = L⁻¹g/2,
// and a mode that holds only for σ_i ≥ 0 (or < 0) is written with the positive (negative) part of σ_i,
// which is 1-Lipschitz. So each mode is a branch N(σ) = ‖r(Wσ) + h‖ (r: identity, positive or negative
// part, row by row) with index = N² − ‖h‖² (quadratic branches) or N (linear branches, max-stress and
// max-strain), and
//   index(σ) ≤ max over branches of ψ(N(σ)),   |N(σ + δ) − N(σ)| ≤ Σ_j |δ_j| ‖W(:, j)‖.
// On its own sign region a branch equals its mode; elsewhere it is a bound (e.g. Hashin's tension branch
// keeps only the shear terms under transverse compression).
#include "plyimpact/laminate/failure_criteria.hpp"
#include "plyimpact/laminate/material.hpp"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <vector>

namespace plyimpact {

/// A plate ply's stresses in material axes, (σ11, σ22, τ12, τ13, τ23), σ33 = 0 [Pa].
using PlateStressVector = Eigen::Matrix<double, 5, 1>;

/// One branch N(σ) = ‖r(Wσ) + h‖₂ of a criterion's gauge.
struct GaugeBranch {
  enum class Ramp { none, positive, negative }; ///< r on one row: x, max(x, 0), min(x, 0)
  Eigen::Matrix<double, 5, 5> W = Eigen::Matrix<double, 5, 5>::Zero(); ///< rows beyond the branch's are 0
  Eigen::Matrix<double, 5, 1> h = Eigen::Matrix<double, 5, 1>::Zero();
  std::array<Ramp, 5> ramp{Ramp::none, Ramp::none, Ramp::none, Ramp::none, Ramp::none};
  bool quadratic = true; ///< index = N² − ‖h‖²; false: index = N (h = 0)

  /// N at the vector v = W σ (or any linear image of the state that equals it).
  [[nodiscard]] double norm_of_image(const Eigen::Matrix<double, 5, 1>& v) const;
  [[nodiscard]] double norm(const PlateStressVector& s) const { return norm_of_image(W * s); }
  /// ψ(N): the branch's index at σ.
  [[nodiscard]] double index(const PlateStressVector& s) const;
  /// The N below which the branch's index stays below `index_limit` (≥ 0).
  [[nodiscard]] double threshold(double index_limit) const;
};

/// The branches of `criterion` for a ply of material `m`: index(σ) ≤ max_b ψ_b(N_b(σ)) for every plate
/// stress σ (σ33 = 0). std::nullopt for the Choi–Chang criteria (the tracker bounds them on the
/// ply-averaged stresses itself), for Hoffman, Tsai–Wu or Tsai–Hill when a quadratic form is not
/// positive definite (e.g. |F12*| ≥ 1), and when a strength the criterion reads is missing.
[[nodiscard]] std::optional<std::vector<GaugeBranch>> criterion_gauge(Criterion criterion, const Material& m,
                                                                      const CriterionOptions& options = {});

} // namespace plyimpact
