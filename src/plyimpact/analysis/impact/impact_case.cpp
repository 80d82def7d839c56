#include "plyimpact/analysis/impact/impact_case.hpp"

#include "plyimpact/analysis/fields/damage_zone.hpp"

#include "plyimpact/analysis/impact/capabilities.hpp"
#include "plyimpact/analysis/impact/mesh_memory.hpp"
#include "plyimpact/analysis/integrators/step_policy.hpp"

#include "plyimpact/analysis/contact/contact_rules.hpp"
#include "plyimpact/analysis/impact/guards.hpp"
#include "plyimpact/analysis/impact/recorders.hpp"
#include "plyimpact/analysis/plate_analyses/modal_analysis.hpp"
#include "plyimpact/analysis/plate_analyses/static_analysis.hpp"
#include "plyimpact/fem/element_loop.hpp"
#include "plyimpact/fem/structured_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace plyimpact {

namespace {

/// The laminate under the impact point (the last region holding it, or the plate's own).
const Laminate& impacted_laminate(const ImpactCaseDescription& d) {
  const Laminate* lam = &d.laminates.front();
  for (const Region& r : d.regions)
    if (r.contains(d.impactor.x, d.impactor.y)) lam = &d.laminates[static_cast<std::size_t>(r.laminate)];
  return *lam;
}

/// The deck values that can make the impact step's matrix singular or not positive definite, for the
/// message of a factorization that failed (docs/robustness.md, "Solver failures").
std::string singular_matrix_causes(const ImpactCaseDescription& d) {
  std::string causes;
  if (d.delamination)
    causes +=
        fmt::format("delamination.penalty_stiffness = {:.4g} Pa/m (far above the plies' own stiffness the "
                    "matrix loses its digits; \"auto\" gives Turon's 50 E3/t); ",
                    d.delamination->stack.interface.penalty_stiffness);
  return causes +
         "the materials' moduli E1, E2, G12, G13, G23 (one many orders below the others); the element "
         "sizes (mesh.size_at_impact, mesh.max_size or the mesh file's: elements many orders smaller "
         "than the plate); [boundary] or the rig (supports that leave a part of the plate free to move "
         "as a rigid body)";
}

/// `work()`, its failed factorization (NotPositiveDefinite) rethrown naming the deck values that can cause
/// it.
template <class Work>
auto naming_singular_causes(const ImpactCaseDescription& d, const Work& work) -> decltype(work()) {
  try {
    return work();
  } catch (const NotPositiveDefinite& e) {
    throw NotPositiveDefinite(
        fmt::format("{}; the deck values that can make it so: {}", e.what(), singular_matrix_causes(d)));
  }
}

/// The laws of the case's plate and its integrator.
PlatePhysics plate_physics(const ImpactCaseDescription& d) {
  std::optional<DelaminationSettings> interfaces = d.delamination;
  if (interfaces && !d.laminates.empty()) { // the cohesive zone is checked where delaminations grow (DZ3)
    interfaces->zone_x = d.impactor.x;
    interfaces->zone_y = d.impactor.y;
    interfaces->zone_radius = damage_zone_radius(d.laminates.front());
  }
  return {d.nonlinear, d.progressive_damage, std::move(interfaces), case_integrator(d), d.newton};
}

/// The model that central differences move in `d` (the same for ω_max and the policy); null where the
/// case's steps are implicit.
std::unique_ptr<const MechanicalModel> explicit_model(const ImpactCaseDescription& d,
                                                      const DiscretePlate& model) {
  const PlatePhysics physics = plate_physics(d);
  if (d.plate.rigid || physics.integrator != Integrator::central_difference) return nullptr;
  return mechanical_model(model, physics);
}

/// The lumped mass that central differences move `explicit_plate` with, scaled as the deck asks
/// (mass_scaling.hpp); null where the case's steps are implicit.
std::shared_ptr<const ScaledMass> explicit_case_mass(const ImpactCaseDescription& d,
                                                     const MechanicalModel* explicit_plate) {
  if (!explicit_plate) return nullptr;
  return std::make_shared<const ScaledMass>(
      explicit_mass(*explicit_plate, explicit_key(plate_physics(d)), d.time.mass_scaling));
}

std::optional<StableStepSource> highest_mode(const ImpactCaseDescription& d,
                                             const MechanicalModel* explicit_plate, const ScaledMass* mass) {
  if (!explicit_plate) return std::nullopt;
  return naming_singular_causes(d, [&] { return explicit_highest_mode(*explicit_plate, *mass); });
}

/// The description, once its mesh is known to fit in the memory available (mesh_memory.hpp): nothing is
/// built before, whichever front end asks.
ImpactCaseDescription within_memory(ImpactCaseDescription d) {
  check_memory_before_assembly(d);
  return d;
}

/// `d` where its plate model runs with its integrator (the one table of what runs, capabilities.hpp);
/// throws std::invalid_argument with the reason otherwise, before anything is assembled.
ImpactCaseDescription supported(ImpactCaseDescription d) {
  require_supported(d);
  return d;
}

} // namespace

