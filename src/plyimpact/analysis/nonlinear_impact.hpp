#pragma once
// Large-deflection impact (SPEC §8, §4): Newmark with Newton iterations in each step on the coupled
// plate–impactor–contact system, total Lagrangian plate (NonlinearPlateModel).
//
// Step n → n+1, unknowns u (plate) and Fc. With a = c0 (u − uₙ) − c2 vₙ − c3 aₙ, the plate residual is
//   r(u, Fc) = Fc s − M a(u) − f_int(u) = 0,   and the contact law Fc = F(α), α = wᵢ(Fc) − sᵀu.
// Each Newton iteration linearizes the plate with K̄ = K_T + c0 M: u' = û + Fc t, û = u + K̄⁻¹ g(u),
// g = −M a(u) − f_int(u), t = K̄⁻¹ s, so sᵀu' is affine in Fc and the contact law is solved exactly
// (solve_contact_force) inside every iteration: plate and contact are solved together. K̄ is factored
// at the start and refreshed (modified Newton) only when the iterations slow down (contraction ratio
// above `refresh_ratio` or more than `refresh_after` iterations in a step); at small Δt, c0 M dominates
// K̄ and one factorization typically serves the whole event.
#include "plyimpact/analysis/impact_analysis.hpp"
#include "plyimpact/analysis/nonlinear_static.hpp"
#include "plyimpact/fem/nonlinear_plate_model.hpp"

namespace plyimpact {

struct NonlinearImpactSettings {
  StrainMeasure measure = StrainMeasure::von_karman;
  int max_iterations = 30;              ///< per time step
  double residual_tolerance = 1e-4;     ///< ‖r‖ ≤ tol · (‖f_int‖ + ‖M a‖ + ‖Fc s‖)
  double displacement_tolerance = 1e-6; ///< ‖Δu‖ ≤ tol · ‖u_{n+1}‖
  int refresh_after = 4;                ///< refactor K̄ when a step needs more iterations
  double refresh_ratio = 0.25;          ///< … or when ‖Δu_k‖/‖Δu_{k−1}‖ exceeds this
  long refresh_interval =
      200; ///< at most every this many steps, refactor at uₙ after a step needing > 1 solve
};

struct NonlinearImpactResult {
  ImpactResult impact;
  long newton_iterations = 0; ///< total over all steps
  int max_iterations_per_step = 0;
  int factorizations = 0; ///< of K̄ (including the first)
};

class NonlinearImpactSolver {
public:
  /// Assembles M, the tangent at rest, and factors K̄. Throws std::invalid_argument for options the
  /// non-linear solver does not support (rigid target, Hertzian pressure load).
  NonlinearImpactSolver(const PlateModel& model, ImpactSettings settings,
                        NonlinearImpactSettings nonlinear = {});

  /// Throws NewtonFailure when a step does not converge (with time and step in the message).
  [[nodiscard]] NonlinearImpactResult run(const ImpactObserver& observer = {}) const;
  [[nodiscard]] NonlinearImpactResult run(const Impactor& impactor,
                                          const ImpactObserver& observer = {}) const;

  [[nodiscard]] const ImpactSettings& settings() const { return settings_; }

private:
  const PlateModel& model_;
  ImpactSettings settings_;
  NonlinearImpactSettings nonlinear_;
  NonlinearPlateModel plate_;
  SparseMatrix M_;
  Eigen::VectorXd m_diag_; ///< M when diagonal, else empty
  double period_ = 0.0;
};

} // namespace plyimpact
