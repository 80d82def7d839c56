#pragma once
// The bilinear mixed-mode cohesive law of an interface that may delaminate (issue 19): tractions
// from the separation of the two faces, softening to zero once the interface has spent its fracture
// toughness. Camanho, Dávila & de Moura 2003 (J. Compos. Mater. 37:1415) for the bilinear law and
// the Benzeggagh–Kenane (B-K) mixed-mode propagation criterion; Turon, Camanho, Costa & Dávila 2006
// (Mech. Mater. 38:1072) for the onset criterion consistent with it; Turon, Dávila, Camanho & Costa
// 2007 (Eng. Fract. Mech. 74:1665) for the penalty stiffness and the cohesive-zone length.
// See docs/delamination.md for the derivations, the choices and the parameters.
//
// Interface frame: separation δ = (δ_s1, δ_s2, δ_n), traction τ = (τ_s1, τ_s2, σ_n), index 0 and 1
// the two shear (sliding) components, index 2 the normal one; δ_n > 0 opens the interface.
#include <Eigen/Core>

namespace plyimpact {

/// How the onset of softening depends on the mode mixity B (both coincide for pure modes).
enum class CohesiveOnset {
  /// Turon et al. 2006: Δ⁰² = Δ3⁰² + (Δsh⁰² − Δ3⁰²) B^η, the B-K form of the propagation criterion
  /// applied to the onset; the default (see docs/delamination.md, "Which onset criterion").
  turon_bk,
  /// Camanho et al. 2003: quadratic traction criterion (⟨σ_n⟩/N)² + (τ_sh/S)² = 1, i.e.
  /// 1/Δ⁰² = (1 − B)/Δ3⁰² + B/Δsh⁰².
  camanho_quadratic,
};

/// Parameters of the bilinear law, SI units. One penalty stiffness K for all three components
/// (Camanho et al. 2003; Turon et al. 2006): this is what makes the mode mixity of the separations
/// equal the energy ratio B = G_shear/G_T.
struct CohesiveParameters {
  double penalty_stiffness = 0.0; ///< K [Pa/m]: the initial (undamaged) stiffness, all components
  double normal_strength = 0.0;   ///< N = σ_n at the onset of pure mode I [Pa]
  double shear_strength = 0.0;    ///< S = |τ_sh| at the onset of pure shear [Pa]
  double G_Ic = 0.0;              ///< mode I fracture toughness [J/m²]
  double G_IIc = 0.0;             ///< mode II (shear) fracture toughness [J/m²]
  double bk_exponent = 0.0;       ///< η of Benzeggagh & Kenane 1996 [-]
  CohesiveOnset onset = CohesiveOnset::turon_bk;
  /// ρ: the closing penalty of a cracked point (d = 1) as a fraction of K, K_n(d) = K (1 − (1 − ρ) d)
  /// (DL10). 1 (the default): closing is never softened. Central differences take a quarter
  /// (cracked_faces_closing_fraction, docs/delamination.md, "Cracked faces that close").
  double cracked_closing_fraction = 1.0;
  friend bool operator==(const CohesiveParameters&, const CohesiveParameters&) = default;
};

/// The history of one integration point: the damage d ∈ [0, 1], which never decreases, and the
/// separation it was last updated with (where the next increment's path starts, for its dissipation).
/// A fresh interface has d = 0; an initial crack is d = 1.
struct CohesiveState {
  double damage = 0.0;
  Eigen::Vector3d separation = Eigen::Vector3d::Zero(); ///< [m]
};

/// What one update returns.
struct CohesiveResponse {
  Eigen::Vector3d traction = Eigen::Vector3d::Zero(); ///< (τ_s1, τ_s2, σ_n) [Pa]
  Eigen::Matrix3d tangent = Eigen::Matrix3d::Zero();  ///< consistent tangent ∂τ/∂δ [Pa/m]
  CohesiveState state;                                ///< state at the end of the increment
  double dissipated_energy = 0.0; ///< energy dissipated in the increment per unit area [J/m²]
};

/// Penalty stiffness K = α E3 / t (Turon et al. 2007): the interface then changes the compliance of
/// the laminate by a fraction of order 1/α. E3 is the through-thickness modulus of the adjacent plies
/// (E2 for a transversely isotropic ply), t the thickness of the thinner adjacent sub-laminate.
inline constexpr double turon_default_alpha = 50.0;
[[nodiscard]] double turon_penalty_stiffness(double E3, double sublaminate_thickness,
                                             double alpha = turon_default_alpha);

/// Length of the cohesive (process) zone ahead of a crack in an infinite body,
/// l_cz = M E G_c / τ⁰² (Turon et al. 2007, who list M for the classical models; Hillerborg et al.
/// 1976: M = 1; Rice 1980 and Falk et al. 2001: M = 9π/32). E is the transverse modulus of the plies
/// (E2 = E3), τ⁰ the strength of the mode considered, G_c its toughness. Slender arms (DCB, thin
/// sub-laminates) have a shorter zone; this is the estimate used for the mesh-size guidance.
inline constexpr double hillerborg_M = 1.0;
[[nodiscard]] double cohesive_zone_length(double E_transverse, double G_c, double strength,
                                          double M = hillerborg_M);

class CohesiveLaw {
public:
  /// Checks the parameters: all positive, and for every mode mixity the onset separation is below the
  /// final one (K large enough: K > N²/(2 G_Ic), K > S²/(2 G_IIc), and the mixed-mode equivalent).
  /// Throws std::invalid_argument with a message naming the offending parameter.
  explicit CohesiveLaw(const CohesiveParameters& parameters);

