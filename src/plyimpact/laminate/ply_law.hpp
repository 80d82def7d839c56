#pragma once
// A ply law at one point: what the layered section (fem/layered_section.hpp) asks of the material of a
// ply, and all it asks. The law knows a point — a strain in material axes, the committed state, the
// crack band L_c and the step dt — and nothing of elements, sections or integrators: a new law
// implements this interface, make_ply_law() chooses it, and no element or integrator changes.
//
//   advance    one increment from the committed state to a strain: the new state, the secant
//              stiffnesses C(d), G(d) and the energy dissipated (what an advancing trial needs);
//   secant_at  the secants at held damage, the loaded branches (open or closed cracks) chosen by the
//              strain (what a held trial needs);
//   onset_bound an upper bound of the undamaged ply's onset index along a segment of stresses: the
//              section's screen, which skips the law at points far from every onset surface.
//
// The vocabulary every law shares is here too: the failure modes, a ply point's strain, its state (per
// mode: damage, the equivalent strains of onset and of the largest load; the strain), what an
// increment returns. PlyDamageLaw (laminate/ply_damage.hpp: Hashin onset, bilinear softening by crack
// band) is the first law.
#include "plyimpact/laminate/material.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

namespace plyimpact {

/// The four failure modes of Hashin's criterion, each with its own damage variable.
enum class DamageMode {
  fibre_tension,      ///< d_ft, active while σ̂11 ≥ 0
  fibre_compression,  ///< d_fc, active while σ̂11 < 0
  matrix_tension,     ///< d_mt, active while σ̂22 ≥ 0
  matrix_compression, ///< d_mc, active while σ̂22 < 0
};

inline constexpr std::array<DamageMode, 4> all_damage_modes{
    DamageMode::fibre_tension, DamageMode::fibre_compression, DamageMode::matrix_tension,
    DamageMode::matrix_compression};

/// "fibre-tension", "fibre-compression", "matrix-tension", "matrix-compression".
[[nodiscard]] std::string_view to_string(DamageMode mode);

/// One T per damage mode, indexed by the mode.
template <class T>
struct ByDamageMode {
  std::array<T, 4> values{};

  [[nodiscard]] T& operator[](DamageMode mode) { return values[static_cast<std::size_t>(mode)]; }
  [[nodiscard]] const T& operator[](DamageMode mode) const { return values[static_cast<std::size_t>(mode)]; }
};

/// One number per damage mode (damage variables, equivalent strains, dissipated energies...).
struct PerDamageMode : ByDamageMode<double> {
  [[nodiscard]] double sum() const { return values[0] + values[1] + values[2] + values[3]; }
};

/// Ply strain in material axes (1 = fibre, 2 = transverse in-plane, 3 = thickness), engineering
/// shear strains. The orders are those of laminate/ply_stiffness.hpp: in-plane (11, 22, 12) as
/// reduced_stiffness(), transverse shear (23, 13) as transverse_shear_stiffness().
struct PlyStrain {
  Eigen::Vector3d in_plane = Eigen::Vector3d::Zero();         ///< ε11, ε22, γ12
  Eigen::Vector2d transverse_shear = Eigen::Vector2d::Zero(); ///< γ23, γ13
};

/// History of one ply at one integration point: a value, copied and committed by the caller once
/// the step has converged. Default-constructed = virgin material.
/// Equivalent displacements are stored per unit characteristic length (equivalent strains
/// ε_eq = δ_eq/L_c), so that the state does not depend on L_c.
struct PlyDamageState {
  PerDamageMode damage;             ///< d_I of the softening law, rate independent, in [0, 1]
  PerDamageMode regularised_damage; ///< d_v,I, viscous; enters the stiffness (= d_I when η = 0)
  PerDamageMode
      max_equivalent_strain; ///< κ_I = largest δ_eq,I/L_c reached, mode I loaded, since it initiated
  PerDamageMode onset_equivalent_strain; ///< δ⁰_eq,I/L_c where mode I initiated; 0 before initiation
  PerDamageMode onset_equivalent_stress; ///< σ⁰_eq,I where mode I initiated [Pa]
  PlyStrain strain;                      ///< the strain of this state (start point of the next increment)
  /// The toughness a mixed-mode mode softens with, fixed at its onset by the mode mix there (the
  /// fracture-plane law's matrix crack); 0 where the law's toughnesses do not depend on the mix [J/m²]
  double crack_toughness = 0.0;

