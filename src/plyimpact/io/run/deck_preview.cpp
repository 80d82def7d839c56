#include "plyimpact/io/run/deck_preview.hpp"

#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/results/impact_text_report.hpp"

#include <filesystem>

namespace plyimpact {

namespace {

/// What the preview shows of every deck: its title, the plate's mesh and supports, the rig, the ply stack
/// and the interfaces of [delamination].
ModelPreview plate_preview(const Deck& deck, const DiscretePlate& model) {
  ModelPreview p{.title =
                     deck.title.empty() ? std::filesystem::path(deck.source).filename().string() : deck.title,
                 .source = deck.source,
                 .mesh = model.mesh(),
                 .supports = support_marks(model.mesh(), model.boundary()),
                 .rig = rig_outline(deck.rig),
                 .impact_point = std::nullopt,
                 .contact_radius = 0.0,
                 .laminate = deck.laminate,
                 .interfaces_after_ply = {},
                 .settings = plate_input_text(deck, model)};
  if (deck.delamination)
    for (const int cut : deck.delamination->stack.cuts)
      p.interfaces_after_ply.push_back(cut + 1); // a cut after 0-based ply k lies under ply k + 1
  return p;
}

} // namespace

ModelPreview deck_preview(const Deck& deck, bool nonlinear) {
  if (deck.analysis != AnalysisKind::impact && deck.analysis != AnalysisKind::threshold)
    return plate_preview(deck, plate_model(deck));
  const ImpactCaseDescription d = impact_case_description(deck, nonlinear);
  const DiscretePlate model = impact_plate_model(d);
  // The explicit stable step needs the highest frequency of the assembled plate (a minute for a stacked
  // coupon): the preview gives the bound the run starts from and says so.
  ImpactSettings settings = resolved_settings(d);
  settings.mesh = mesh_used(model, d.mesh.grading.has_value() && !settings.rigid_target);
  const bool stable_step_pending = settings.integration == Integrator::central_difference && !d.time.dt;
  ModelPreview p = plate_preview(deck, model);
  p.impact_point = Eigen::Vector2d(settings.impactor.x, settings.impactor.y);
  p.contact_radius = expected_contact_radius(d);
  p.settings = impact_input_text(deck, model, settings, stable_step_pending);
  return p;
}

} // namespace plyimpact