  [[nodiscard]] const CohesiveParameters& parameters() const { return p_; }

  // --- the pieces of the law, as functions of the separation -----------------------------------

  /// Mixed-mode equivalent separation λ = √(δ_s1² + δ_s2² + ⟨δ_n⟩²) [m] (compression does not count).
  [[nodiscard]] static double equivalent_separation(const Eigen::Vector3d& separation);
  /// Mode mixity B = G_shear/(G_I + G_shear) = δ_sh²/(δ_sh² + ⟨δ_n⟩²) (single K); 0 at δ = 0 by
  /// convention, 1 in compression with sliding.
  [[nodiscard]] static double mode_mixity(const Eigen::Vector3d& separation);

  /// B-K critical energy release rate G_c(B) = G_Ic + (G_IIc − G_Ic) B^η [J/m²].
  [[nodiscard]] double critical_energy_release_rate(double B) const;
  /// Equivalent separation at the onset of softening, Δ⁰(B) [m], per the chosen onset criterion.
  [[nodiscard]] double onset_separation(double B) const;
  /// Equivalent separation at full failure, Δᶠ(B) = 2 G_c(B) / (K Δ⁰(B)) [m]: the triangle under the
  /// equivalent traction–separation curve has area G_c(B).
  [[nodiscard]] double final_separation(double B) const;
  /// Damage of the bilinear law on its softening envelope at equivalent separation λ and mixity B:
  /// d = Δᶠ(λ − Δ⁰) / (λ(Δᶠ − Δ⁰)), clamped to [0, 1] (Camanho et al. 2003; Turon et al. 2006).
  [[nodiscard]] double envelope_damage(double lambda, double B) const;
  /// The equivalent separation below which an undamaged point is elastic whatever its mixity and stays
  /// out of the loading band under the envelope: (1 − band) min(Δ⁰_I, Δ⁰_II), less a round-off margin [m].
  [[nodiscard]] double elastic_limit(double loading_band) const;

  // --- the update at one integration point -----------------------------------------------------

  /// Tractions, consistent tangent, new state and dissipated energy for the separation `separation`
  /// at the end of an increment that started in state `previous`:
  ///   d = max(d_previous, envelope_damage(λ, B))       (irreversible),
  ///   τ = (1 − d) K (δ_s1, δ_s2, ⟨δ_n⟩) − K ⟨−δ_n⟩ e_n  (contact: σ_n = K δ_n for δ_n ≤ 0, never degraded).
  /// The energy dissipated while d grows from d₀ to d₁ at mixity B is exactly ∫ ½ K λ² dd along the
  /// envelope = G_c(B) (λ(d₁) − λ(d₀)) / (Δᶠ − Δ⁰), with λ(d) the envelope separation of damage d.
  /// The increment's separation is taken to move straight from the previous state's to `separation`,
  /// and the integral is summed over `dissipation_pieces` pieces of that path, each at its own mixity:
  /// exact for a proportional increment, first order in the piece length where the mixity changes.
  ///
  /// `loading_band` > 0 is for Newton's method on a structure: at a point whose equivalent separation is
  /// within the relative band below its envelope (λ ≥ (1 − band) λ_env(d)), the tangent is the
  /// softening one of the envelope instead of the secant, while the traction and state stay exact. The
  /// law is only piecewise smooth; choosing the loading side at its kink keeps the iterations of a point
  /// that is about to load (or to start softening) from cycling between the two pieces.
  [[nodiscard]] CohesiveResponse update(const CohesiveState& previous, const Eigen::Vector3d& separation,
                                        double loading_band = 0.0) const;