  [[nodiscard]] bool initiated(DamageMode mode) const { return onset_equivalent_strain[mode] > 0.0; }
  /// No mode has initiated and no stiffness variable has moved: the law answers such a ply below every
  /// Hashin surface with its undamaged stiffness and this state, its strain replaced.
  [[nodiscard]] bool virgin() const {
    return std::all_of(all_damage_modes.begin(), all_damage_modes.end(), [this](DamageMode mode) {
      return !initiated(mode) && regularised_damage[mode] == 0.0;
    });
  }
};

/// Which ply law a run uses (make_ply_law).
enum class PlyLawKind {
  hashin,         ///< PlyDamageLaw: Hashin onset, four modes (laminate/ply_damage.hpp)
  fracture_plane, ///< FracturePlaneLaw: matrix cracks on Puck's fracture plane (fracture_plane_law.hpp)
};

/// Settings of the damage law.
struct PlyDamageOptions {
  /// The law (deck: [damage] ply_law).
  PlyLawKind law = PlyLawKind::hashin;
  /// α, weight of the in-plane shear in Hashin's fibre-tension mode, F_ft = (σ̂11/Xt)² + α(τ̂12/S12)²
  /// and δ_eq,ft = L_c √(⟨ε11⟩² + α γ12²). 1 is Hashin (1980); 0 (default, Hashin–Rotem 1973 for this mode)
  /// keeps in-plane shear from breaking fibres, which with α = 1 it does at τ12 = S12
  /// (docs/progressive_damage.md).
  double alpha = 0.0;
  /// η [s], time constant of the viscous regularisation; 0 = rate independent.
  double viscosity = 0.0;
  friend bool operator==(const PlyDamageOptions&, const PlyDamageOptions&) = default;
};

/// What one increment returns to a structure: the state, stresses and secant stiffnesses, and the
/// energy dissipated; what a plate's internal force and secant need.
struct PlyDamageUpdate {
  PlyDamageState state;                    ///< state at the end of the increment
  Eigen::Vector3d stress;                  ///< σ11, σ22, τ12 [Pa]
  Eigen::Vector2d transverse_shear_stress; ///< τ23, τ13 [Pa]
  Eigen::Matrix3d secant;                  ///< C(d), damaged reduced stiffness (11, 22, 12) [Pa]
  /// diag((1 − d_t)G23, (1 − d_t)G13), order (23, 13), with the matrix damage d_t = 1 − (1 − d_mt)(1 − d_mc)
  /// [Pa]: a matrix crack transfers no transverse shear, whether it is open or closed.
  Eigen::Matrix2d transverse_shear_secant;
  PerDamageMode dissipation; ///< energy dissipated in the increment, per mode [J/m³]

