#pragma once
// Damage initiation during an impact (SPEC §6–7; thesis 3.5.3, 4.3–4.6): every evaluated step, the
// selected criteria at the stress points of every element (the 3×3 Gauss points of
// PlateElement::stress_points), for every ply (and interface for delamination) of the element's
// laminate. A point that has failed in a criterion stays failed. Plies are numbered from the impacted
// face in every region.
#include "plyimpact/analysis/fields/stress_recovery.hpp"
#include "plyimpact/analysis/impact/impact_observer.hpp"
#include "plyimpact/fem/discrete_plate.hpp"
#include "plyimpact/laminate/criterion_gauge.hpp"
#include "plyimpact/laminate/failure_criteria.hpp"

#include <array>
#include <vector>

namespace plyimpact {

/// One failed Gauss point (the columns of Tables 4.4–4.7). Numbers are 1-based as in the thesis;
/// ply = 0 for an interface criterion, interface = 0 for a ply criterion.
struct DamageOnset {
  Criterion criterion = Criterion::choi_chang_matrix;
  FailureMode mode = FailureMode::none;
  int ply = 0, interface = 0;
  int element = 0, ipgs = 0, jpgs = 0; ///< IPGS along x (ξ), JPGS along y (η), 1..3
  double x = 0.0, y = 0.0;             ///< Gauss point position [m]
  double time = 0.0, force = 0.0;      ///< [s], contact force [N]
  double sigma22 = 0.0, tau23 = 0.0;   ///< ply-averaged σ̄22, τ̄23 of the (upper) ply [Pa]
  double index = 0.0;                  ///< failure index at onset
};

/// Failed area of one layer under one criterion after time t (step function, recorded on change).
struct DamageAreaSample {
  double time = 0.0;
  Criterion criterion = Criterion::choi_chang_matrix;
  int ply = 0, interface = 0;
  double area = 0.0; ///< Σ tributary areas w_i w_j |J| of the failed Gauss points [m²]
};

struct DamageOptions {
  int every = 1; ///< evaluate every k-th step
  CriterionOptions criterion_options;
  /// Skip the points that provably cannot fail or raise a peak index (the same onsets and peaks);
  /// false: every point at every observation (the reference the tests compare the skipping with).
  bool skip_proven_points = true;
};

class DamageTracker final : public ImpactObserver {
public:
  DamageTracker(const DiscretePlate& model, std::vector<Criterion> criteria, DamageOptions options = {});

  /// Evaluates the criteria for the plate state u (free DOFs) at time t.
  void observe(long step, double t, double force, const Eigen::VectorXd& u);
  void on_step(const StepView& v) override {
    if (v.step % options_.every == 0) observe(v.step, v.t, v.force, v.plate_displacement());
  }