MeshUsed mesh_used(const DiscretePlate& model, bool graded) {
  MeshUsed m;
  const Mesh& mesh = model.mesh();
  m.elements = mesh.element_count();
  m.element = model.formulation();
  m.graded = graded;
  m.smallest_element = std::numeric_limits<double>::infinity();
  for (int e = 0; e < mesh.element_count(); ++e) {
    const ElementCoordinates X = mesh.element_coordinates(e);
    const double side =
        std::max(X.col(0).maxCoeff() - X.col(0).minCoeff(), X.col(1).maxCoeff() - X.col(1).minCoeff());
    m.smallest_element = std::min(m.smallest_element, side);
    m.largest_element = std::max(m.largest_element, side);
  }
  return m;
}

double resolved_contact_stiffness(const ImpactCaseDescription& d) {
  if (d.contact.k) return *d.contact.k;
  return automatic_contact_stiffness(d.impactor, impacted_laminate(d));
}

ImpactSettings resolved_settings(const ImpactCaseDescription& d) {
  ImpactSettings s;
  s.impactor = d.impactor;
  s.k = resolved_contact_stiffness(d);
  s.contact = d.contact;
  s.dt = d.time.dt ? *d.time.dt
                   : automatic_time_step(d.impactor.mass, s.k, d.impactor.velocity,
                                         contact_exponent(d.impactor.nose));
  if (d.time.adaptive && !d.time.dt) // the automatic step is the smallest of the error-controlled ones
    s.dt = std::ldexp(s.dt, d.time.adaptive->levels - 1);
  s.adaptive = d.time.adaptive;
  s.integration = case_integrator(d);
  if (d.delamination && s.integration != Integrator::central_difference && !d.time.dt &&
      !d.laminates.empty()) // within the interfaces' limit (DL5)
    s.dt = std::min(s.dt, 0.8 * largest_delamination_time_step(d.laminates.front(), d.delamination->stack,
                                                               d.time.newmark_beta));
  s.end = d.time.end;
  s.end_rule = d.time.end_rule;
  s.newmark_beta = d.time.newmark_beta;
  s.newmark_gamma = d.time.newmark_gamma;
  s.max_steps = d.time.max_steps;
  s.stop_at_energy_error = d.time.stop_at_energy_error;
  s.rigid_target = d.plate.rigid;
  s.nonlinear = d.nonlinear;
  s.progressive_damage = d.progressive_damage;
  if (d.delamination) s.delamination = interfaces_for(*d.delamination, s.integration);
  return s;
}

std::optional<double> explicit_highest_frequency(const ImpactCaseDescription& d, const DiscretePlate& model) {
  const std::unique_ptr<const MechanicalModel> plate = explicit_model(d, model);
  const std::shared_ptr<const ScaledMass> mass = explicit_case_mass(d, plate.get());
  const std::optional<StableStepSource> mode = highest_mode(d, plate.get(), mass.get());
  if (!mode) return std::nullopt;
  return mode->omega_max;
}

ImpactSettings resolved_settings(const ImpactCaseDescription& d, std::optional<double> explicit_omega_max) {
  ImpactSettings s = resolved_settings(d);
  if (explicit_omega_max && !d.time.dt) // dt = "auto" below the stable step (CD5)
    s.dt = std::min(s.dt, stable_time_step(*explicit_omega_max));
  return s;
}

ImpactSettings resolved_settings(const ImpactCaseDescription& d, const DiscretePlate& model) {
  return resolved_settings(d, explicit_highest_frequency(d, model));
}

namespace {

/// What of `d` builds its case: the impactor and the contact stiffness left out, what they set of the case
/// kept resolved (the time step; the graded mesh's size and impact point), and the memory guard left out.
ImpactCaseDescription plate_part(ImpactCaseDescription d) {
  d.time.dt = resolved_settings(d).dt;
  Impactor impact_point;
  if (d.mesh.grading) {
    d.mesh.grading->size_at_impact = size_at_impact(d);
    impact_point.x = d.impactor.x;
    impact_point.y = d.impactor.y;
  }
  d.impactor = impact_point;
  d.contact.k.reset();
  d.memory_limit_bytes.reset(); // the memory free when the deck was read: a guard, not the plate
  return d;
}

bool same_mesh_file(const ImpactCaseDescription& a, const ImpactCaseDescription& b) {
  if (!a.mesh_from_file || !b.mesh_from_file) return a.mesh_from_file == b.mesh_from_file;
  return *a.mesh_from_file == *b.mesh_from_file;
}

} // namespace

