#pragma once
// The stacked plate (issue 19, docs/delamination.md "The stacked plate"): the laminate cut at the
// interfaces that may delaminate into sub-laminates, each a Mindlin plate (DiscretePlate) on the same mesh
// and on its own mid-plane, neighbours tied by cohesive interfaces (cohesive_interface.hpp). The
// unknowns are the sub-laminates' free DOFs one after the other (sub-laminate 0, the impacted one,
// first). The internal force is
//
//   f(u) = K_plates u + Σ_interfaces f_coh(u; d),
//
// with K_plates the block-diagonal stiffness of the sub-laminates (each linear: membrane, bending and
// transverse shear of its own plies) and f_coh the interface tractions (DL2), whose damage d is the
// only history of the model.
#include "plyimpact/fem/cohesive_interface.hpp"
#include "plyimpact/fem/discrete_plate.hpp"
#include "plyimpact/laminate/cohesive_law.hpp"
#include "plyimpact/laminate/laminate.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace plyimpact {

/// The transverse shear correction of a sub-laminate: the slice [z1, z2] of a laminate of thickness h
/// (z from its mid-plane) under the laminate's parabolic shear stress τ ∝ 1 − 4z²/h² (the assumption
/// behind the single laminate's 5/6) carries the shear force Q_k = ∫τ and the energy ∫τ²/G; a Mindlin
/// sub-laminate with constant shear and correction κ stores Q_k²/(κ G (z2 − z1)). Equal energies give
///
///   κ = (∫ f)² / ((z2 − z1) ∫ f²),   f = 1 − 4z²/h²,                                   (DL0)
///
/// so that the stack with interfaces that hold has the single laminate's shear compliance: 5/6 for the
/// whole section and for either half (a DCB arm), 0.9934 for a middle quarter, 0.7862 for an outer one
/// (docs/delamination.md, "Consistency"). Scaled by the laminate's own correction over 5/6.
[[nodiscard]] double slice_shear_correction(double z1, double z2, double h);

/// The sub-laminates of `laminate` cut after the plies listed (0-based: a cut after ply k separates
/// ply k from ply k + 1), in increasing order, each with the transverse shear correction
/// `shear_correction`, or (empty) its slice's (DL0) times the laminate's correction over 5/6. Throws
/// std::invalid_argument for a cut outside [0, ply_count − 2] or cuts out of order.
[[nodiscard]] std::vector<Laminate> split_laminate(const Laminate& laminate, const std::vector<int>& cuts,
                                                   std::optional<double> shear_correction = {});

/// The ply (1-based, from the impacted face) that each interface of `cuts` lies under: a cut after 0-based
/// ply k lies under ply k + 1. How results, reports and pictures name the interfaces.
[[nodiscard]] std::vector<int> interfaces_after_ply(const std::vector<int>& cuts);

/// The default cuts: every interface between plies of different orientation (issue 19).
[[nodiscard]] std::vector<int> interfaces_between_orientations(const Laminate& laminate);

/// One penalty stiffness for every interface of `laminate` cut at `cuts` (Turon et al. 2007,
/// turon_penalty_stiffness): at each interface α E3/t with E3 the larger E2 of the two plies that meet
/// there and t the thinner of the two sub-laminates; the largest over the interfaces, so that none
/// adds more than ~1/α of its sub-laminates' through-thickness compliance. Throws
/// std::invalid_argument without cuts.
[[nodiscard]] double turon_penalty_stiffness(const Laminate& laminate, const std::vector<int>& cuts,
                                             double alpha = turon_default_alpha);

/// The values of the interface law that the plies meeting at the interfaces give, where a deck leaves them
/// out (docs/delamination.md, "Values from the plies"): the matrix of the plies on either side is what
/// an interlaminar crack runs through, and the ply data already hold its mode I and mode II toughness
/// and its transverse tensile strength (Maimí et al. 2007 and NASA CompDam_DGD take the intralaminar
/// matrix toughnesses as the interlaminar G_Ic and G_IIc). Each is the smallest over the plies that
/// meet at the cuts, and empty where one of them lacks it.
struct PlyInterfaceValues {
  std::optional<double> G_Ic;            ///< G_mt [J/m²]
  std::optional<double> G_IIc;           ///< G_mc [J/m²]
  std::optional<double> normal_strength; ///< Yt [Pa]
};
/// PlyInterfaceValues of `laminate` cut at `cuts` (0-based, as split_laminate).
[[nodiscard]] PlyInterfaceValues interface_values_from_plies(const Laminate& laminate,
                                                             const std::vector<int>& cuts);
