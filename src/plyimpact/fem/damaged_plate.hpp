#pragma once
// The plate whose plies crack (issue 18): the MITC9 plate of DiscretePlate with a damage state per element,
// 3×3 Gauss point, ply and through-thickness point. OOFEM's picture: the element asks its cross-section
// for stresses at an integration point (fem/layered_section.hpp); the section asks every ply's law.
//
//   generalized strains (ε0, κ, γ) = S_p uₑ at Gauss point p (MITC9 strains, plate_element.hpp)
//   section:            [[A, B], [B, D]](d), F(d) = LayeredSection's secant at those strains (DP1)
//   internal force:     f = Σₑ Σ_p w_p S_pᵀ [[A, B], [B, D]](d) (ε0, κ) ⊕ F(d) γ = K_s(d) u  (secant)
//
// Kinematics × section: with von Kármán kinematics (SPEC §8) the generalized strains at a point gain the
// membrane terms of the deflection's slopes, e = S_p uₑ + (½ w,x², ½ w,y², w,x w,y, 0, …), the section is
// the same layered damaging one, and the force of the damaged sections' difference is taken with the
// strain's derivative E_p = ∂e/∂uₑ: f = f_vK(u) + Σ_p w_p E_pᵀ (C(d) − C0) e_p, where f_vK is the elastic
// von Kármán plate (NonlinearPlate). An undamaged plate is the von Kármán plate bit for bit.
//
// The characteristic length of an element's points (crack band) is √(element area) (Abaqus for shells):
// a band of damaged points one element wide dissipates G per unit crack area.
//
// Cost: only elements that carry damage, or whose strains have come near a Hashin surface ("active"
// elements), evaluate the law; the others are the elastic element. Each accepted step screens the
// inactive elements with a bound of the Hashin indices over each ply group's thickness range
// (docs/progressive_damage.md); an element found beyond the surface asks for the step to be solved again.
#include "plyimpact/fem/discrete_plate.hpp"
#include "plyimpact/fem/layered_section.hpp"
#include "plyimpact/fem/nonlinear_plate.hpp"
#include "plyimpact/laminate/ply_damage.hpp"

#include <Eigen/Core>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace plyimpact {

/// The plate's kinematics under a section whose plies crack.
enum class Kinematics {
  linear,     ///< small deflections: the strains are linear in u
  von_karman, ///< moderate deflections (SPEC §8): the membrane strains gain ½ w,x², ½ w,y², w,x w,y
};

/// Settings of the progressive damage of the plies.
struct ProgressiveDamageSettings {
  PlyDamageOptions law;         ///< α, viscosity η
  double area_threshold = 0.5;  ///< a ply point counts as damaged when a damage variable reaches this
  double screen_fraction = 0.6; ///< elements whose Hashin bound exceeds this fraction of 1 are active
  /// Elements larger than a mode's band limit: false (default) = BandLimitError when the mode initiates
  /// there; true = the strengths of those elements are lowered to their band limit (Maimí et al. 2007,
  /// band_limited_strengths in ply_damage.hpp) and strength_reduction_warning() says by how much.
  bool reduce_strengths_above_band_limit = false;
  friend bool operator==(const ProgressiveDamageSettings&, const ProgressiveDamageSettings&) = default;
};

/// Per element and ply: the largest damage variable of each mode over the element's points.
struct ElementPlyDamage {
  int element = 0;
  int ply = 0; ///< 0-based
  PerDamageMode damage;
};

/// A strength a ply law uses below the deck's value, where an element is larger than a band limit and the
/// deck lowers strengths ([damage] oversize = "reduce-strength"; band_limited_strengths in ply_law.hpp).
struct LoweredStrength {
  std::string material;                             ///< the material's name
  std::string strength;                             ///< "Xt", "Xc", "Yt", "Yc" or "S12"
  double deck = 0.0;                                ///< the deck's value [Pa]
  double used = 0.0;                                ///< the value the law uses there [Pa]
  int element = -1;                                 ///< the first element (in element order) that uses it
  Eigen::Vector2d centre = Eigen::Vector2d::Zero(); ///< that element's centre [m]
  /// 1 − used/deck.
  [[nodiscard]] double reduction() const { return 1.0 - used / deck; }
};

