#pragma once
// The layered section of a plate whose plies crack (OOFEM's cross-section): what stands between the
// element, which knows only its kinematics, and the ply law, which knows only a point. Given the
// generalized strains (ε0, κ, γ) of an integration point, it integrates the plies through the thickness
// (DP1), asks the law at each ply point, and returns the section's secant stiffnesses:
//
//   ply strain at z_g:  ε_ply = T_ε(θ) (ε0 + z_g κ),  γ_ply = √K T_s(θ) γ   (material axes)
//   law:                C(d), G(d) = secant stiffnesses (ply_damage.hpp, PD3–PD5)
//   section (DP1):      [[A, B], [B, D]](d) = Σ_plies Σ_g w_g t [[1, z_g], [z_g, z_g²]] ⊗ T_εᵀ C(d) T_ε
//                       F(d) = K Σ_plies Σ_g w_g t T_sᵀ G(d) T_s
//
// Two Gauss points through each ply (z_g = z_mid ± t/(2√3), w_g = ½) integrate the undamaged A, B, D
// exactly, so an undamaged section is the elastic one. √K in the ply's transverse shear strain makes the
// ply's shear energy the plate's (F carries the shear correction K), so the energy the law reports
// dissipated is the energy the plate loses.
//
// The section is constant (one per laminate and, where strengths are lowered to a band limit, per element
// length class); the laws' states live with the run (DamageField), 2 per ply at each point, in ply order
// ([ply][g]), and are handed to the section as spans. The laws are PlyLaws (laminate/ply_law.hpp, made by
// make_ply_law): the section knows a law only through that interface. Its screen asks each law for a
// bound of its onset index over each ply group's thickness range (PlyLaw::onset_bound; for Hashin's,
// docs/progressive_damage.md), so that points far below every onset surface never call the law.
#include "plyimpact/fem/section.hpp"
#include "plyimpact/laminate/ply_law.hpp"

#include <Eigen/Core>

#include <memory>
#include <span>
#include <vector>

namespace plyimpact {

/// Generalized strains of a point: ε0 (3), κ (3), γ (yz, xz).
using GeneralizedStrain = Eigen::Matrix<double, 8, 1>;

class LayeredSection {
public:
  /// The plies of `laminate` with the damage law of `materials` (the laminate's materials, or those of an
  /// element length class with lowered strengths). Throws std::invalid_argument, naming the deck keys,
  /// when a material a ply uses misses a strength or toughness the law needs.
  LayeredSection(const Laminate& laminate, const std::vector<Material>& materials,
                 const PlyDamageOptions& options);
  ~LayeredSection();
  LayeredSection(LayeredSection&&) noexcept;
  LayeredSection& operator=(LayeredSection&&) noexcept;
  LayeredSection(const LayeredSection&) = delete;
  LayeredSection& operator=(const LayeredSection&) = delete;

  /// The laws' states at one point: two per ply.
  [[nodiscard]] std::size_t states_per_point() const;
  /// Ply groups (plies of one material and angle): the size of advance()'s scratch.
  [[nodiscard]] std::size_t group_count() const;
  /// The law of material i, or null when no ply uses it.
  [[nodiscard]] const PlyLaw* law(std::size_t material) const { return laws_[material].get(); }

  /// An upper bound of the undamaged plies' onset indices over the thickness at a point with membrane
  /// strain and curvature `strain` (each law's bound over each ply group's range).
  [[nodiscard]] double onset_bound(const Eigen::Matrix<double, 6, 1>& strain) const;

  /// Sets the strain of a point's states to the ply strains of `strain`: where the law's next increment
  /// starts from.
  void set_strains(std::span<PlyDamageState> states, const GeneralizedStrain& strain) const;

  /// One increment of every ply point's law from `committed` to `strain` (trial states into `trial`):
  /// the secant section, with the dissipation of the increment times `point_weight` added to
  /// `dissipation` [J]. `group_bound`: scratch of group_count() entries. Throws BandLimitError.
  struct Increment {
    SectionStiffness secant;
    bool initiated = false; ///< some ply point has initiated some mode (in its trial state)
  };
  [[nodiscard]] Increment advance(std::span<const PlyDamageState> committed, std::span<PlyDamageState> trial,
                                  const GeneralizedStrain& strain, double characteristic_length, double dt,
                                  double point_weight, PerDamageMode& dissipation,
                                  std::span<double> group_bound) const;

  /// The secant section with the damage held at `committed`, the loaded modes (open or closed cracks)
  /// chosen by `strain`; `modes` keeps each ply point's loaded modes, and the result says whether any
  /// changed.
  struct Held {
    SectionStiffness secant;
    bool modes_changed = false;
  };
  [[nodiscard]] Held held(std::span<const PlyDamageState> committed, std::span<unsigned char> modes,
                          const GeneralizedStrain& strain) const;

  struct PlyPoints; ///< one ply at its two points through the thickness
  struct Group;     ///< plies of one material and angle: the screening bound's unit

private:
  std::vector<std::unique_ptr<PlyLaw>> laws_; ///< by material (make_ply_law)
  std::vector<Group> groups_;
  std::vector<PlyPoints> plies_;
  double shear_correction_ = 0.0;
};

} // namespace plyimpact
