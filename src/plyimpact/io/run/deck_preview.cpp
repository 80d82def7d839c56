#include "plyimpact/io/run/deck_preview.hpp"

#include "plyimpact/fem/stacked_plate.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/results/impact_text_report.hpp"

#include <filesystem>
#include <string>
#include <utility>

namespace plyimpact {

namespace {

/// What the preview shows of every deck: its title, the plate's mesh and supports, the rig, the ply stack
/// and the interfaces of [delamination], and `settings`.
ModelPreview plate_preview(const Deck& deck, const DiscretePlate& model, std::string settings) {
  return {.title = deck.title.empty() ? std::filesystem::path(deck.source).filename().string() : deck.title,
          .source = deck.source,
          .mesh = model.mesh(),
          .supports = support_marks(model.mesh(), model.boundary()),
          .rig = rig_outline(deck.rig),
          .impact_point = std::nullopt,
          .contact_radius = 0.0,
          .laminate = deck.laminate,
          .interfaces_after_ply =
              deck.delamination ? interfaces_after_ply(deck.delamination->stack.cuts) : std::vector<int>{},
          .settings = std::move(settings)};
}

} // namespace

ModelPreview deck_preview(const Deck& deck, bool nonlinear) {
  if (deck.analysis != AnalysisKind::impact && deck.analysis != AnalysisKind::threshold) {
    const DiscretePlate model = plate_model(deck);
    return plate_preview(deck, model, plate_input_text(deck, model));
  }
  const ImpactCaseDescription d = impact_case_description(deck, nonlinear);
  const DiscretePlate model = impact_plate_model(d);
  // The explicit stable step needs the highest frequency of the assembled plate (a minute for a stacked
  // coupon): the preview gives the bound the run starts from and says so.
  ImpactSettings settings = resolved_settings(d);
  settings.mesh = mesh_used(model, d.mesh.grading.has_value() && !settings.rigid_target);
  const bool stable_step_pending = settings.integration == Integrator::central_difference && !d.time.dt;
  ModelPreview p = plate_preview(deck, model, impact_input_text(deck, model, settings, stable_step_pending));
  p.impact_point = Eigen::Vector2d(settings.impactor.x, settings.impactor.y);
  p.contact_radius = expected_contact_radius(d);
  return p;
}

} // namespace plyimpact