/// `into` becomes `candidate` where the candidate lowers its strength more (of equal ones, `into` stays):
/// how a largest reduction is kept over elements and over sub-laminates.
inline void keep_larger_reduction(std::optional<LoweredStrength>& into,
                                  const std::optional<LoweredStrength>& candidate) {
  if (candidate && (!into || candidate->reduction() > into->reduction())) into = candidate;
}

/// How far a run's laws lowered the deck's strengths (issue 79: the largest reduction, and where).
struct StrengthReduction {
  int elements = 0;                       ///< elements with some strength lowered
  std::optional<LoweredStrength> largest; ///< the largest reduction of any element
  /// The largest reduction of an element whose plies damaged (some damage variable above 0 at some point):
  /// where a lowered strength moved the answer, as opposed to elements that stayed elastic.
  std::optional<LoweredStrength> largest_where_damaged;
};

/// What the law returned at every point of the active elements, for one displacement (the trial state of
/// a step): kept until the step is accepted.
class DamageField;

/// The shared, constant part: element operators, laws, undamaged matrices. Built once per case.
class DamagedPlate {
public:
  /// Throws std::invalid_argument when the model is not MITC9, a laminate is not `exact`, or a material
  /// misses a strength or toughness the law needs (the message names them and the deck keys).
  DamagedPlate(const DiscretePlate& model, ProgressiveDamageSettings settings,
               Kinematics kinematics = Kinematics::linear);
  ~DamagedPlate();
  DamagedPlate(const DamagedPlate&) = delete;
  DamagedPlate& operator=(const DamagedPlate&) = delete;

  [[nodiscard]] const DiscretePlate& model() const { return model_; }
  [[nodiscard]] const ProgressiveDamageSettings& settings() const { return settings_; }
  [[nodiscard]] Kinematics kinematics() const {
    return von_karman_ ? Kinematics::von_karman : Kinematics::linear;
  }
  [[nodiscard]] int size() const { return model_.size(); }
  /// The undamaged stiffness K0 over the free DOFs (DiscretePlate::stiffness()).
  [[nodiscard]] const SparseMatrix& undamaged_stiffness() const { return K0_; }
  /// The characteristic length of element e's points, √(area) [m].
  [[nodiscard]] double characteristic_length(int e) const { return length_[static_cast<std::size_t>(e)]; }
  /// Area of element e [m²].
  [[nodiscard]] double element_area(int e) const { return area_[static_cast<std::size_t>(e)]; }

  /// With reduce_strengths_above_band_limit: how many elements have lowered strengths and the largest
  /// reduction (material, strength, deck value → used value), for the run's warnings; nullopt when none.
  [[nodiscard]] std::optional<std::string> strength_reduction_warning() const;
  /// The lowered strengths of the elements, and among them of those that `field` has damaged.
  [[nodiscard]] StrengthReduction strength_reduction(const DamageField& field) const;

  /// A virgin damage field for one run.
  [[nodiscard]] DamageField virgin_field() const;

  /// Trial evaluation at u from the committed state of `field` (dt for the viscous regularisation):
  /// returns f_int = K_s(d(u)) u and keeps the trial responses in `field`. Throws BandLimitError (with
  /// the element) when a mode initiates at a point whose characteristic length is beyond its band limit.
  [[nodiscard]] Eigen::VectorXd internal_force(const Eigen::VectorXd& u, double dt, DamageField& field) const;
  /// internal_force() into `f` (sized once by the caller): the same numbers without a new vector.
  void internal_force_into(const Eigen::VectorXd& u, double dt, DamageField& field, Eigen::VectorXd& f) const;
  /// K_s with the trial damage of the last internal_force() (K0 where no element is active).
  [[nodiscard]] SparseMatrix secant_stiffness(const DamageField& field) const;
  /// The matrix of an iteration at u: secant_stiffness() with linear kinematics; with von Kármán's,
  /// the elastic plate's tangent K_T(u) plus the damaged sections' difference taken with E_p at u, and the
  /// initial-stress term of their membrane resultants' difference.
  [[nodiscard]] SparseMatrix iteration_matrix(const Eigen::VectorXd& u, const DamageField& field) const;
  /// Activates the inactive elements that have reached a Hashin surface at u. True when there were any:
  /// the trial did not evaluate them, and the step must be iterated again.
  [[nodiscard]] bool activate_reached(const Eigen::VectorXd& u, DamageField& field) const;
  /// The force with the damage held at the committed d_n, the loaded modes (open or closed
  /// cracks) chosen by the strain at u, K_s(d_n, u) u; the sections are kept, so secant_stiffness() is
  /// the matrix of the last call. No law update.
  [[nodiscard]] Eigen::VectorXd frozen_internal_force(const Eigen::VectorXd& u, DamageField& field) const;
  /// frozen_internal_force() into `f` (sized once by the caller).
  void frozen_internal_force_into(const Eigen::VectorXd& u, DamageField& field, Eigen::VectorXd& f) const;
  /// Accepts the trial state of the last internal_force() at u (f_int its result): commits it, adds its
  /// dissipation, updates the areas and the stored energy, and activates the elements near a surface.
  void commit(const Eigen::VectorXd& u, const Eigen::VectorXd& f_int, DamageField& field) const;