/// The shear strength that makes a one-penalty law dissipate G_c(B) at every mode mixity:
/// S = N √(G_IIc / G_Ic) (Turon, Camanho, Costa & Renart 2010, Compos. Struct. 92:1857).
[[nodiscard]] double turon_shear_strength(double normal_strength, double G_Ic, double G_IIc);
/// The Benzeggagh–Kenane exponent a deck that gives none gets: 1.634, IM7/8552 carbon/epoxy (Camanho,
/// Bessa, Catalanotti, Vogler & Rolfes 2013, Mech. Mater. 59:36–49, as listed in NASA CompDam_DGD,
/// tests/IM7-8552.props, eta_BK). A thermoplastic matrix lies higher (AS4/PEEK 2.284, Camanho, Dávila &
/// de Moura 2003): such a deck gives its own.
inline constexpr double default_bk_exponent = 1.634;

/// The history of a stacked plate: the damage of every interface point.
struct StackedPlateState {
  std::vector<std::vector<CohesiveState>> interfaces; ///< [interface][point]
};

/// Internal force and tangent at one displacement, with the trial states they came from.
struct StackedPlateEvaluation {
  Eigen::VectorXd force;
  SparseMatrix tangent; ///< unsymmetric where an interface softens under mixed mode
  StackedPlateState trial;
  double dissipated = 0.0; ///< energy dissipated from the committed to the trial states [J]
};

/// How the laminate is stacked and tied.
struct StackSettings {
  std::vector<int> cuts;        ///< split_laminate's cuts
  CohesiveParameters interface; ///< the law of every interface
  CohesiveQuadrature rule = CohesiveQuadrature::nodal;
  std::optional<double> shear_correction = std::nullopt; ///< of every sub-laminate; empty: each slice's (DL0)
  /// Newton's choice of tangent at the law's kink (CohesiveLaw::update): the loading tangent within
  /// this relative band below the softening envelope.
  double loading_band = 1e-2;
  /// An initial delamination: every interface fully delaminated (d = 1) at the start within this radius
  /// of (seed_x, seed_y) [m]; 0: none (the fracture-mechanics checks, docs/delamination_threshold.md).
  double seed_radius = 0.0;
  double seed_x = 0.0, seed_y = 0.0;
  friend bool operator==(const StackSettings&, const StackSettings&) = default;
};

class StackedPlate {
public:
  /// The sub-laminates of `laminate` cut at `stack.cuts`, on `mesh`, each with the boundary conditions
  /// `bc_of(k)` of sub-laminate k (0 the impacted one).
  StackedPlate(const Mesh& mesh, const Laminate& laminate, const StackSettings& stack,
               Discretization discretization,
               const std::function<BoundaryConditions(int sublaminate)>& bc_of);

  [[nodiscard]] int size() const { return size_; }
  [[nodiscard]] int sublaminate_count() const { return static_cast<int>(plates_.size()); }
  [[nodiscard]] int interface_count() const { return static_cast<int>(interfaces_.size()); }
  [[nodiscard]] const DiscretePlate& sublaminate(int k) const {
    return *plates_[static_cast<std::size_t>(k)];
  }
  /// First stacked equation of sub-laminate k.
  [[nodiscard]] int offset(int k) const { return offset_[static_cast<std::size_t>(k)]; }
  [[nodiscard]] const CohesiveInterface& interface(int i) const {
    return *interfaces_[static_cast<std::size_t>(i)];
  }
  /// Block-diagonal stiffness of the sub-laminates.
  [[nodiscard]] const SparseMatrix& plate_stiffness() const { return K_plates_; }
  /// Block-diagonal mass of the sub-laminates (each the discretization's mass matrix about its own
  /// mid-plane: their sum carries the whole laminate's translational and rotary inertia).
  [[nodiscard]] SparseMatrix mass() const;

  /// No damage anywhere.
  [[nodiscard]] StackedPlateState virgin_state() const;
  /// The state a run starts from: no damage but the seed of the settings (StackSettings::seed_radius).
  [[nodiscard]] StackedPlateState initial_state() const;
  /// Marks as cracked (d = 1) the points of interface i where `cracked(x, y)` holds (an initial crack).
  void crack(StackedPlateState& state, int i,
             const std::function<bool(const Eigen::Vector2d&)>& cracked) const;

