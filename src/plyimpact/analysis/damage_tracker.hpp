#pragma once
// Damage initiation during an impact (SPEC §6–7; thesis 3.5.3, 4.3–4.6): every evaluated step, the
// selected criteria at the 3×3 Gauss points of every element, for every ply (and interface for
// delamination). A point that has failed in a criterion stays failed.
#include "plyimpact/analysis/stress_recovery.hpp"
#include "plyimpact/fem/plate_model.hpp"
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
};

class DamageTracker {
public:
  DamageTracker(const PlateModel& model, std::vector<Criterion> criteria, DamageOptions options = {});

  /// ImpactObserver: evaluates the criteria for the plate state u (free DOFs) at time t.
  void observe(long step, double t, double force, const Eigen::VectorXd& u);

  /// Every failed Gauss point in order of onset.
  [[nodiscard]] const std::vector<DamageOnset>& onsets() const { return onsets_; }
  /// The first onset of each (criterion, mode, ply or interface), in order of onset.
  [[nodiscard]] std::vector<DamageOnset> first_onsets() const;
  [[nodiscard]] const std::vector<DamageAreaSample>& area_history() const { return areas_; }
  /// Largest failure index reached so far by `criterion` anywhere (0 if never evaluated).
  [[nodiscard]] double peak_index(Criterion criterion) const;
  [[nodiscard]] bool any_failure() const { return !onsets_.empty(); }
  [[nodiscard]] const std::vector<Criterion>& criteria() const { return criteria_; }

private:
  struct GaussPoint {
    int element, i, j;
    double x, y, area;
  };
  void evaluate_point(std::size_t g, double t, double force);
  [[nodiscard]] bool cannot_change(const Eigen::Matrix<double, 5, 1>& strains) const;
  [[nodiscard]] std::size_t slot(std::size_t c, std::size_t layer, std::size_t g) const {
    return (c * layers_ + layer) * points_.size() + g;
  }

  const PlateModel& model_;
  std::vector<Criterion> criteria_;
  DamageOptions options_;
  bool track_cracks_for_delamination_ = false; ///< matrix cracking gates delamination (2.43)
  std::size_t layers_ = 0;                     ///< plies (interfaces use indices 0..N−2)
  std::vector<GaussPoint> points_;
  using StrainOperator = Eigen::Matrix<double, 8, q9_dofs>; ///< (ε0, κ, γ) from element DOFs
  using StressOperator = Eigen::Matrix<double, 5, 8>; ///< (σ11, σ22, τ12, τ13, τ23) from (ε0, κ, γ)
  std::vector<StrainOperator> B_;                     ///< per point (or per local point on a regular mesh)
  /// Per ply (rows 5k..5k+4): Q̄, the height z and the rotation folded into (σ11, σ22, τ12, τ13, τ23)
  /// from (ε0, κ, γ), at the ply mid-plane (= ply average) and at its faces.
  Eigen::MatrixXd A_average_, A_top_, A_bottom_;
  bool needs_faces_ = false;
  Eigen::MatrixXd U_, local_strains_, E_, S_average_, S_top_, S_bottom_; ///< work arrays, sized once
  std::vector<Eigen::Matrix<double, 5, 27>> B_bending_; ///< (κ, γ) rows, (w, θx, θy) columns of B_
  std::vector<int> inplane_equations_;
  std::vector<Eigen::Matrix<double, 5, 5>> average_bending_, top_bending_,
      bottom_bending_;                                          ///< (κ, γ) columns of A
  std::vector<Eigen::Matrix<double, 3, 5>> transverse_bending_; ///< rows σ22, τ13, τ23 of average_bending_
  std::vector<Eigen::Matrix<double, 5, 1>> choi_chang_bound_; ///< per criterion: index ≤ bound · |(κ, γ)|
  std::vector<std::array<int, q9_dofs>> element_equations_;
  bool regular_ = false;
  std::vector<char> failed_;          ///< per (criterion, layer, point)
  std::vector<char> cracked_;         ///< Choi–Chang matrix crack per (ply, point), for gating
  std::vector<double> area_;          ///< per (criterion, layer)
  std::vector<double> peak_;          ///< per criterion
  std::vector<PlyStress> averaged_;   ///< per ply, at the current point
  std::vector<FailureResult> matrix_; ///< Choi–Chang matrix cracking per ply, current point
  bool needs_matrix_ = false;
  std::vector<DamageOnset> onsets_;
  std::vector<DamageAreaSample> areas_;
};

[[nodiscard]] std::vector<Criterion> parse_criteria(const std::vector<std::string>& names);

} // namespace plyimpact
