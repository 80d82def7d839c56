#pragma once
// Free vibration K φ = ω² M φ (SPEC §8): lowest frequencies by shift-invert Lanczos (Spectra).
#include "plyimpact/fem/block_mass.hpp"
#include "plyimpact/fem/discrete_plate.hpp"

#include <vector>

namespace plyimpact {

struct ModalResult {
  std::vector<double> frequencies_hz; ///< ascending; rigid-body and spurious modes appear as ≈ 0
  Eigen::MatrixXd modes;              ///< free-DOF mode shapes (columns), M-normalised
  int zero_energy_modes = 0;          ///< modes with φᵀKφ at round-off level (rigid + mechanisms)
};

/// The `count` lowest modes with the deck's mass matrix (or `mass` when given).
[[nodiscard]] ModalResult solve_modal(const DiscretePlate& model, int count);
[[nodiscard]] ModalResult solve_modal(const DiscretePlate& model, int count, MassMatrix mass);

/// The `count` lowest modes of K φ = ω² M φ for any symmetric K ≥ 0 and M > 0 (e.g. the stacked plate
/// with its interfaces' elastic stiffness).
[[nodiscard]] ModalResult solve_modal(const SparseMatrix& K, const SparseMatrix& M, int count);

/// Period of the lowest elastic (non-zero) mode [s], for the impact's end-of-event rule: of the bending
/// DOFs alone where the in-plane ones are exactly decoupled (bending_equations_if_decoupled).
[[nodiscard]] double fundamental_period(const DiscretePlate& model);
/// The same of K φ = ω² M φ as the time loop holds them (its equations only): a step policy that has
/// assembled them spares the assembly (StepPolicy::fundamental_period).
[[nodiscard]] double fundamental_period(const SparseMatrix& K, const SparseMatrix& M);

/// Relative residual at which the Lanczos iteration for ω_max stops (highest_angular_frequency).
constexpr double highest_frequency_tolerance = 1e-3;

/// The highest angular frequency ω_max of K φ = ω² M φ with a diagonal M (`mass`, all entries > 0),
/// by Lanczos on M^{-½} K M^{-½} (Spectra; its products on the element-loop threads) to a residual
/// of highest_frequency_tolerance, returned as the upper end √(θ (1 + tol)) of the converged Ritz
/// value θ's interval [rad/s]: above the exact value by at most 5e-4 relative. It sets the stable step
/// 2/ω_max of explicit central differences.
[[nodiscard]] double highest_angular_frequency(const SparseMatrix& K, const Eigen::VectorXd& mass);

/// ω_max of highest_angular_frequency and the equation where its mode's mass-weighted amplitude
/// √m_i |φ_i| is largest: where the kinetic energy of the highest mode gathers, the DOF that sets the
/// explicit step.
struct HighestMode {
  double omega = 0.0; ///< [rad/s]
  int equation = -1;
};
[[nodiscard]] HighestMode highest_mode(const SparseMatrix& K, const Eigen::VectorXd& mass);
/// The same with a block-diagonal mass (selective mass scaling), by Lanczos on M^-½ K M^-½; the equation
/// is that of the largest entry of M^½ φ.
[[nodiscard]] HighestMode highest_mode(const SparseMatrix& K, const BlockDiagonalMass& mass);

} // namespace plyimpact