bool same_plate(const ImpactCaseDescription& a, const ImpactCaseDescription& b) {
  if (!same_mesh_file(a, b)) return false;
  ImpactCaseDescription pa = plate_part(a), pb = plate_part(b);
  pa.mesh_from_file = pb.mesh_from_file = nullptr; // compared above, by content
  return pa == pb;
}

double expected_contact_radius(const ImpactCaseDescription& d) {
  return expected_contact_radius(d.impactor, resolved_contact_stiffness(d));
}

double size_at_impact(const ImpactCaseDescription& d) {
  if (!d.mesh.grading) return 0.0;
  if (d.mesh.grading->size_at_impact) return *d.mesh.grading->size_at_impact;
  // The expected radius rounded down to a step of 2^(1/4) from 1 mm: cases of a sweep whose impactors
  // differ a little share their mesh (and factorization), whatever the order they run in.
  const double steps = std::floor(4.0 * std::log2(expected_contact_radius(d) / 1e-3));
  const double automatic = 1e-3 * std::exp2(steps / 4.0);
  // mesh.max_size caps every element, this one too (issue 77: 0.5 mm asked, 1 to 2.5 mm given)
  return d.mesh.grading->max_size ? std::min(automatic, *d.mesh.grading->max_size) : automatic;
}

Mesh impact_mesh(const ImpactCaseDescription& d) {
  if (d.mesh_from_file) return *d.mesh_from_file;
  if (!d.mesh.grading) return structured_rectangle(d.plate, d.mesh.nx, d.mesh.ny);
  const MeshGrading& g = *d.mesh.grading;
  const double h0 = size_at_impact(d);
  const double h_max = std::max(h0, g.max_size.value_or(std::min(d.plate.a, d.plate.b) / 10.0));
  // The impact point at `impact_offset` in its element, the sizes growing away from it.
  return structured_rectangle(d.plate,
                              graded_lines(d.plate.a, d.impactor.x, h0, g.growth, g.impact_offset[0], h_max),
                              graded_lines(d.plate.b, d.impactor.y, h0, g.growth, g.impact_offset[1], h_max));
}

DiscretePlate impact_plate_model(const ImpactCaseDescription& d) {
  if (d.laminates.empty()) throw std::invalid_argument("impact: the case has no laminate");
  if (d.plate.rigid) return {d.laminates.front(), d.plate, MeshSpec{1, 1}, d.boundary};
  Mesh mesh = impact_mesh(d);
  std::vector<int> of_element = element_laminates(mesh, d.regions);
  return {std::move(mesh), PlateSections{d.laminates, std::move(of_element)},
          Discretization{d.mesh.mass, d.mesh.element}, d.boundary};
}

ImpactCase::ImpactCase(ImpactCaseDescription description)
    : description_(within_memory(supported(std::move(description)))),
      model_(std::make_unique<DiscretePlate>(impact_plate_model(description_))) {
  std::unique_ptr<const MechanicalModel> explicit_plate = explicit_model(description_, *model_);
  std::shared_ptr<const ScaledMass> explicit_mass = naming_singular_causes(
      description_, [&] { return explicit_case_mass(description_, explicit_plate.get()); });
  const std::optional<StableStepSource> stable_step =
      highest_mode(description_, explicit_plate.get(), explicit_mass.get());
  if (stable_step) explicit_omega_max_ = stable_step->omega_max;
  settings_ = resolved_settings(description_, explicit_omega_max_);
  settings_.stable_step = stable_step;
  if (explicit_mass && explicit_mass->report.kind != MassScalingKind::none)
    settings_.mass_scaling = explicit_mass->report;
  require_bilateral(description_.boundary, "an impact");
  settings_.mesh = mesh_used(*model_, description_.mesh.grading.has_value() && !settings_.rigid_target);
  if (!(settings_.dt > 0.0)) throw std::invalid_argument("impact: time step must be positive");
  check_end_after_first_step(settings_.dt, settings_.end); // before the factorization
  if (!(settings_.impactor.mass > 0.0)) throw std::invalid_argument("impact: impactor mass must be positive");
  if (settings_.rigid_target) {
    policy_ = rigid_target_policy();
    return;
  }
  StepPolicyOptions options;
  options.newmark = NewmarkCoefficients(settings_.dt, settings_.newmark_beta, settings_.newmark_gamma);
  options.load = settings_.contact.load;
  options.solver = description_.solver;
  options.ordering = description_.ordering;
  options.memory_limit_bytes = description_.memory_limit_bytes;
  options.explicit_omega_max = explicit_omega_max_;
  options.explicit_mass = std::move(explicit_mass);
  naming_singular_causes(description_, [&] {
    policy_ = step_policy(*model_, options, plate_physics(description_), std::move(explicit_plate));
  });
  if (!settings_.end) {                                              // for the end-of-event rule
    fundamental_period_ = naming_singular_causes(description_, [&] { // the time loop's matrices, if held
      return policy_->stiffness() ? plyimpact::fundamental_period(*policy_->stiffness(), *policy_->mass())
                                  : plyimpact::fundamental_period(*model_);
    });
  }
}