  /// Activates the elements that the screen finds near a Hashin surface at u (without committing).
  /// Returns the number of elements newly activated.
  int screen(const Eigen::VectorXd& u, DamageField& field) const;

  // Implementation type (defined in damaged_plate.cpp).
  struct ElementOperators;

private:
  void build_element_operators();
  /// Elements whose laws coincide: one class per distinct characteristic length when strengths are
  /// lowered to the band limit, otherwise one class for all.
  void build_length_classes();
  [[nodiscard]] const ElementOperators& operators_of(int e) const;
  /// The layered section of element e (its laminate, in its length class).
  [[nodiscard]] const LayeredSection& layered_section(int e) const;
  /// The largest strength reduction of each [class][section]'s laws against the deck (nullopt: none).
  void build_lowered_strengths();
  /// The largest lowered strength of element e's section, with the element and its centre; nullopt: none.
  [[nodiscard]] std::optional<LoweredStrength> lowered_strength(int e) const;
  /// The elements with lowered strengths and the largest reduction (largest_where_damaged left empty).
  [[nodiscard]] StrengthReduction lowered_elements() const;
  /// Generalized strains (ε0, κ, γ) at the 3×3 Gauss points of an element.
  using PointStrains = std::array<GeneralizedStrain, 9>;
  /// The generalized strains at point p of an element with DOFs uₑ (with the kinematics' terms).
  [[nodiscard]] Eigen::Matrix<double, 8, 1> point_strain(const ElementOperators& ops, std::size_t p,
                                                         const ElementVector& ue) const;
  /// Its rows ε0 and κ alone (the shear rows zero): what the Hashin screen reads.
  [[nodiscard]] Eigen::Matrix<double, 8, 1>
  membrane_bending_strain(const ElementOperators& ops, std::size_t p, const ElementVector& ue) const;
  /// The sections of active element `slot` at u with the committed damage (held damage); returns the
  /// strains of its damaged points (the others are left unset: their section is the undamaged one).
  PointStrains frozen_sections(DamageField& field, std::size_t slot, const Eigen::VectorXd& u) const;
  /// E_pᵀ w (C(d) − C0) ε_p (E_p = S_p with linear kinematics) summed over element `slot`'s damaged points
  /// (its sections as they stand) into its slot of the field's element forces.
  void section_force(DamageField& field, std::size_t slot, const PointStrains& strains,
                     const Eigen::VectorXd& u) const;
  /// f = the undamaged plate's force at u plus every active element's section force, the elements'
  /// `sections(slot, group_bound)` (which sets their sections and returns their strains) evaluated on the
  /// run's threads and added in slot order (element_loop.hpp).
  template <class Sections>
  void assemble_force(const Eigen::VectorXd& u, DamageField& field, Eigen::VectorXd& f,
                      const Sections& sections) const;
  /// Adds to K, in K0's pattern, the damaged points' Σ E_pᵀ w (C(d) − C0) E_p of every active element
  /// (E_p = S_p where `u` is null; else von Kármán's at u with the initial-stress term of the difference's
  /// membrane resultants, 2.103).
  void add_section_differences(SparseMatrix& K, const DamageField& field, const Eigen::VectorXd* u) const;
  /// The force of the undamaged plate at u: K0 u, or the von Kármán plate's f_int(u) (its element loop's
  /// places in `field`).
  void elastic_force(const Eigen::VectorXd& u, Eigen::VectorXd& f, DamageField& field) const;
  /// The law at every point of active element e at u (trial states and secant sections into `field`);
  /// returns the points' strains, from which internal_force() forms the element force.
  /// `group_bound`: scratch of the calling thread (the point's bound of each ply group, −1: not computed).
  PointStrains evaluate_element(int e, const Eigen::VectorXd& u, double dt, DamageField& field,
                                std::vector<double>& group_bound) const;
  /// The largest onset_bound over element e's points at u.
  [[nodiscard]] double element_bound(int e, const Eigen::VectorXd& u) const;
  void activate(int e, DamageField& field) const;
  /// field.bound_ (element_bound) of every inactive element at u, on the run's threads.
  void inactive_bounds(const Eigen::VectorXd& u, DamageField& field) const;
  /// Activates, in element order, the inactive elements whose field.bound_ is at least `threshold`;
  /// returns how many.
  int activate_bounded_above(double threshold, DamageField& field) const;