  /// Every failed Gauss point in order of onset.
  [[nodiscard]] const std::vector<DamageOnset>& onsets() const { return onsets_; }
  /// The first onset of each (criterion, mode, ply or interface), in order of onset.
  [[nodiscard]] std::vector<DamageOnset> first_onsets() const;
  [[nodiscard]] const std::vector<DamageAreaSample>& area_history() const { return areas_; }
  /// Largest failure index reached so far by `criterion` anywhere (0 if never evaluated).
  [[nodiscard]] double peak_index(Criterion criterion) const;
  [[nodiscard]] bool any_failure() const { return !onsets_.empty(); }
  [[nodiscard]] const std::vector<Criterion>& criteria() const { return criteria_; }
  /// How many times a stress point had its plies evaluated (the rest were proven safe and skipped).
  [[nodiscard]] long evaluated_points() const { return evaluated_points_; }
  /// Stress points × observations: what evaluating every point every time would have cost.
  [[nodiscard]] long observed_points() const { return observed_points_; }

private:
  struct GaussPoint {
    int element, i, j;
    double x, y, area;
  };
  /// Per laminate: Q̄, the height z and the rotation folded into (σ11, σ22, τ12, τ13, τ23) from
  /// (ε0, κ, γ), per ply (rows 5k..5k+4), at the ply mid-plane (= ply average) and at its faces.
  struct SectionOperators {
    const Laminate* laminate = nullptr;
    std::size_t plies = 0;
    Eigen::MatrixXd A_average, A_top, A_bottom;
    std::vector<Eigen::Matrix<double, 5, 5>> average_bending, top_bending, bottom_bending; ///< (κ, γ) columns
    std::vector<Eigen::Matrix<double, 3, 5>> transverse_bending; ///< rows σ22, τ13, τ23 of average_bending
  };
  [[nodiscard]] static SectionOperators section_operators(const Laminate& lam);
  void evaluate_point(std::size_t g, double t, double force);
  [[nodiscard]] static Eigen::Matrix<double, 5, 1> layer_bound(const SectionOperators& sec, std::size_t k,
                                                               bool interface);
  [[nodiscard]] std::size_t slot(std::size_t c, std::size_t layer, std::size_t g) const {
    return (c * layers_ + layer) * points_.size() + g;
  }
  [[nodiscard]] const SectionOperators& section_at(std::size_t g) const {
    return sections_[static_cast<std::size_t>(model_.section_index(points_[g].element))];
  }
  [[nodiscard]] const StrainOperator& strain_operator(int e, int l) const {
    return B_[gauss3x3.size() * static_cast<std::size_t>(model_.mesh().shape_class(e)) +
              static_cast<std::size_t>(l)];
  }
  void gather_all(const Eigen::VectorXd& u);
  void observe_bending(double t, double force);
  void observe_general(double t, double force);
  void observe_skipping_bending(const Eigen::VectorXd& u, double t, double force);
  void point_stresses_bending(std::size_t g, const SectionOperators& sec,
                              const Eigen::Matrix<double, 5, 1>& eb);
  void build_gauges();
  [[nodiscard]] double headroom(std::size_t slot, double limit) const;
  [[nodiscard]] double gauge_margin(std::size_t c, std::size_t g,
                                    const Eigen::Matrix<double, 5, 1>& eb) const;
  void advance_paths(const Eigen::VectorXd& u);
  [[nodiscard]] Eigen::Matrix<double, 27, 1> bending_dofs(const Eigen::VectorXd& u, int e) const;
  [[nodiscard]] bool still_proven(std::size_t g, std::size_t e, std::size_t shape) const;
  [[nodiscard]] bool proven_now(std::size_t g) const;
  void refresh_proof_exactly(std::size_t g, std::size_t e, const Eigen::Matrix<double, 5, 1>& strains);
  void keep_proof(std::size_t g, std::size_t e, const Eigen::Matrix<double, 5, 1>& strains);
  [[nodiscard]] bool proven_again(std::size_t g, std::size_t e, const Eigen::Matrix<double, 5, 1>& strains);
  void refresh_proof(std::size_t g, std::size_t e, const Eigen::Matrix<double, 5, 1>& strains);

