#pragma once
// Ply and interface quantities sampled once per element, for pictures (ParaView) and reports.
//
// Sampled at the element centre (ξ = η = 0), where the 2×2/3×3 Gauss points of a Q9 are
// symmetric about: the ply stress is the exact ply average σ̄_k in material axes (SPEC §5), the
// interface shear is the equilibrium-recovered (τyz, τxz) at the interface height (continuous
// across it), and the failure indices are the criteria evaluated on σ̄_k. The damage flags
// come from the Gauss-point damage tracker (SPEC §7): the fraction of an element's 9 Gauss points
// that have failed in a ply (or interface) under any tracked criterion by time t.
#include "plyimpact/analysis/fields/damage_tracker.hpp"
#include "plyimpact/fem/discrete_plate.hpp"
#include "plyimpact/laminate/failure_criteria.hpp"

#include <Eigen/Core>
#include <vector>

namespace plyimpact {

struct ElementCentreFields {
  int elements = 0, plies = 0;
  std::vector<PlyStress> ply_stress;            ///< [ply·elements + e], σ̄ in material axes [Pa]
  std::vector<Eigen::Vector2d> interface_shear; ///< [interface·elements + e], (τyz, τxz) [Pa]
  std::vector<Criterion> criteria;              ///< the evaluated criteria, in order
  std::vector<double> index; ///< [(c·layers + layer)·elements + e]; layer = ply or interface
  [[nodiscard]] int interfaces() const { return plies - 1; }
  /// Position of (layer, element) in the per-layer arrays.
  [[nodiscard]] std::size_t at(int layer, int e) const {
    return std::size_t(layer) * std::size_t(elements) + std::size_t(e);
  }
  [[nodiscard]] const PlyStress& ply(int k, int e) const { return ply_stress[at(k, e)]; }
  [[nodiscard]] const Eigen::Vector2d& shear(int i, int e) const { return interface_shear[at(i, e)]; }
  /// Failure index of criterion c (position in `criteria`) at ply or interface `layer` (0-based).
  [[nodiscard]] double failure_index(std::size_t c, int layer, int e) const {
    return index[(c * std::size_t(plies) + std::size_t(layer)) * std::size_t(elements) + std::size_t(e)];
  }
};

/// Samples every element of `model` for the plate state u (free DOFs). Criteria whose strengths
/// are missing for a ply give index 0 there.
[[nodiscard]] ElementCentreFields element_centre_fields(const DiscretePlate& model, const Eigen::VectorXd& u,
                                                        const std::vector<Criterion>& criteria,
                                                        const CriterionOptions& options = {});

/// Fraction (0…1) of the 9 Gauss points of each element that have failed by time t.
struct DamageFractions {
  int elements = 0;
  std::vector<double> ply;       ///< [ply·elements + e], any ply criterion
  std::vector<double> interface; ///< [interface·elements + e], any interface criterion
  [[nodiscard]] double of_ply(int k, int e) const {
    return ply[std::size_t(k) * std::size_t(elements) + std::size_t(e)];
  }
  [[nodiscard]] double of_interface(int i, int e) const {
    return interface[std::size_t(i) * std::size_t(elements) + std::size_t(e)];
  }
};
[[nodiscard]] DamageFractions damage_fractions(const std::vector<DamageOnset>& onsets, int elements,
                                               int plies, double t);

} // namespace plyimpact