  const DiscretePlate& model_;
  ProgressiveDamageSettings settings_;
  std::unique_ptr<NonlinearPlate> von_karman_; ///< the elastic von Kármán plate; null: linear
  SparseMatrix K0_;
  /// K0 stored by rows for K0 u: each entry one sequential sum over its row, the bits of the column-wise
  /// product without its scatter
  Eigen::SparseMatrix<double, Eigen::RowMajor> K0_by_rows_;
  std::vector<double> length_, area_;
  std::vector<int> class_of_element_;                 ///< length class of each element
  std::vector<double> class_length_;                  ///< L_c of each class (0: the deck's strengths)
  std::vector<std::vector<LayeredSection>> sections_; ///< [class][section]
  std::vector<std::vector<std::optional<LoweredStrength>>> lowered_; ///< [class][section] (element unset)
  std::vector<ElementOperators> operators_;                          ///< per shape class
  std::vector<ElementSlots> slot_; ///< (i, j) of Kₑ → index in K0_ values
};

/// What a run reports of its plies' damage at the last commit: the energies, the areas and the maps. One
/// plate's DamageField, or the sub-laminates' fields of a stacked plate seen as one laminate
/// (StackedDamageField, fem/stacked_damage.hpp).
class PlyDamageView {
public:
  /// Mode, element and ply of the first damage (d > 0), once it has appeared.
  struct FirstDamage {
    DamageMode mode;
    int element = 0, ply = 0;
  };
  /// Per mode, the first damage of that mode (d > 0), once it has appeared.
  using FirstDamageByMode = ByDamageMode<std::optional<FirstDamage>>;

  virtual ~PlyDamageView() = default;
  /// Energy dissipated by damage up to the last commit, per mode [J].
  [[nodiscard]] virtual const PerDamageMode& dissipated() const = 0;
  /// Damaged area of each ply at the last commit (points with a damage variable ≥ area_threshold) [m²].
  [[nodiscard]] virtual const std::vector<double>& ply_damage_area() const = 0;
  /// Projected damaged area (union over the plies, what a C-scan of ply damage shows) [m²].
  [[nodiscard]] virtual double projected_damage_area() const = 0;
  /// Number of elements that evaluate the law.
  [[nodiscard]] virtual int active_elements() const = 0;
  /// Per element and ply, the largest damage of each mode (committed), for maps and ParaView.
  [[nodiscard]] virtual std::vector<ElementPlyDamage> element_ply_damage() const = 0;
  [[nodiscard]] virtual const std::optional<FirstDamage>& first_damage() const = 0;
  [[nodiscard]] virtual const FirstDamageByMode& first_damage_by_mode() const = 0;
  /// The strengths the laws lowered below the deck's, and where (none unless [damage] oversize =
  /// "reduce-strength").
  [[nodiscard]] virtual StrengthReduction strength_reduction() const = 0;

protected:
  PlyDamageView() = default;
  PlyDamageView(const PlyDamageView&) = default;
  PlyDamageView(PlyDamageView&&) = default;
  PlyDamageView& operator=(const PlyDamageView&) = default;
  PlyDamageView& operator=(PlyDamageView&&) = default;
};

/// An integration point that was damaged at the last commit (some ply's damage variable ≥ area_threshold).
struct DamagedPoint {
  int element = 0;
  int point = 0;     ///< 0..8, the element's 3×3 Gauss points
  double area = 0.0; ///< the point's share of the element's area [m²]
};

