#pragma once
// Mass scaling of an explicit run (docs/mass_scaling.md): mass added to the DOFs whose frequency would set
// the stable step, so that central differences take longer steps.
//
// Which DOFs need mass comes from Gershgorin's theorem on the symmetric form M^-½ K M^-½ of K φ = ω² M φ
// (M lumped, diagonal): every eigenvalue ω² lies in a disc around K_ii/m_i of radius
// Σ_{j≠i} |K_ij|/√(m_i m_j), so
//
//     ω_max² ≤ max_i g_i,   g_i = K_ii/m_i + Σ_{j≠i} |K_ij| / √(m_i m_j).                      (MS1)
//
// (The rows of M⁻¹K give a bound too, but one that mixes units where rotations, whose inertia is
// ρh³/12, sit beside translations: it overstates a thin sub-laminate's rotations a thousandfold.)
// A DOF with g_i above a target ω_t² is given the smallest mass that brings its g_i to ω_t² with its
// neighbours' masses as they were: with x = 1/√m_i and S_i = Σ_{j≠i} |K_ij|/√m_j,
//
//     K_ii x² + S_i x = ω_t²   →   m_i' = ((√(S_i² + 4 K_ii ω_t²) + S_i) / (2 ω_t²))²          (MS2)
//
// Masses only grow, so every S_i only falls: one pass bounds every scaled row by ω_t². Scaling every DOF
// ("nodal") bounds ω_max by ω_t whatever the model; scaling the rotations only ("rotary") bounds them by
// the translations' largest g, so that they stop setting the step.
// A node's two rotations take the same inertia, and a node's translations the same mass (the larger of
// what each needs): the scaled node stays isotropic, as a lumped node of the unscaled model is.
// The step itself is then measured on the scaled mass (modal_analysis.hpp, highest_mode), not taken from
// MS1, which is an upper bound.
//
// Selective scaling of a stack's interfaces (Olovsson, Simonsson & Unosson 2005, Int. J. Numer. Meth.
// Engng 63:1436) adds to the lumped mass M a mass proportional to the interfaces' intact penalty stiffness
// K_c (the part of K that ties the faces of neighbouring sub-laminates):
//
//     M_s = M + K_c / ω_c²,   ω_c = interface_frequency_ratio · ω_t.                           (MS3)
//
// K_c annihilates every motion in which the faces move together (the plate's rigid and common motion),
// so the plate's mass, momentum and slow modes are those of M; the faces' relative modes are bounded,
// K_c φ = λ M_s φ giving λ < ω_c². The plates' rotations take MS2 on K − K_c to ω_t. ω_c is half of ω_t
// because the interface law, evaluated once per step, creates energy where the faces' own mode comes
// near the step's limit (softening, and faces that touch again: docs/mass_scaling.md, measured); K_c is
// nodal (the interface points are the nodes), so M_s is block-diagonal, one block per node and direction
// (fem/block_mass.hpp).
#include "plyimpact/analysis/impact/parameters.hpp"
#include "plyimpact/fem/block_mass.hpp"
#include "plyimpact/fem/mechanical_model.hpp"

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace plyimpact {

/// ω_c/ω_t of MS3: the interfaces' relative modes held at half the target frequency (docs/mass_scaling.md).
inline constexpr double interface_frequency_ratio = 0.5;

/// What a mass scaling added, for the summary and the report.
struct MassScalingReport {
  MassScalingKind kind = MassScalingKind::none;
  double target_omega = 0.0;                      ///< ω_t of MS2 [rad/s]
  double target_dt = 0.0;                         ///< the stable step of ω_t, 0.9 · 2/ω_t [s]
  std::vector<double> mass_kg;                    ///< each sub-laminate's translational mass, unscaled
  std::vector<double> added_mass_kg;              ///< per sub-laminate (one for a single laminate)
  std::vector<double> rotary_inertia_kg_m2;       ///< each sub-laminate's rotary inertia, unscaled
  std::vector<double> added_rotary_inertia_kg_m2; ///< per sub-laminate
  double largest_factor = 1.0;                    ///< the largest m_i'/m_i
  int scaled_nodes = 0;                           ///< nodes of every sub-laminate given mass or inertia
  /// Selective: the largest diagonal entry of K_c/ω_c² over the lumped mass of its DOF (the faces'
  /// relative motion is that much heavier); 0 otherwise.
  double interface_factor = 0.0;
};

/// The mass of an explicit run, scaled or not: the lumped diagonal, plus with selective scaling the
/// interfaces' K_c/ω_t² (MS3).
struct ScaledMass {
  Eigen::VectorXd mass;       ///< the diagonal the integrator moves with [kg, kg·m²]
  std::vector<int> equations; ///< the equations given mass on the diagonal, ascending
  std::vector<double> added;  ///< what each of them was given
  SparseMatrix coupling;      ///< K_c/ω_c² of MS3; empty (0 × 0) without selective scaling
  /// diag(mass) + coupling, blocks inverted once; null where the mass is diagonal
  std::shared_ptr<const BlockDiagonalMass> blocks;
  MassScalingReport report;

  /// ½ Σ Δm_i v_i² + ½ vᵀ (K_c/ω_c²) v: the kinetic energy of the added mass at the velocity v [J].
  [[nodiscard]] double added_kinetic_energy(const Eigen::VectorXd& v) const;
  /// The whole mass as a matrix: diag(mass) + coupling.
  [[nodiscard]] SparseMatrix matrix() const;
};

/// The DOFs a Gershgorin bound runs over.
enum class DofGroup { translations, rotations, all };

/// MS1: max_i g_i over the equations of `group` [rad²/s²] (0 where it has none).
[[nodiscard]] double gershgorin_bound(const SparseMatrix& K, const Eigen::VectorXd& m,
                                      std::span<const EquationPlace> places, DofGroup group);

/// MS2 (and MS3) on the diagonal mass `m` of stiffness `K` (symmetric; both in the integrator's
/// numbering), whose equation i lies at `places[i]` on a mesh of `nodes` nodes per sub-laminate;
/// `interfaces` is the part K_c of K that ties sub-laminates (null for a single plate). Throws
/// std::invalid_argument where `scaling` asks for nodal scaling without a target step, or for selective
/// scaling without interfaces.
[[nodiscard]] ScaledMass scaled_mass(const SparseMatrix& K, const Eigen::VectorXd& m,
                                     std::span<const EquationPlace> places, int nodes,
                                     const MassScaling& scaling, const SparseMatrix* interfaces = nullptr);

/// The largest translational mass a scaling may add, as a fraction of the plate's, before the run is
/// marked suspect (issue 77: target_dt = 1e-6 s added 19.7 kg to a 0.2 g plate and quadrupled the peak
/// force, silently). Explicit codes' practice keeps added mass to a few per cent of the model's.
inline constexpr double added_mass_fraction_tolerance = 0.05;

/// Where a scaling added more than added_mass_fraction_tolerance of the plate's translational mass: the
/// reason the run is suspect — the added mass against the plate's, and the factor by which the frequency
/// of a mode that moves the plate's mass together falls, √(m / (m + Δm)).
[[nodiscard]] std::optional<std::string> added_mass_suspicion(const MassScalingReport& report);

/// "rotary inertia x 3.2 at most on 1 240 nodes (added 4.1e-07 kg m^2, 12 % of the plate's)" and the like.
[[nodiscard]] std::string mass_scaling_text(const MassScalingReport& report);

[[nodiscard]] const char* to_string(MassScalingKind kind);

} // namespace plyimpact
