#pragma once
// report.txt: the whole impact run on one page of text, in the spirit of the thesis's Annex 2
// ("Fichier de résultats"): input echo (material, laminate, A B D F, mesh, restraints), impactor
// and contact data, time step, peak values, the first-failure table and, when asked
// ([output] report_displacements_at), the nodal displacements at one time.
#include "plyimpact/analysis/fields/damage_tracker.hpp"
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/io/deck/deck.hpp"

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace plyimpact {

/// The plate state at one time, for the displacement table.
struct NodalSnapshot {
  double t = 0.0;    ///< [s]
  Eigen::VectorXd u; ///< free DOFs of the DiscretePlate
};

[[nodiscard]] std::string impact_report_text(const Deck& deck, const DiscretePlate& model,
                                             const ImpactSettings& settings, const ImpactResult& result,
                                             const std::vector<DamageOnset>& first_failures,
                                             const std::vector<int>& clamp_tip_elements,
                                             const std::optional<DamageOnset>& laminate_first_failure,
                                             const std::optional<NodalSnapshot>& displacements);

} // namespace plyimpact