  /// f(u), its tangent and the trial states, from the committed states (their damage held in the forces of
  /// the held modes, CohesiveDamage).
  [[nodiscard]] StackedPlateEvaluation evaluate(const Eigen::VectorXd& u, const StackedPlateState& committed,
                                                CohesiveDamage damage = CohesiveDamage::evolve) const;
  /// f(u) and the trial states without the tangent (left empty): the iterations of a step that keep
  /// their factor.
  [[nodiscard]] StackedPlateEvaluation internal_force(const Eigen::VectorXd& u,
                                                      const StackedPlateState& committed,
                                                      CohesiveDamage damage = CohesiveDamage::evolve) const;
  /// Elastic energy ½ uᵀ K_plates u + the interfaces' stored energy [J].
  [[nodiscard]] double stored_energy(const Eigen::VectorXd& u, const StackedPlateState& state) const;
  /// The same with `scratch` for K_plates u: the numbers of stored_energy(u, state) without a new vector.
  [[nodiscard]] double stored_energy(const Eigen::VectorXd& u, const StackedPlateState& state,
                                     Eigen::VectorXd& scratch) const;
  /// The interfaces' stored energy alone [J].
  [[nodiscard]] double interface_energy(const Eigen::VectorXd& u, const StackedPlateState& state) const;
  /// The same with the buffers of `work` (the interfaces one after another, each on threads).
  [[nodiscard]] double interface_energy(const Eigen::VectorXd& u, const StackedPlateState& state,
                                        CohesiveWorkspace& work) const;
  /// The interfaces' forces at u added to `force`, their trial states from the committed ones into
  /// `trial` (its vectors reused), and the energy dissipated reaching them returned [J]: the part of
  /// internal_force() beyond K_plates u, for a caller that holds K_plates u (the explicit step).
  /// `work` holds the buffers of the interfaces' evaluation on threads (one interface after another).
  double add_interface_forces(const Eigen::VectorXd& u, const StackedPlateState& committed,
                              Eigen::VectorXd& force, StackedPlateState& trial, CohesiveDamage damage,
                              CohesiveWorkspace& work) const;

  /// The stacked index of DOF `dof` (0..4 = u, v, w, θx, θy) of node n in sub-laminate k (−1: restrained).
  [[nodiscard]] int equation(int k, int node, int dof) const;

private:
  /// f(u) and the trial states; the tangent's triplets into `tangent` unless it is null.
  [[nodiscard]] StackedPlateEvaluation assemble(const Eigen::VectorXd& u, const StackedPlateState& committed,
                                                std::vector<Eigen::Triplet<double>>* tangent,
                                                CohesiveDamage damage) const;
  /// The interfaces' forces added to `force`, their trial states into `trial`, their tangents' triplets
  /// into `tangent` unless it is null; returns the energy dissipated reaching the trial states [J].
  double add_interfaces(const Eigen::VectorXd& u, const StackedPlateState& committed, Eigen::VectorXd& force,
                        StackedPlateState& trial, std::vector<Eigen::Triplet<double>>* tangent,
                        CohesiveDamage damage, CohesiveWorkspace& work) const;
  /// The matrices `of` the sub-laminates placed on the diagonal of the stacked numbering.
  [[nodiscard]] SparseMatrix
  block_diagonal(const std::function<SparseMatrix(const DiscretePlate&)>& of) const;

  std::vector<std::unique_ptr<DiscretePlate>> plates_;
  std::vector<int> offset_;
  int size_ = 0;
  std::vector<std::unique_ptr<CohesiveInterface>> interfaces_;
  SparseMatrix K_plates_;
  double seed_radius_ = 0.0;          ///< StackSettings::seed_radius
  Eigen::Vector2d seed_centre_{0, 0}; ///< (seed_x, seed_y)
};

/// The interfaces' areas and dissipation after a step of a run on the stacked plate (issue 19).
struct DelaminationAreas {
  std::vector<double> delaminated_area; ///< per interface: points fully cracked (d = 1) [m²]
  double projected_area = 0.0;          ///< union over the interfaces of the delaminated points [m²]
  double dissipated = 0.0;              ///< energy dissipated by the interfaces [J]
};

/// The interfaces at the end of a run on the stacked plate (issue 19, docs/delamination.md).
struct DelaminationResult {
  std::vector<int> interface_after_ply;  ///< each interface lies after this ply (1-based, from the top)
  std::vector<double> angle_below_deg;   ///< per interface: the fibre angle of the ply below it [°]
  std::vector<double> delaminated_area;  ///< per interface: points fully cracked (d = 1) [m²]
  std::vector<double> process_zone_area; ///< per interface: points softening (0 < d < 1) [m²]
  double projected_area = 0.0;           ///< union over the interfaces of the delaminated points [m²]
  double dissipated = 0.0;               ///< energy dissipated by the interfaces [J]
  /// per interface and element: the largest damage of its points (0 intact, 1 cracked)
  std::vector<std::vector<double>> element_damage;
  /// per interface and point (index e · points per element + q): the damage
  std::vector<std::vector<double>> point_damage;
  /// per point: the part of its element it stands for (CohesiveInterface::point_cell) [m], and its area [m²]
  std::vector<std::array<Eigen::Vector2d, 4>> point_cells;
  std::vector<double> point_area;
  double cohesive_zone_length = 0.0;    ///< E2 G_c / strength² of the shorter mode (Hillerborg) [m]
  double interface_point_spacing = 0.0; ///< the interface points' spacing in the largest element [m]
};

} // namespace plyimpact