ImpactCase::~ImpactCase() = default;

namespace {

/// c of the separation rule (SE1): the undamaged plate's deflection at the impact point under a unit
/// force there, toward the impactor (against +z: with unilateral supports the plate may lift off them) [m/N].
double impact_point_compliance(const DiscretePlate& model, const Impactor& imp) {
  StaticLoad unit;
  unit.point = PointLoad{imp.x, imp.y, -1.0};
  try {
    return -solve_static(model, unit).load_point_deflection;
  } catch (const InsufficientRestraint& e) {
    throw std::invalid_argument(fmt::format(
        "time.end = \"separation\" bounds the plate's rise by its static compliance at the impact point, and "
        "this plate has none: {}. Use time.end = \"auto\" (the re-hit rule) or a time",
        e.what()));
  }
}

} // namespace

ImpactResult ImpactCase::run(const RunRequest& request) const {
  const ElementThreads threads(request.threads);
  const Impactor imp = request.impactor.value_or(settings_.impactor);
  const double k = request.contact_stiffness.value_or(settings_.k);
  if (!(imp.mass > 0.0)) throw std::invalid_argument("impact: impactor mass must be positive");
  LoopSettings loop;
  loop.dt = settings_.dt;
  loop.end = settings_.end;
  loop.newmark_beta = settings_.newmark_beta;
  loop.newmark_gamma = settings_.newmark_gamma;
  loop.max_steps = settings_.max_steps;
  loop.stop_at_energy_error = settings_.stop_at_energy_error;
  loop.adaptive = settings_.adaptive;
  loop.fundamental_period = fundamental_period_;
  if (!settings_.end && settings_.end_rule == EventEnd::separation)
    loop.separation_compliance = settings_.rigid_target ? 0.0 : impact_point_compliance(*model_, imp);
  loop.cancel = request.cancel;
  loop.keep_failed_run = request.keep_failed_run;
  loop.contact_point_response = request.contact_point_response && request.observers.empty() &&
                                request.history_every == 0 && request.field_times.empty();
  if (!settings_.rigid_target && !settings_.nonlinear)
    loop.linear_thickness = impacted_laminate(description_).thickness();
  // Guards that warn (docs/robustness.md): a Δt too coarse for the contact, an impact point on an
  // element boundary. (An error-controlled run chooses its own steps below dt.)
  if (!settings_.adaptive)
    if (auto w = time_step_warning(imp.mass, imp.velocity, k, settings_.dt, contact_exponent(imp.nose)))
      loop.warnings.push_back(std::move(*w));
  if (!settings_.rigid_target) {
    // A point force on an element boundary loads whichever element holds it; the Hertz pressure is
    // integrated over every element its circle touches and needs no such warning.
    if (settings_.contact.load == ContactLoad::point)
      if (auto w = impact_point_warning(model_->mesh(), imp.x, imp.y)) loop.warnings.push_back(std::move(*w));
    if (auto w = contact_mesh_warning(model_->mesh(), imp.x, imp.y, expected_contact_radius(imp, k),
                                      settings_.contact.load))
      loop.warnings.push_back(std::move(*w));
  }
  const std::vector<std::string>& policy_warnings = policy_->warnings();
  loop.warnings.insert(loop.warnings.end(), policy_warnings.begin(), policy_warnings.end());

  std::vector<ImpactObserver*> observers = request.observers;
  HistoryRecorder history(request.history_every);
  FieldRecorder fields(request.field_times);
  if (request.history_every > 0) observers.push_back(&history);
  if (!request.field_times.empty()) observers.push_back(&fields);

  ImpactResult r = naming_singular_causes(
      description_, [&] { return run_impact_loop(*policy_, imp, k, settings_.contact, loop, observers); });
  r.history = std::move(history.samples());
  r.fields = std::move(fields.fields());
  if (settings_.mass_scaling)
    if (auto why = added_mass_suspicion(*settings_.mass_scaling)) {
      r.suspect = true;
      r.suspect_reason = r.suspect_reason.empty() ? *why : r.suspect_reason + "; " + *why;
      r.warnings.push_back(std::move(*why));
    }
  if (settings_.mass_scaling && r.delamination && r.progressive) {
    const PerDamageMode& by_mode = r.progressive->dissipated;
    if (auto w = selective_scaling_after_drop_warning(
            settings_.mass_scaling->interface_factor, r.delamination->projected_area,
            by_mode[DamageMode::fibre_tension] + by_mode[DamageMode::fibre_compression]))
      r.warnings.push_back(std::move(*w));
  }
  return r;
}

} // namespace plyimpact