/// The damage state of one run: committed per-point states of the active elements, their trial
/// responses, and the energies and areas that follow.
class DamageField final : public PlyDamageView {
public:
  [[nodiscard]] const PerDamageMode& dissipated() const override { return dissipated_; }
  /// Elastic energy stored in the plate at the last commit, ½ uᵀ K_s(d) u [J].
  [[nodiscard]] double stored_energy() const { return stored_energy_; }
  [[nodiscard]] const std::vector<double>& ply_damage_area() const override { return ply_area_; }
  [[nodiscard]] double projected_damage_area() const override { return projected_area_; }
  /// The points whose union is projected_damage_area().
  [[nodiscard]] const std::vector<DamagedPoint>& damaged_points() const { return damaged_points_; }
  /// Growth of the damage since the last mark_factorized(): the sum over the accepted steps of the
  /// largest increment of any damage variable in the step (an upper bound of the largest growth).
  [[nodiscard]] double growth_since_factorization() const { return growth_; }
  void mark_factorized() { growth_ = 0.0; }
  /// True when a held evaluation (frozen_internal_force) has changed the loaded modes (a crack opened or
  /// closed) of some point since the last call of this function.
  [[nodiscard]] bool take_modes_changed() { return std::exchange(modes_changed_, false); }
  [[nodiscard]] int active_elements() const override { return static_cast<int>(active_.size()); }
  [[nodiscard]] std::vector<ElementPlyDamage> element_ply_damage() const override;
  [[nodiscard]] const std::optional<FirstDamage>& first_damage() const override { return first_; }
  [[nodiscard]] const FirstDamageByMode& first_damage_by_mode() const override { return first_by_mode_; }
  [[nodiscard]] StrengthReduction strength_reduction() const override;

private:
  friend class DamagedPlate;
  const DamagedPlate* plate_ = nullptr; ///< the plate whose virgin_field() this was
  struct ActiveElement {
    int element = 0;
    std::vector<PlyDamageState> committed; ///< [point][ply][g]
    std::vector<PlyDamageState> trial;
    std::vector<unsigned char> modes;         ///< loaded modes of the last held evaluation (PlySecant::modes)
    PerDamageMode trial_dissipation;          ///< of the trial increment [J]
    std::array<SectionStiffness, 9> sections; ///< trial secant sections at the 9 points
    bool evaluated = false;                   ///< trial responses are those of the last internal_force()
    bool has_sections = false;                ///< `sections` hold the secant of some evaluation
    /// Point p has never initiated any mode in any ply (committed): while its Hashin bound stays below
    /// 1 its section is the undamaged one and the law is not called.
    std::array<bool, 9> pristine{true, true, true, true, true, true, true, true, true};
    std::array<bool, 9> pristine_trial{true, true, true, true, true, true, true, true, true};
    std::array<bool, 9> trial_touched{}; ///< the trial states of point p differ from the committed ones
    bool modes_changed = false;          ///< the last held evaluation changed the loaded modes
  };
  std::vector<ActiveElement> active_;
  std::vector<int> slot_of_element_; ///< index into active_, −1 when inactive
  std::vector<double> bound_;        ///< Hashin bound of each inactive element at the last screen
  /// per thread of the element loop: the point's bound of each ply group, while one point is evaluated
  std::vector<std::vector<double>> group_bounds_;
  std::size_t groups_ = 0;                    ///< the most ply groups of a section
  std::vector<ElementVector> element_forces_; ///< per active element: its section force (section_force)
  std::vector<char> force_changed_;           ///< … and whether it has one (a damaged point)
  std::vector<ElementVector> elastic_forces_; ///< the von Kármán element loop's places (elastic_force)
  Eigen::VectorXd u_committed_;               ///< displacement of the last commit
  bool bounds_current_ = false;               ///< bound_ was computed at the u being committed
  PerDamageMode dissipated_;
  double stored_energy_ = 0.0;
  std::vector<double> ply_area_;
  double projected_area_ = 0.0;
  std::vector<DamagedPoint> damaged_points_;
  double growth_ = 0.0;
  bool modes_changed_ = false;
  std::optional<FirstDamage> first_;
  FirstDamageByMode first_by_mode_;
};

} // namespace plyimpact
