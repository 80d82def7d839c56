#pragma once
// The one table of what runs (issue 49): every plate model of an impact case under every time
// integrator. The deck reader, the facade (ImpactCase) and docs/deck.md read it, so that a combination
// that does not run is refused with the reason written here, once, and the documentation cannot drift
// from the code (test: the table in docs/deck.md is capability_table_markdown()).
//
// A model is a composition: kinematics (linear or von Kármán) × section (elastic, or plies that crack)
// × stacking (one laminate, or sub-laminates tied by cohesive interfaces). An integrator is implicit
// Newmark (one factor of K̄ for the linear elastic plate, Newton iterations otherwise), the lagged
// Newton–Newmark step of the laws with state (the damage of the step before held fixed), or explicit
// central differences on the lumped mass.
#include "plyimpact/analysis/impact/parameters.hpp"
#include "plyimpact/fem/damaged_plate.hpp"
#include "plyimpact/fem/mesh_spec.hpp"
#include "plyimpact/fem/nonlinear_plate_element.hpp"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace plyimpact {

struct ImpactCaseDescription;

/// What the plate of a case is made of.
struct ModelKind {
  bool rigid_target = false; ///< no plate: a rigid, immovable target
  bool von_karman = false;   ///< geometrically non-linear kinematics (SPEC §8)
  bool ply_damage = false;   ///< plies that crack ([damage] model = "progressive")
  bool interfaces = false;   ///< sub-laminates tied by cohesive interfaces ([delamination])
};

/// "elastic plate", "von Kármán plate with ply damage and interfaces", …
[[nodiscard]] std::string model_name(const ModelKind& m);

/// One cell of the table: whether the pair runs, and the step that runs it or why it does not.
struct Capability {
  bool runs = false;
  std::string_view detail;
};
[[nodiscard]] Capability capability(const ModelKind& m, Integrator i);
/// Why the pair cannot run, as a message for the user (model, integrator, reason); empty when it runs.
[[nodiscard]] std::optional<std::string> refusal(const ModelKind& m, Integrator i);
/// The whole table as Markdown (docs/deck.md, "What runs").
[[nodiscard]] std::string capability_table_markdown();

/// The integrators the model runs with, in the deck's spelling ("implicit, lagged, explicit").
[[nodiscard]] std::string integrators_that_run(const ModelKind& m);
/// The one integrator of a plate model `m` from what the deck asks: `time` ([time] integration), the
/// laws' own choices (`damage`, `interfaces`; empty where the model has no such law). Throws
/// std::invalid_argument, naming the keys and what runs, where they ask for different integrators.
[[nodiscard]] Integrator resolve_integrator(const ModelKind& m, TimeScheme time,
                                            std::optional<Integrator> damage,
                                            std::optional<Integrator> interfaces);

/// What a case chooses beside its model and its integrator, where they restrict the choice.
struct CaseOptions {
  ElementFormulation element = ElementFormulation::automatic; ///< as asked ([mesh] element)
  StrainMeasure strain_measure = StrainMeasure::von_karman;   ///< of von Kármán kinematics
  bool regions = false;                                       ///< [[region]] tables with other laminates
  MassMatrix mass = MassMatrix::lumped;                       ///< [mesh] mass
  bool adaptive = false;                                      ///< error-controlled steps ([time] adaptive)
  MassScalingKind mass_scaling = MassScalingKind::none;       ///< [time] mass_scaling
  bool ply_criteria = false; ///< failure criteria tracked on the plies ([damage] criteria)
};

/// A rule of what runs beside the model × integrator table: a choice that a model or an integrator
/// restricts, the deck key that makes it, and the refusal, with its reason and the way out.
struct Restriction {
  std::string_view table;   ///< the deck table of the key ("" at the top level)
  std::string_view key;     ///< the key whose value is refused
  std::string_view rule;    ///< what runs, in a few words (docs/deck.md, "What runs")
  std::string_view message; ///< the refusal: what is refused, why, what to change
  bool (*breaks)(const ModelKind&, Integrator, const CaseOptions&);
};
/// Every restriction, in the order they are checked (the more particular first).
[[nodiscard]] std::span<const Restriction> restrictions();
/// The first restriction a case breaks; null where it breaks none.
[[nodiscard]] const Restriction* broken_restriction(const ModelKind& m, Integrator i, const CaseOptions& o);
/// The restrictions as a Markdown list (docs/deck.md, "What runs"; `plyimpact capabilities`).
[[nodiscard]] std::string restrictions_markdown();

/// The model of a case.
[[nodiscard]] ModelKind model_kind(const ImpactCaseDescription& d);
/// The integrator of a case: [time] integration = "explicit", or the [damage] / [delamination]
/// integration. Throws std::invalid_argument where they ask for different integrators (the whole plate
/// steps with one).
[[nodiscard]] Integrator case_integrator(const ImpactCaseDescription& d);
/// The options of a case that the restrictions look at.
[[nodiscard]] CaseOptions case_options(const ImpactCaseDescription& d);
/// Throws std::invalid_argument with refusal()'s message where the case's pair does not run, or with the
/// message of the first restriction it breaks.
void require_supported(const ImpactCaseDescription& d);

} // namespace plyimpact
