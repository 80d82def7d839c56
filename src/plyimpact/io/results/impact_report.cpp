#include "plyimpact/io/results/impact_report.hpp"

#include "plyimpact/analysis/fields/energy_split.hpp"
#include "plyimpact/analysis/thresholds/delamination_shape.hpp"

#include "plyimpact/fem/dof_map.hpp"
#include "plyimpact/io/results/history_csv.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace plyimpact {

namespace {

/// summary.json `end_of_event`: the rule that decides the end, and where the separation rule ended it.
nlohmann::json end_of_event_json(const ImpactResult& r) {
  const char* rule = r.end_rule == EventEndRule::time         ? "time.end"
                     : r.end_rule == EventEndRule::separation ? "separation"
                                                              : "re-hit";
  nlohmann::json j = {{"rule", rule}, {"separation", nullptr}};
  if (const auto& e = r.separation_end)
    j["separation"] = {{"time_s", e->time},
                       {"impactor_gap_m", e->impactor_gap},
                       {"plate_amplitude_bound_m", e->amplitude_bound},
                       {"plate_energy_J", e->plate_energy},
                       {"compliance_m_per_N", e->compliance}};
  return j;
}

/// A value that may not apply: JSON null when empty, never a 0 that reads like a result.
nlohmann::json or_null(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

nlohmann::json or_null(const std::string& text) {
  return text.empty() ? nlohmann::json(nullptr) : nlohmann::json(text);
}

/// x to three significant digits: an error estimate, whose further digits are rounding noise.
double three_digits(double x) {
  return std::strtod(fmt::format("{:.3g}", x).c_str(), nullptr);
}

/// Why the rebound velocity and absorbed energy are not given.
std::string not_given(const ImpactResult& r) {
  return r.episodes.empty() ? "   not given (no contact)"
                            : "   not given (the impactor has not left the plate)";
}

/// summary.json `load_drop` (docs/output.md): the delamination threshold load F_d as a lab reads it; null
/// where the run kept no samples to read it from.
nlohmann::json load_drop_json(const ImpactResult& r) {
  if (!r.force_history) return nullptr;
  const std::optional<LoadDrop>& drop = r.force_history->load_drop;
  nlohmann::json j = {{"rule",
                       "the largest force before the force's running median over a tenth of the first "
                       "contact's loading phase first falls by 5 % (analysis/thresholds/load_drop.hpp)"}};
  j["force_N"] = drop ? nlohmann::json(drop->force) : nlohmann::json(nullptr);
  j["time_s"] = drop ? nlohmann::json(drop->time) : nlohmann::json(nullptr);
  j["detected_at_s"] = drop ? nlohmann::json(drop->detected) : nlohmann::json(nullptr);
  return j;
}

/// The text line of the first load drop (none where the run kept no samples).
std::string load_drop_text(const ImpactResult& r) {
  if (!r.force_history) return {};
  if (const std::optional<LoadDrop>& drop = r.force_history->load_drop)
    return fmt::format(
        "  first load drop (F_d)   {:12.2f} N at {:.2f} us (smoothed force 5 % lower at {:.2f} us)\n",
        drop->force, drop->time * 1e6, drop->detected * 1e6);
  return "  first load drop (F_d)           none (the smoothed force never fell by 5 % while loading)\n";
}

/// Per interface, the shape of its delaminated area (analysis/thresholds/delamination_shape.hpp) against the
/// fibres of the ply below it.
nlohmann::json shapes_json(const DelaminationResult& d) {
  nlohmann::json shapes = nlohmann::json::array();
  const std::vector<DelaminationShape> of_interface = delamination_shapes(d);
  for (std::size_t i = 0; i < of_interface.size(); ++i) {
    const DelaminationShape& s = of_interface[i];
    nlohmann::json j;
    j["after_ply"] = d.interface_after_ply[i];
    j["ply_below_angle_deg"] = d.angle_below_deg[i];
    j["area_m2"] = s.area;
    j["axis_deg"] = s.axis_deg ? nlohmann::json(*s.axis_deg) : nlohmann::json();
    j["aspect_ratio"] =
        s.aspect_ratio && std::isfinite(*s.aspect_ratio) ? nlohmann::json(*s.aspect_ratio) : nlohmann::json();
    j["axis_to_fibre_deg"] = s.axis_deg
                                 ? nlohmann::json(angle_between_lines_deg(*s.axis_deg, d.angle_below_deg[i]))
                                 : nlohmann::json();
    shapes.push_back(std::move(j));
  }
  return shapes;
}

/// The stacked plate's interfaces (docs/delamination.md): the law, the areas, the energy, the zone.
nlohmann::json delamination_json(const DelaminationSettings& s, Integrator integration,
                                 const DelaminationResult& d, const std::optional<NewtonStatistics>& newton) {
  const CohesiveParameters& law = s.stack.interface;
  nlohmann::json j;
  j["interfaces_after_ply"] = d.interface_after_ply;
  j["delaminated_area_m2"] = d.delaminated_area;
  j["process_zone_area_m2"] = d.process_zone_area;
  j["projected_delaminated_area_m2"] = d.projected_area;
  j["dissipated_energy_J"] = d.dissipated;
  j["shapes"] = shapes_json(d);
  j["cohesive_zone_length_m"] = d.cohesive_zone_length;
  j["interface_point_spacing_m"] = d.interface_point_spacing;
  j["penalty_stiffness_Pa_per_m"] = law.penalty_stiffness;
  j["cracked_closing_fraction"] = law.cracked_closing_fraction; // (DL10)
  j["normal_strength_Pa"] = law.normal_strength;
  j["shear_strength_Pa"] = law.shear_strength;
  j["G_Ic_J_per_m2"] = law.G_Ic;
  j["G_IIc_J_per_m2"] = law.G_IIc;
  j["bk_exponent"] = law.bk_exponent;
  j["law_defaults"] = nlohmann::json::object(); // the values the deck left out, and where they came from
  for (const auto& [key, origin] : s.law_defaults)
    j["law_defaults"][key] = origin;
  j["onset"] = law.onset == CohesiveOnset::turon_bk ? "turon-bk" : "camanho-quadratic";
  j["points"] = s.stack.rule == CohesiveQuadrature::nodal ? "nodal" : "gauss";
  j["supports"] = s.supports_on_all ? "all" : "bottom";
  if (s.stack.seed_radius > 0.0) j["seed_radius_m"] = s.stack.seed_radius;
  j["integration"] = std::string(to_string(integration));
  if (newton) {
    j["iterations"] = newton->iterations;
    j["max_iterations_per_step"] = newton->max_iterations_per_step;
    j["factorizations"] = newton->factorizations;
    j["factor_updates"] = newton->factor_updates;
  }
  return j;
}

std::string millimetres_squared(const std::vector<double>& areas) {
  std::string list;
  for (const double a : areas)
    list += fmt::format("{}{:.1f}", list.empty() ? "" : ", ", a * 1e6);
  return list;
}

/// One line per damage mode that appeared, in the order they appeared (report.txt).
std::string first_damage_by_mode_text(const ProgressiveDamageResult& pd) {
  std::vector<DamageMode> seen;
  for (const DamageMode m : all_damage_modes)
    if (pd.first_by_mode[m]) seen.push_back(m);
  const auto first = [&](DamageMode m) { return *pd.first_by_mode[m]; };
  std::stable_sort(seen.begin(), seen.end(),
                   [&](DamageMode a, DamageMode b) { return first(a).time < first(b).time; });
  std::string text;
  for (const DamageMode m : seen)
    text += fmt::format("    {:<20} first in ply {} at {:.2f} us, {:.1f} N\n", to_string(m), first(m).ply,
                        first(m).time * 1e6, first(m).force);
  return text;
}

/// The law's values that the deck left out, one line each with its origin; empty where it gave all.
std::string law_defaults_text(const DelaminationSettings& s) {
  const CohesiveParameters& law = s.stack.interface;
  std::string t;
  for (const auto& [key, origin] : s.law_defaults) {
    const double value = key == "G_Ic"              ? law.G_Ic
                         : key == "G_IIc"           ? law.G_IIc
                         : key == "bk_exponent"     ? law.bk_exponent
                         : key == "normal_strength" ? law.normal_strength * 1e-6
                                                    : law.shear_strength * 1e-6;
    const char* unit = key == "G_Ic" || key == "G_IIc" ? " J/m^2" : key == "bk_exponent" ? "" : " MPa";
    t += fmt::format("    {:<16} {:.4g}{} not in the deck: {}\n", key, value, unit, origin);
  }
  return t;
}

std::string delamination_text(const DelaminationSettings& s, const DelaminationResult& d) {
  std::string plies;
  for (const int p : d.interface_after_ply)
    plies += fmt::format("{}{}", plies.empty() ? "" : ", ", p);
  std::string t;
  const CohesiveParameters& law = s.stack.interface;
  t += fmt::format("  delamination            {:12d} interface(s), after plies {}; K = {:.3g} Pa/m{}\n",
                   d.interface_after_ply.size(), plies, law.penalty_stiffness,
                   law.cracked_closing_fraction < 1.0
                       ? fmt::format(", cracked faces close on {:g} K", law.cracked_closing_fraction)
                       : std::string());
  t += law_defaults_text(s);
  t += fmt::format("  delaminated area        {:12.2f} mm^2 projected; per interface {} mm^2 (softening {} "
                   "mm^2)\n",
                   d.projected_area * 1e6, millimetres_squared(d.delaminated_area),
                   millimetres_squared(d.process_zone_area));
  t += fmt::format("  delamination energy     {:12.4f} J dissipated by the interfaces\n", d.dissipated);
  const std::vector<DelaminationShape> shapes = delamination_shapes(d);
  for (std::size_t i = 0; i < shapes.size(); ++i)
    if (shapes[i].axis_deg && shapes[i].aspect_ratio)
      t += fmt::format(
          "    shape after ply {:<3}  long axis {:.1f} deg (ply below {:g} deg), aspect ratio {:.2f}\n",
          d.interface_after_ply[i], *shapes[i].axis_deg, d.angle_below_deg[i], *shapes[i].aspect_ratio);
  t += fmt::format("  cohesive zone           {:12.3f} mm, interface points {:.3f} mm apart\n",
                   d.cohesive_zone_length * 1e3, d.interface_point_spacing * 1e3);
  return t;
}

/// The largest kinetic energy of the added mass as a fraction of the impact energy (0 without).
double added_energy_fraction(const ImpactSettings& s, const ImpactResult& r) {
  const double e0 = 0.5 * s.impactor.mass * s.impactor.velocity * s.impactor.velocity;
  return r.added_mass_kinetic_energy && e0 > 0.0 ? *r.added_mass_kinetic_energy / e0 : 0.0;
}

/// summary.json `absorbed_energy_by_mechanism` (docs/output.md, analysis/fields/energy_split.hpp): null until
/// the impactor has left.
/// One lowered strength: what, of which material, by how much, and the first element that uses it.
nlohmann::json lowered_strength_json(const std::optional<LoweredStrength>& l) {
  if (!l) return nullptr;
  return {{"strength", l->strength}, {"material", l->material}, {"reduction_percent", 100.0 * l->reduction()},
          {"deck_Pa", l->deck},      {"used_Pa", l->used},      {"element", l->element},
          {"x_m", l->centre.x()},    {"y_m", l->centre.y()}};
}

/// A lowered strength's reduction in percent, 0 where none was lowered.
double reduction_percent(const std::optional<LoweredStrength>& l) {
  return l ? 100.0 * l->reduction() : 0.0;
}

/// The strengths lowered to band limits (issue 79): how many elements, the largest reduction, and the
/// largest where the plies damaged.
nlohmann::json strength_reduction_json(const StrengthReduction& r) {
  return {{"elements_lowered", r.elements},
          {"largest_percent", reduction_percent(r.largest)},
          {"largest_where_damaged_percent", reduction_percent(r.largest_where_damaged)},
          {"largest", lowered_strength_json(r.largest)},
          {"largest_where_damaged", lowered_strength_json(r.largest_where_damaged)}};
}

nlohmann::json absorbed_by_mechanism_json(const ImpactResult& r) {
  const std::optional<AbsorbedEnergySplit> split = absorbed_energy_split(r);
  if (!split) return nullptr;
  return {{"contact_J", split->contact},
          {"ply_damage_J", split->ply_damage},
          {"delamination_J", split->delamination},
          {"plate_vibration_J", split->plate_vibration},
          {"unaccounted_J", split->unaccounted}};
}

/// summary.json `mass_scaling` (docs/output.md): what was added, per sub-laminate, and what it carried.
nlohmann::json mass_scaling_json(const MassScalingReport& m, const ImpactSettings& s, const ImpactResult& r) {
  return {{"kind", to_string(m.kind)},
          {"target_dt_s", m.target_dt},
          {"scaled_nodes", m.scaled_nodes},
          {"largest_factor", m.largest_factor},
          {"mass_kg", m.mass_kg},
          {"added_mass_kg", m.added_mass_kg},
          {"rotary_inertia_kg_m2", m.rotary_inertia_kg_m2},
          {"added_rotary_inertia_kg_m2", m.added_rotary_inertia_kg_m2},
          {"interface_mass_factor", m.interface_factor},
          {"added_kinetic_energy_max_J", or_null(r.added_mass_kinetic_energy)},
          {"added_kinetic_energy_fraction", added_energy_fraction(s, r)}};
}

} // namespace

nlohmann::json impact_summary_json(const Deck& deck, const ImpactSettings& s, const ImpactResult& r) {
  nlohmann::json j = summary_header(deck, "impact");
  j["peak_force"] = r.peak_force;
  j["time_of_peak_force"] = r.time_of_peak_force;
  j["load_drop"] = load_drop_json(r);
  j["contact_duration"] = r.contact_duration;
  j["episodes"] = nlohmann::json::array();
  for (const auto& e : r.episodes)
    j["episodes"].push_back({{"start", e.start}, {"end", e.end}, {"peak_force", e.peak_force}});
  j["peak_contact_deflection"] = r.peak_contact_deflection;
  j["max_indentation"] = r.max_indentation;
  j["permanent_indentation"] = r.permanent_indentation;
  j["rebound_velocity"] = or_null(r.rebound_velocity);
  j["absorbed_energy"] = or_null(r.absorbed_energy);
  j["contact_dissipation"] = r.contact_dissipation;
  j["absorbed_energy_by_mechanism"] = absorbed_by_mechanism_json(r);
  j["initial_energy"] = 0.5 * s.impactor.mass * s.impactor.velocity * s.impactor.velocity;
  j["contacts"] = r.episodes.size();
  j["steps"] = r.steps;
  j["dt"] = s.dt;
  j["integration"] = std::string(to_string(s.integration)); // the plate's integrator (capabilities.hpp)
  if (s.stable_step) { // central differences: what sets the stable step (step_policy.hpp)
    const StableStepSource& source = *s.stable_step;
    j["stable_step"] = {{"omega_max_rad_per_s", source.omega_max},
                        {"stable_step_s", stable_time_step(source.omega_max)},
                        {"highest_mode_at",
                         {{"sublaminate", source.place.sublaminate + 1},
                          {"dof", dof_name(source.place.dof)},
                          {"x_m", source.xy.x()},
                          {"y_m", source.xy.y()}}}};
  }
  if (s.mass_scaling) j["mass_scaling"] = mass_scaling_json(*s.mass_scaling, s, r);
  j["end_time"] = r.end_time;
  j["end_of_event"] = end_of_event_json(r);
  j["complete"] = r.complete;
  j["incomplete_reason"] = or_null(r.incomplete_reason);
  if (!r.stop_reason.empty()) j["stop_reason"] = r.stop_reason;
  j["energy_balance_error"] = three_digits(r.energy_balance_error);
  j["suspect"] = r.suspect;
  j["suspect_reason"] = or_null(r.suspect_reason);
  j["warnings"] = deck.warnings;          // plausibility of the deck (deck_plausibility.hpp), then the run's
  for (const std::string& w : r.warnings) // guards.hpp: coarse Δt, mesh, cut-short or suspect run, w/h
    j["warnings"].push_back(w);
  j["wall_time"] = r.wall_time;
  j["contact_stiffness"] = s.k;
  j["impactor_mass"] = s.impactor.mass;
  j["impact_velocity"] = s.impactor.velocity;
  j["fundamental_period"] = or_null(r.fundamental_period);
  j["equations"] = r.dofs;
  j["mesh"] = {{"elements", s.mesh.elements},
               {"element", to_string(s.mesh.element)},
               {"graded", s.mesh.graded},
               {"smallest_element_m", s.mesh.smallest_element},
               {"largest_element_m", s.mesh.largest_element}};
  j["contact_load"] = to_string(s.contact.load);
  j["inplane_dofs_eliminated"] = r.inplane_eliminated;
  j["newton_iterations_max"] = r.newton_iterations_max;
  if (r.progressive && r.newton) { // ply damage (docs/progressive_damage.md)
    const ProgressiveDamageResult& pd = *r.progressive;
    nlohmann::json d;
    d["model"] = "progressive";
    d["integration"] = std::string(to_string(s.integration));
    d["dissipated_energy"] = pd.dissipated.sum();
    for (const DamageMode m : all_damage_modes)
      d["dissipated_energy_by_mode"][std::string(to_string(m))] = pd.dissipated[m];
    d["projected_damage_area"] = pd.projected_damage_area;
    d["ply_damage_area"] = pd.ply_damage_area;
    d["area_threshold"] = s.progressive_damage->area_threshold;
    d["first_damage"] = nullptr;
    if (const auto first = pd.first())
      d["first_damage"] = {{"mode", std::string(to_string(*pd.first_mode))},
                           {"ply", first->ply},
                           {"time", first->time},
                           {"contact_force", first->force}};
    for (const DamageMode m : all_damage_modes) {
      const auto& first = pd.first_by_mode[m];
      d["first_damage_by_mode"][std::string(to_string(m))] =
          first ? nlohmann::json{{"ply", first->ply}, {"time", first->time}, {"contact_force", first->force}}
                : nlohmann::json(nullptr);
    }
    d["active_elements"] = pd.active_elements;
    d["strength_reduction"] = strength_reduction_json(pd.strength_reduction);
    d["iterations"] = r.newton->iterations;
    d["max_iterations_per_step"] = r.newton->max_iterations_per_step;
    d["factorizations"] = r.newton->factorizations;
    j["damage"] = d;
  }
  if (r.delamination && s.delamination) { // the stacked plate's interfaces (docs/delamination.md)
    j["delamination"] = delamination_json(*s.delamination, s.integration, *r.delamination, r.newton);
    if (r.force_history) {
      const std::optional<FirstDelamination>& grew = r.force_history->first_delamination;
      j["delamination"]["first_growth"] =
          grew ? nlohmann::json{{"time_s", grew->time}, {"force_N", grew->force}} : nlohmann::json(nullptr);
    }
  }
  if (r.time_steps) { // error-controlled steps (docs/deck.md, [time] adaptive)
    const AdaptiveStepResult& a = *r.time_steps;
    j["time_steps"] = {{"adaptive", true},
                       {"tolerance", a.tolerance},
                       {"largest_dt", a.largest_dt},
                       {"smallest_allowed_dt", a.smallest_allowed_dt},
                       {"smallest_used_dt", a.smallest_used_dt},
                       {"rejected_steps", a.rejected_steps},
                       {"steps_above_tolerance", a.steps_above_tolerance},
                       {"largest_error_ratio", a.largest_error_ratio},
                       {"factorizations", a.factorizations}};
  }
  if (s.nonlinear && r.newton) { // large deflections (docs/nonlinear.md)
    j["nonlinear"] = true;
    j["strain_measure"] = to_string(s.nonlinear->measure);
    j["newton_iterations"] = r.newton->iterations;
    j["max_newton_iterations_per_step"] = r.newton->max_iterations_per_step;
    j["factorizations"] = r.newton->factorizations;
  }
  return j;
}

std::string impact_history_csv(const ImpactResult& r) {
  std::string csv = history_csv_header(history_layout(r));
  for (const auto& h : r.history)
    csv += history_csv_row(h);
  return csv;
}

std::string impact_summary_text(const ImpactSettings& s, const ImpactResult& r) {
  std::string t;
  t += fmt::format("impact: m = {:.4g} kg, v0 = {:.4g} m/s, k = {:.4g} {}, dt = {:.4g} us, {} equations{}\n",
                   s.impactor.mass, s.impactor.velocity, s.k, contact_constant_unit(s.impactor.nose),
                   s.dt * 1e6, r.dofs, r.inplane_eliminated ? " (in-plane DOFs decoupled, left out)" : "");
  t += fmt::format("  mesh: {} {} elements{}, {:.3g} to {:.3g} mm; contact load {}\n", s.mesh.elements,
                   to_string(s.mesh.element), s.mesh.graded ? " graded toward the impact point" : "",
                   s.mesh.smallest_element * 1e3, s.mesh.largest_element * 1e3, to_string(s.contact.load));
  if (s.stable_step)
    t += fmt::format(
        "  stable step: {:.4g} us (0.9 x 2/omega_max, omega_max = {:.4g} rad/s); the highest mode "
        "is largest at {}\n",
        stable_time_step(s.stable_step->omega_max) * 1e6, s.stable_step->omega_max,
        stable_step_place_text(*s.stable_step, s.delamination.has_value()));
  if (s.mass_scaling) {
    t += "  " + mass_scaling_text(*s.mass_scaling) + "\n";
    if (r.added_mass_kinetic_energy)
      t += fmt::format("  added mass: largest kinetic energy {:.4g} J ({:.3g} % of the impact energy)\n",
                       *r.added_mass_kinetic_energy, 100.0 * added_energy_fraction(s, r));
  }
  t += fmt::format("  peak force              {:12.2f} N at {:.2f} us\n", r.peak_force,
                   r.time_of_peak_force * 1e6);
  t += load_drop_text(r);
  t += fmt::format("  contact duration        {:12.2f} us (first contact; {} contact(s))\n",
                   r.contact_duration * 1e6, r.episodes.size());
  t += fmt::format("  peak plate deflection   {:12.4f} mm at the contact point\n",
                   r.peak_contact_deflection * 1e3);
  t += fmt::format("  max indentation         {:12.4f} mm, permanent {:.4f} mm\n", r.max_indentation * 1e3,
                   r.permanent_indentation * 1e3);
  const double e0 = 0.5 * s.impactor.mass * s.impactor.velocity * s.impactor.velocity;
  t += "  rebound velocity        " +
       (r.rebound_velocity ? fmt::format("{:12.4f} m/s", *r.rebound_velocity) : not_given(r)) + "\n";
  t += "  absorbed energy         " +
       (r.absorbed_energy ? fmt::format("{:12.4f} J of {:.4f} J", *r.absorbed_energy, e0) : not_given(r)) +
       fmt::format(" (contact dissipation {:.4f} J)\n", r.contact_dissipation);
  if (const std::optional<AbsorbedEnergySplit> split = absorbed_energy_split(r))
    t += fmt::format(
        "  absorbed by mechanism   contact {:.4f} J, ply damage {:.4f} J, delamination {:.4f} J, "
        "plate vibration {:.4f} J (unaccounted {:.2g} J)\n",
        split->contact, split->ply_damage, split->delamination, split->plate_vibration, split->unaccounted);
  if (r.progressive) {
    const ProgressiveDamageResult& pd = *r.progressive;
    t += fmt::format("  ply damage dissipation  {:12.4f} J (fibre tension {:.4f}, fibre compression {:.4f}, "
                     "matrix tension {:.4f}, matrix compression {:.4f})\n",
                     pd.dissipated.sum(), pd.dissipated[DamageMode::fibre_tension],
                     pd.dissipated[DamageMode::fibre_compression], pd.dissipated[DamageMode::matrix_tension],
                     pd.dissipated[DamageMode::matrix_compression]);
    t += fmt::format("  projected damage area   {:12.2f} mm^2 (points with d >= {})\n",
                     pd.projected_damage_area * 1e6, s.progressive_damage->area_threshold);
    const auto first = pd.first();
    t += first ? fmt::format("  first ply damage        {:>12} in ply {} at {:.2f} us, {:.1f} N\n",
                             to_string(*pd.first_mode), first->ply, first->time * 1e6, first->force)
               : std::string("  first ply damage                none\n");
    t += first_damage_by_mode_text(pd);
    if (const auto& l = pd.strength_reduction.largest)
      t += fmt::format("  strengths lowered       {:12d} elements, by up to {:.1f} % ({} of '{}'); where the "
                       "plies damaged by up to {:.1f} %\n",
                       pd.strength_reduction.elements, reduction_percent(l), l->strength, l->material,
                       reduction_percent(pd.strength_reduction.largest_where_damaged));
    if (s.integration == Integrator::central_difference)
      t += fmt::format("  damage step                 explicit: no solve, dt = {:.4g} us\n", s.dt * 1e6);
    else if (r.newton)
      t += fmt::format("  damage iterations       {:12d} solves in {} steps (at most {} in a step), {} "
                       "factorizations of K_s + c0 M\n",
                       r.newton->iterations, r.steps, r.newton->max_iterations_per_step,
                       r.newton->factorizations);
  }
  if (r.delamination && s.delamination) t += delamination_text(*s.delamination, *r.delamination);
  if (r.force_history && r.force_history->first_delamination)
    t += fmt::format("  delamination first grew at {:.2f} us, contact force {:.2f} N\n",
                     r.force_history->first_delamination->time * 1e6,
                     r.force_history->first_delamination->force);
  t += fmt::format("  energy balance error    {:12.3g} % of {:.4f} J{}\n", 100.0 * r.energy_balance_error, e0,
                   r.suspect ? "  SUSPECT" : "");
  t += fmt::format("  steps                   {:12d} to t = {:.1f} us, wall time {:.3f} s{}\n", r.steps,
                   r.end_time * 1e6, r.wall_time, r.complete ? "" : "  INCOMPLETE");
  if (const auto& e = r.separation_end)
    t += fmt::format(
        "  ended at separation     impactor {:.3g} um above the plate's reach of {:.3g} um (plate "
        "energy {:.3g} J, compliance {:.3g} m/N)\n",
        e->impactor_gap * 1e6, e->amplitude_bound * 1e6, e->plate_energy, e->compliance);
  if (r.time_steps)
    t += fmt::format(
        "  adaptive steps          {:12.3g} to {:.3g} us (allowed {:.3g} to {:.3g}), {} redone, {} "
        "factorizations, largest error {:.3g} of the bound\n",
        r.time_steps->smallest_used_dt * 1e6, r.time_steps->largest_dt * 1e6,
        r.time_steps->smallest_allowed_dt * 1e6, r.time_steps->largest_dt * 1e6, r.time_steps->rejected_steps,
        r.time_steps->factorizations, r.time_steps->largest_error_ratio);
  if (!r.incomplete_reason.empty()) t += "  incomplete: " + r.incomplete_reason + "\n";
  if (r.suspect) t += "  suspect: " + r.suspect_reason + "\n";
  return t;
}

void write_impact_results(const ResultsFolder& folder, const DiscretePlate* model, const ImpactResult& r,
                          const nlohmann::json& summary) {
  if (model != nullptr)
    for (const auto& f : r.fields)
      folder.write_nodal_field(fmt::format("field_t{:.6e}.csv", f.t), *model, f.u);
  folder.write_summary(summary); // last: its presence marks a finished write
}

} // namespace plyimpact
