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

/// What a static, modal or buckling deck's plate is: the materials, the laminate, the plate and its mesh
/// with the restraint codes (the start of report.txt).
[[nodiscard]] std::string plate_input_text(const Deck& deck, const DiscretePlate& model);
/// The input echo of report.txt, every setting resolved as the run uses it: plate_input_text, the impactor
/// and the contact law, the time stepping and integrator, and the plate model (kinematics, ply damage, the
/// interfaces that may delaminate). What `plyimpact preview` prints before a run; `stable_step_pending`: an
/// explicit run whose time step (at most settings.dt) is the stable step the run finds when it starts.
[[nodiscard]] std::string impact_input_text(const Deck& deck, const DiscretePlate& model,
                                            const ImpactSettings& settings, bool stable_step_pending = false);

[[nodiscard]] std::string impact_report_text(const Deck& deck, const DiscretePlate& model,
                                             const ImpactSettings& settings, const ImpactResult& result,
                                             const std::vector<DamageOnset>& first_failures,
                                             const std::vector<int>& clamp_tip_elements,
                                             const std::optional<DamageOnset>& laminate_first_failure,
                                             const std::optional<NodalSnapshot>& displacements);

} // namespace plyimpact
