// The table of plate models × time integrators (capabilities.hpp).
#include "plyimpact/analysis/impact/capabilities.hpp"

#include "plyimpact/analysis/impact/impact_case.hpp"

#include <fmt/format.h>

#include <array>
#include <stdexcept>

namespace plyimpact {

namespace {

/// Cells of one row: implicit, lagged, central differences.
struct Row {
  ModelKind model;
  std::array<Capability, 3> cells;
};

constexpr std::string_view no_state = "– (no law with a state to lag)";
constexpr Capability runs(std::string_view how) {
  return {true, how};
}
constexpr Capability refused(std::string_view why) {
  return {false, why};
}

// clang-format off
constexpr std::array<Row, 9> table{{
  {{false, false, false, false}, {runs("linear Newmark, K̄ factored once (linear_step.cpp)"),
                                  refused(no_state),
                                  runs("central differences (central_difference_step.cpp)")}},
  {{false, true, false, false},  {runs("Newton–Newmark on the tangent, modified Newton (newton_newmark_step.cpp)"),
                                  refused(no_state),
                                  runs("central differences (central_difference_step.cpp)")}},
  {{false, false, true, false},  {runs("Newton–Newmark on the secant (newton_newmark_step.cpp)"),
                                  runs("Newton–Newmark, damage of the step before (newton_newmark_step.cpp)"),
                                  runs("central differences (central_difference_step.cpp)")}},
  {{false, false, false, true},  {runs("Newton–Newmark, interfaces iterated, their tangent by LU (newton_newmark_step.cpp on stacked_model.cpp)"),
                                  runs("Newton–Newmark, interfaces of the step before, factor updates (newton_newmark_step.cpp on stacked_model.cpp)"),
                                  runs("central differences (central_difference_step.cpp on stacked_model.cpp)")}},
  {{false, false, true, true},   {runs("Newton–Newmark, plies and interfaces iterated, LU (newton_newmark_step.cpp on stacked_model.cpp)"),
                                  runs("Newton–Newmark, plies and interfaces of the step before (newton_newmark_step.cpp on stacked_model.cpp)"),
                                  runs("central differences (central_difference_step.cpp on stacked_model.cpp)")}},
  {{false, true, true, false},   {runs("Newton–Newmark on the tangent plus the damaged sections' secant (newton_newmark_step.cpp)"),
                                  runs("Newton–Newmark, damage of the step before (newton_newmark_step.cpp)"),
                                  runs("central differences (central_difference_step.cpp)")}},
  {{false, true, false, true},   {runs("Newton–Newmark, interfaces iterated, each sub-laminate's tangent, LU (newton_newmark_step.cpp on stacked_model.cpp)"),
                                  runs("Newton–Newmark, interfaces of the step before, each sub-laminate's tangent (newton_newmark_step.cpp on stacked_model.cpp)"),
                                  runs("central differences (central_difference_step.cpp on stacked_model.cpp)")}},
  {{false, true, true, true},    {runs("Newton–Newmark, plies and interfaces iterated, LU (newton_newmark_step.cpp on stacked_model.cpp)"),
                                  runs("Newton–Newmark, plies and interfaces of the step before (newton_newmark_step.cpp on stacked_model.cpp)"),
                                  runs("central differences (central_difference_step.cpp on stacked_model.cpp)")}},
  {{true, false, false, false},  {runs("the impactor alone (rigid_target_step.cpp)"),
                                  refused(no_state),
                                  runs("the impactor alone (rigid_target_step.cpp)")}},
}};
// clang-format on

bool same(const ModelKind& a, const ModelKind& b) {
  return a.rigid_target == b.rigid_target && a.von_karman == b.von_karman && a.ply_damage == b.ply_damage &&
         a.interfaces == b.interfaces;
}

/// A rigid target with anything that needs a plate: the physical reason, else empty.
std::optional<std::string_view> rigid_target_conflict(const ModelKind& m) {
  if (!m.rigid_target) return std::nullopt;
  if (m.ply_damage) return "progressive damage needs a plate: a rigid target has no plies to crack";
  if (m.interfaces) return "delamination needs a plate: a rigid target has no interfaces to open";
  if (m.von_karman) return "non-linear impact needs a plate: a rigid target has no deflection to stiffen";
  return std::nullopt;
}

std::size_t column(Integrator i) {
  return static_cast<std::size_t>(i);
}

ElementFormulation resolved(ElementFormulation e) { // fem/discrete_plate.cpp: automatic is MITC9
  return e == ElementFormulation::automatic ? ElementFormulation::mitc9 : e;
}

// clang-format off
constexpr std::array<Restriction, 9> restriction_table{{
  {"mesh", "element", "ply damage needs the MITC9 element",
   "damage.model = \"progressive\" needs the MITC9 element: leave out mesh.element or set it to \"mitc9\" "
   "(the q9 element integrates transverse shear at other points than the 3x3 Gauss points where the plies' "
   "damage lives)",
   [](const ModelKind& m, Integrator, const CaseOptions& o) {
     return m.ply_damage && o.element == ElementFormulation::q9;
   }},
  {"", "strain_measure", "ply damage takes the von Kármán strains",
   "progressive damage takes the von Kármán strains of a non-linear plate: set strain_measure = "
   "\"von-karman\" (the Green–Lagrange measure is not built for the layered section whose plies crack)",
   [](const ModelKind& m, Integrator, const CaseOptions& o) {
     return m.von_karman && m.ply_damage && o.strain_measure == StrainMeasure::green_lagrange;
   }},
  {"", "strain_measure", "Green–Lagrange strains need the q9 element",
   "the Green-Lagrange strain measure is available with the q9 element only (its transverse-shear terms "
   "(2.55) have no MITC9 interpolation): set [mesh] element = \"q9\" or use strain_measure = \"von-karman\"",
   [](const ModelKind& m, Integrator, const CaseOptions& o) {
     return m.von_karman && o.strain_measure == StrainMeasure::green_lagrange &&
            resolved(o.element) == ElementFormulation::mitc9;
   }},
  {"", "region", "interfaces need one laminate over the whole plate",
   "[delamination] needs one laminate over the whole plate: [[region]] tables with other laminates are not "
   "available with it yet (docs/delamination.md, limits)",
   [](const ModelKind& m, Integrator, const CaseOptions& o) { return m.interfaces && o.regions; }},
  {"mesh", "mass", "explicit steps need the lumped mass",
   "explicit steps (central differences) need a diagonal mass: set [mesh] mass = \"lumped\" (a consistent "
   "mass would be solved at every step), or choose implicit steps",
   [](const ModelKind& m, Integrator i, const CaseOptions& o) {
     return !m.rigid_target && i == Integrator::central_difference && o.mass != MassMatrix::lumped;
   }},
  {"time", "adaptive", "error-controlled steps are implicit",
   "time.adaptive factors K̄ at each step level, but explicit steps solve nothing and need every step below "
   "the stable one: remove adaptive = true, or use integration = \"implicit\"",
   [](const ModelKind&, Integrator i, const CaseOptions& o) {
     return o.adaptive && i == Integrator::central_difference;
   }},
  {"time", "adaptive", "error-controlled steps: the elastic plate and the rigid target only",
   "time.adaptive controls the error of the contact force only: the non-linear plate, the ply criteria, the "
   "progressive damage and the interfaces need every step at one Δt. Remove adaptive = true (and give dt), "
   "or leave out nonlinear, [damage] and [delamination]",
   [](const ModelKind& m, Integrator, const CaseOptions& o) {
     return o.adaptive && (m.von_karman || m.ply_damage || m.interfaces || o.ply_criteria);
   }},
  {"time", "mass_scaling", "mass scaling: explicit steps only",
   "time.mass_scaling scales the lumped mass of explicit steps, but the plate's steps are implicit: remove "
   "mass_scaling, or choose explicit steps (integration = \"explicit\" in [time], [damage] or [delamination])",
   [](const ModelKind&, Integrator i, const CaseOptions& o) {
     return o.mass_scaling != MassScalingKind::none && i != Integrator::central_difference;
   }},
  {"time", "mass_scaling", "selective mass scaling: a stack only",
   "time.mass_scaling = \"selective\" adds mass to the relative motion of a stack's interfaces, and this "
   "case has no [delamination]: use \"rotary\" (or \"nodal\" with target_dt) for a single plate",
   [](const ModelKind& m, Integrator, const CaseOptions& o) {
     return o.mass_scaling == MassScalingKind::selective && !m.interfaces;
   }},
}};
// clang-format on

} // namespace

std::span<const Restriction> restrictions() {
  return restriction_table;
}

const Restriction* broken_restriction(const ModelKind& m, Integrator i, const CaseOptions& o) {
  for (const Restriction& r : restriction_table)
    if (r.breaks(m, i, o)) return &r;
  return nullptr;
}

std::string restrictions_markdown() {
  std::string md;
  for (const Restriction& r : restriction_table) {
    const std::string key = r.key == "region" ? std::string("[[region]]")
                            : r.table.empty() ? std::string(r.key)
                                              : fmt::format("{}.{}", r.table, r.key);
    md += fmt::format("- {} (`{}`)\n", r.rule, key);
  }
  return md;
}

std::string_view to_string(Integrator i) {
  switch (i) {
  case Integrator::implicit:
    return "implicit";
  case Integrator::lagged:
    return "lagged";
  case Integrator::central_difference:
    return "explicit";
  }
  return "?";
}

std::string model_name(const ModelKind& m) {
  if (m.rigid_target) return "rigid target";
  std::string name = m.von_karman ? "von Kármán plate" : "elastic plate";
  if (m.ply_damage && m.interfaces) return name + " with ply damage and interfaces";
  if (m.ply_damage) return name + " with ply damage";
  if (m.interfaces) return name + " with interfaces";
  return name;
}

Capability capability(const ModelKind& m, Integrator i) {
  if (const auto why = rigid_target_conflict(m)) return refused(*why);
  for (const Row& row : table)
    if (same(row.model, m)) return row.cells[column(i)];
  return refused("not in the table");
}

std::optional<std::string> refusal(const ModelKind& m, Integrator i) {
  if (const auto why = rigid_target_conflict(m)) return std::string(*why);
  const Capability c = capability(m, i);
  if (c.runs) return std::nullopt;
  return fmt::format("the {} does not run with {} steps: {} (docs/deck.md, \"What runs\")", model_name(m),
                     to_string(i), c.detail);
}

std::string capability_table_markdown() {
  std::string md = "| model | `implicit` | `lagged` | `explicit` |\n|---|---|---|---|\n";
  for (const Row& row : table) {
    md += "| " + model_name(row.model);
    for (const Capability& c : row.cells)
      md += fmt::format(" | {}{}", c.runs ? "runs: " : "", c.detail);
    md += " |\n";
  }
  return md;
}

std::string integrators_that_run(const ModelKind& m) {
  std::string list;
  for (const Integrator i : {Integrator::implicit, Integrator::lagged, Integrator::central_difference})
    if (capability(m, i).runs) list += (list.empty() ? "" : ", ") + std::string(to_string(i));
  return list.empty() ? "none" : list;
}

Integrator resolve_integrator(const ModelKind& m, TimeScheme time, std::optional<Integrator> damage,
                              std::optional<Integrator> interfaces) {
  const auto differ = [&](std::string_view first, Integrator a, std::string_view second, Integrator b) {
    return std::invalid_argument(
        fmt::format("the plate steps with one integrator, but {} = \"{}\" and {} = \"{}\" differ: give "
                    "them the same value (the {} runs with: {})",
                    first, to_string(a), second, to_string(b), model_name(m), integrators_that_run(m)));
  };
  if (damage && interfaces && *damage != *interfaces)
    throw differ("[damage] integration", *damage, "[delamination] integration", *interfaces);
  const std::optional<Integrator> laws = damage ? damage : interfaces;
  if (time == TimeScheme::central_difference) {
    if (laws && *laws != Integrator::central_difference)
      throw differ("[time] integration", Integrator::central_difference,
                   damage ? "[damage] integration" : "[delamination] integration", *laws);
    return Integrator::central_difference;
  }
  return laws.value_or(Integrator::implicit);
}

ModelKind model_kind(const ImpactCaseDescription& d) {
  return {d.plate.rigid, d.nonlinear.has_value(), d.progressive_damage.has_value(),
          d.delamination.has_value()};
}

Integrator case_integrator(const ImpactCaseDescription& d) {
  std::optional<Integrator> laws = d.time.laws;
  if (!laws && d.delamination && d.time.integration != TimeScheme::central_difference)
    laws = Integrator::lagged; // the stack's default
  const bool plies = d.progressive_damage.has_value();
  return resolve_integrator(model_kind(d), d.time.integration, plies ? laws : std::nullopt,
                            plies ? std::nullopt : laws);
}

CaseOptions case_options(const ImpactCaseDescription& d) {
  CaseOptions o;
  o.element = d.mesh.element;
  if (d.nonlinear) o.strain_measure = d.nonlinear->measure;
  o.regions = !d.regions.empty();
  o.mass = d.mesh.mass;
  o.adaptive = d.time.adaptive.has_value();
  o.mass_scaling = d.time.mass_scaling.kind;
  return o;
}

void require_supported(const ImpactCaseDescription& d) {
  const ModelKind m = model_kind(d);
  const Integrator i = case_integrator(d);
  if (auto why = refusal(m, i)) throw std::invalid_argument(*why);
  if (const Restriction* r = broken_restriction(m, i, case_options(d)))
    throw std::invalid_argument(std::string(r->message));
}

} // namespace plyimpact