  /// True when no stiffness variable d_v is above 0: the secants are the undamaged ones, bit for bit.
  [[nodiscard]] bool undamaged() const { return state.regularised_damage.values == std::array<double, 4>{}; }
};

/// The increment with its algorithmic tangent (for Newton iterations and the finite-difference check).
struct PlyDamageResponse : PlyDamageUpdate {
  /// Algorithmic tangent ∂σ/∂ε in the order (ε11, ε22, γ12, γ23, γ13) [Pa]: the secant plus the
  /// growth of damage with strain. Not symmetric. In the increment where a mode initiates, the
  /// dependence of its onset point on the strain is left out.
  Eigen::Matrix<double, 5, 5> tangent;
};

/// The secant stiffnesses of a ply at a given damage, without evolution (the lagged step).
struct PlySecant {
  Eigen::Matrix3d in_plane;         ///< C(d), order (11, 22, 12) [Pa]
  Eigen::Matrix2d transverse_shear; ///< diag((1 − d_t)G23, (1 − d_t)G13) [Pa]
  /// The loaded modes the strain chose: bit 0 fibre compression, bit 1 matrix compression.
  unsigned modes = 0;
};

/// Thrown when the characteristic length is too large for linear softening: δ_f ≤ δ_0, i.e.
/// L_c ≥ 2G/(σ⁰_eq ε⁰_eq) (= 2GE/σ_0² in a uniaxial state); the law would snap back and dissipate
/// more than G. The remedy is a finer mesh.
class BandLimitError : public std::runtime_error {
public:
  BandLimitError(std::string_view material, DamageMode mode, double characteristic_length,
                 double max_characteristic_length);
  [[nodiscard]] DamageMode mode() const { return mode_; }
  [[nodiscard]] double characteristic_length() const { return characteristic_length_; }
  [[nodiscard]] double max_characteristic_length() const { return max_characteristic_length_; }

private:
  DamageMode mode_;
  double characteristic_length_;
  double max_characteristic_length_;
};

class PlyLaw {
public:
  virtual ~PlyLaw() = default;
  PlyLaw(const PlyLaw&) = delete;
  PlyLaw& operator=(const PlyLaw&) = delete;

  /// The material's data, as the law uses them (strengths possibly lowered to a band limit).
  [[nodiscard]] virtual const Material& material() const = 0;
  /// The in-plane secant of an undamaged point, order (11, 22, 12) [Pa].
  [[nodiscard]] virtual const Eigen::Matrix3d& undamaged_stiffness() const = 0;
  /// The transverse shear secant of an undamaged point, order (23, 13) [Pa].
  [[nodiscard]] virtual const Eigen::Matrix2d& undamaged_transverse_shear() const = 0;
  /// One increment from the committed state `previous` to the total strain `strain`, for a point of
  /// crack band `characteristic_length` [m] over a step `dt` [s]. Throws BandLimitError where the band
  /// is too long for the law to dissipate its toughness.
  [[nodiscard]] virtual PlyDamageUpdate advance(const PlyDamageState& previous, const PlyStrain& strain,
                                                double characteristic_length, double dt) const = 0;
  /// The secants at the damage variables `damage`, the loaded branches chosen by `strain`; no evolution.
  [[nodiscard]] virtual PlySecant secant_at(const PerDamageMode& damage, const PlyStrain& strain) const = 0;
  /// An upper bound of the undamaged ply's onset index on the segment of in-plane stresses (11, 22, 12)
  /// from s0 to s1 [Pa]: where it is below 1, advance() answers every point of the segment elastically.
  [[nodiscard]] virtual double onset_bound(const Eigen::Vector3d& s0, const Eigen::Vector3d& s1) const = 0;
  /// The largest characteristic length [m] for which mode `mode` softens without snap-back in the uniaxial
  /// and pure-shear states that initiate it (2GK/σ_0²); other states are checked at onset (BandLimitError).
  [[nodiscard]] virtual double band_limit(DamageMode mode) const = 0;
  /// The strengths lowered so that a point of characteristic length L_c [m] softens without snap-back at
  /// every onset of the undamaged ply (Maimí et al. 2007, elements beyond the band limit), with a margin
  /// of 0.95 on the energy's square root; strengths below their limit are kept.
  [[nodiscard]] virtual Strengths band_limited_strengths(double characteristic_length) const = 0;

protected:
  PlyLaw() = default;
};

/// The ply law options.law of a material with `options` (PlyDamageLaw or FracturePlaneLaw). Throws
/// std::invalid_argument where the material misses a strength or toughness the law needs.
[[nodiscard]] std::unique_ptr<PlyLaw> make_ply_law(const Material& material, const PlyDamageOptions& options);

} // namespace plyimpact