  /// Traction and tangent at the separation `separation` with the damage of `state` held fixed (the
  /// secant of the law, and the contact penalty in compression); the state's damage is kept, nothing is
  /// dissipated. The lagged step solves with it (docs/delamination.md, "Impact on the stacked plate").
  [[nodiscard]] CohesiveResponse at_fixed_damage(const CohesiveState& state,
                                                 const Eigen::Vector3d& separation) const;

  /// The mean traction of a time step from the separation `state.separation` (δ₀, the step's start) to
  /// `separation` (δ₁) with the damage of `state` held fixed, the discrete gradient of ψ(·; d): the
  /// traction τ̄ with τ̄ · (δ₁ − δ₀) = ψ(δ₁) − ψ(δ₀) exactly,
  ///   τ̄_s = ½ (1 − d) K (δ₀ + δ₁)_s in shear, τ̄_n = ½ k (δ₀ + δ₁)_n with k = (1 − d) K when both ends
  ///   open and K_n(d) when both close, τ̄_n = (ψ_n(δ₁) − ψ_n(δ₀)) / (δ₁ − δ₀)_n across the kink,     (DL6)
  /// and its tangent ∂τ̄/∂δ₁ (diagonal, continuous across the kink). The lagged step puts it in the
  /// trapezoidal rule's place of the mean of the two ends' tractions, so that the step keeps the energy
  /// also where faces open or close inside it (Armero & Petőcz 1998 for penalty contact, cited from
  /// memory; docs/delamination.md, "The lagged step keeps the energy"). The state's damage is kept,
  /// nothing is dissipated.
  [[nodiscard]] CohesiveResponse step_mean(const CohesiveState& state,
                                           const Eigen::Vector3d& separation) const;

  /// The closing penalty at damage d, K_n(d) = K (1 − (1 − ρ) d) (DL10): K on an intact point, ρ K on a
  /// cracked one [Pa/m].
  [[nodiscard]] double closing_stiffness(double damage) const {
    return p_.penalty_stiffness * (1.0 - (1.0 - p_.cracked_closing_fraction) * damage);
  }
  /// Free energy ψ = ½(1 − d) K (δ_sh² + ⟨δ_n⟩²) + ½ K_n(d) ⟨−δ_n⟩² stored per unit area [J/m²].
  [[nodiscard]] double stored_energy(const CohesiveState& state, const Eigen::Vector3d& separation) const;

  /// Pieces of an increment's path in the dissipation integral.
  static constexpr int dissipation_pieces = 16;

private:
  /// ∫ ½ K λ² dd from `previous` to the damage `d` (≥ previous.damage) along the straight path to
  /// `separation` (see update), and ½ (K_n(d₀) − K_n(d)) ⟨−δ_n⟩² where a closed point's damage grows under
  /// a closing penalty that follows it (ρ < 1, DL10).
  [[nodiscard]] double dissipation(const CohesiveState& previous, const Eigen::Vector3d& separation,
                                   double d) const;
  /// Derivative of Δ⁰ with respect to B.
  [[nodiscard]] double onset_separation_slope(double B) const;
  /// Envelope separation λ at which the damage is d, for mixity B (inverse of envelope_damage).
  [[nodiscard]] double envelope_separation(double d, double B) const;

  CohesiveParameters p_;
  double normal_onset_; ///< Δ3⁰ = N/K
  double shear_onset_;  ///< Δsh⁰ = S/K
};

} // namespace plyimpact
