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
#include "plyimpact/analysis/parameters.hpp"
#include "plyimpact/fem/damaged_plate.hpp"

#include <optional>
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

/// The time integrator of a case (the whole plate steps with one).
enum class Integrator {
  implicit,           ///< Newmark: linear (one factor) or Newton–Newmark
  lagged,             ///< Newton–Newmark with the laws' state of the step before held fixed
  central_difference, ///< explicit central differences on the lumped mass
};

/// The deck spelling: "implicit", "lagged", "explicit".
[[nodiscard]] std::string_view to_string(Integrator i);
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
/// [damage] and [delamination] integration as an integrator.
[[nodiscard]] Integrator integrator_of(DamageIntegration i);
/// The one integrator of a plate model `m` from what the deck asks: `time` ([time] integration), the
/// laws' own choices (`damage`, `interfaces`; empty where the model has no such law). Throws
/// std::invalid_argument, naming the keys and what runs, where they ask for different integrators.
[[nodiscard]] Integrator resolve_integrator(const ModelKind& m, TimeIntegration time,
                                            std::optional<Integrator> damage,
                                            std::optional<Integrator> interfaces);

/// The model of a case.
[[nodiscard]] ModelKind model_kind(const ImpactCaseDescription& d);
/// The integrator of a case: [time] integration = "explicit", or the [damage] / [delamination]
/// integration. Throws std::invalid_argument where they ask for different integrators (the whole plate
/// steps with one).
[[nodiscard]] Integrator case_integrator(const ImpactCaseDescription& d);
/// Throws std::invalid_argument with refusal()'s message where the case's pair does not run.
void require_supported(const ImpactCaseDescription& d);

} // namespace plyimpact