  const DiscretePlate& model_;
  std::vector<Criterion> criteria_;
  DamageOptions options_;
  bool track_cracks_for_delamination_ = false; ///< matrix cracking gates delamination (2.43)
  std::size_t layers_ = 0;                     ///< most plies of any laminate (interfaces use 0..N−2)
  std::vector<GaussPoint> points_;
  std::vector<SectionOperators> sections_; ///< per laminate of the model
  std::vector<StrainOperator> B_;          ///< (ε0, κ, γ) from element DOFs per (shape class, local point)
  bool uniform_ = false;                   ///< one element shape and one laminate: batched products
  bool needs_faces_ = false;
  Eigen::MatrixXd U_, local_strains_, E_, S_average_, S_top_, S_bottom_; ///< work arrays, sized once
  std::vector<Eigen::Matrix<double, 5, 27>> B_bending_; ///< (κ, γ) rows, (w, θx, θy) columns of B_
  std::vector<int> inplane_equations_;
  std::size_t bound_slots_ = 0; ///< the criteria, and the matrix cracks when they gate delamination
  /// Per slot, β: its Choi–Chang indices, or the norms of its criterion's gauge, grow by at most
  /// β·|Δ(κ, γ)|; for Choi–Chang also index ≤ β·|(κ, γ)|, for a gauge N ≤ ‖h‖ + β·|(κ, γ)|.
  std::vector<Eigen::Matrix<double, 5, 1>> slot_bound_;
  /// The gauge of a face criterion (laminate/criterion_gauge.hpp) on one face of one ply, with W
  /// replaced by W·A_face (columns κ, γ): N = ‖r(W e) + h‖ at the point's bending strains e.
  struct GaugeTerm {
    std::size_t ply = 0;
    GaugeBranch branch;
  };
  std::vector<std::vector<std::vector<GaugeTerm>>> gauge_terms_; ///< per criterion, per laminate
  std::vector<double> gauge_largest_h_; ///< per criterion: largest ‖h‖ of its quadratic branches (< 0: none)
  std::vector<char> gauge_linear_;      ///< per criterion: has linear branches
  bool gauged_ = false;                 ///< every face criterion has a gauge on every ply
  // Skipping points between evaluations (bending only; Choi–Chang, and the face criteria that have a
  // gauge, in the gauge's norms N instead of the indices): a point's bounds and indices can grow between two
  // observations by at most lip_w · Δw + lip_rot · Δθ, where Δw, Δθ are the largest changes of the element's
  // w and rotations; summed over observations (the element's path), the growth since the point's last proof
  // is bounded, and the point is looked at again only when that growth could use up a margin of its proof (to
  // 1 for the layers that have not failed, to the peak index so far for all). Exact: the onsets and peaks are
  // those of evaluating every point every time.
  struct PointLipschitz {
    double w = 0.0, rotation = 0.0; ///< index bound growth per unit Δw [1/m], per unit Δθ [1/rad]
  };
  std::vector<PointLipschitz> lipschitz_;      ///< per (shape class, local point, bound slot)
  Eigen::VectorXd previous_u_;                 ///< the plate state of the last observation
  bool proofs_valid_ = false;                  ///< false: every point is evaluated at the next observation
  std::vector<double> path_w_, path_rotation_; ///< per element: Σ max|Δw|, Σ max|Δθ|
  std::vector<double> proof_path_w_, proof_path_rotation_; ///< per point: the element paths at its proof
  std::vector<double> margin_; ///< per (slot, point): what the bounds (or norms) may grow by before a change
  std::vector<Eigen::Matrix<double, 5, 1>> proof_strains_; ///< per point: (κ, γ) at its last proof
  std::vector<double> proof_margin_;                       ///< per (slot, point): the margins then
  std::vector<double> point_largest_;  ///< per slot: the largest index of the point just evaluated
  std::vector<double> point_unfailed_; ///< per slot: the same over the layers that have not failed
  std::vector<char> failed_;           ///< per (criterion, layer, point)
  std::vector<char> cracked_;          ///< Choi–Chang matrix crack per (ply, point), for gating
  std::vector<double> area_;           ///< per (criterion, layer)
  std::vector<double> peak_;           ///< per criterion
  std::vector<PlyStress> averaged_;    ///< per ply, at the current point
  std::vector<FailureResult> matrix_;  ///< Choi–Chang matrix cracking per ply, current point
  bool needs_matrix_ = false;
  std::vector<DamageOnset> onsets_;
  std::vector<DamageAreaSample> areas_;
  long evaluated_points_ = 0, observed_points_ = 0;
};

[[nodiscard]] std::vector<Criterion> parse_criteria(const std::vector<std::string>& names);

} // namespace plyimpact
