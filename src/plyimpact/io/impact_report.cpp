#include "plyimpact/io/impact_report.hpp"

#include "plyimpact/io/plate_from_deck.hpp"

#include "plyimpact/io/laminate_report.hpp"
#include "plyimpact/io/system_memory.hpp"

#include <fmt/format.h>

#include <cmath>

namespace plyimpact {

double automatic_time_step(double mass, double k, double velocity) {
  const double contact_time = 3.21807 * std::pow(mass * mass / (k * k * velocity), 0.2);
  const double dt = contact_time / 1000.0;
  const double scale = std::pow(10.0, std::floor(std::log10(dt)) - 1.0);
  return std::floor(dt / scale) * scale;
}

ImpactSettings impact_settings_from_deck(const Deck& deck) {
  ImpactSettings s;
  s.impactor = *deck.impactor;
  s.k = contact_stiffness(deck);
  s.contact = deck.contact;
  s.dt = deck.time.dt ? *deck.time.dt : automatic_time_step(s.impactor.mass, s.k, s.impactor.velocity);
  s.end = deck.time.end;
  s.newmark_beta = deck.time.newmark_beta;
  s.newmark_gamma = deck.time.newmark_gamma;
  s.max_steps = deck.time.max_steps;
  s.rigid_target = deck.plate && deck.plate->rigid;
  s.field_times = deck.field_times;
  s.history_every = deck.history_every;
  s.memory_limit_bytes = available_memory_bytes(); // factorization guard (docs/robustness.md)
  return s;
}

nlohmann::json impact_summary_json(const Deck& deck, const ImpactSettings& s, const ImpactResult& r) {
  nlohmann::json j = summary_header(deck, "impact");
  j["peak_force"] = r.peak_force;
  j["time_of_peak_force"] = r.time_of_peak_force;
  j["contact_duration"] = r.contact_duration;
  j["episodes"] = nlohmann::json::array();
  for (const auto& e : r.episodes)
    j["episodes"].push_back({{"start", e.start}, {"end", e.end}, {"peak_force", e.peak_force}});
  j["peak_contact_deflection"] = r.peak_contact_deflection;
  j["max_indentation"] = r.max_indentation;
  j["permanent_indentation"] = r.permanent_indentation;
  j["rebound_velocity"] = r.rebound_velocity;
  j["absorbed_energy"] = r.absorbed_energy;
  j["contact_dissipation"] = r.contact_dissipation;
  j["initial_energy"] = 0.5 * s.impactor.mass * s.impactor.velocity * s.impactor.velocity;
  j["contacts"] = r.episodes.size();
  j["steps"] = r.steps;
  j["dt"] = s.dt;
  j["end_time"] = r.history.empty() ? 0.0 : r.history.back().t;
  j["complete"] = r.complete;
  if (!r.stop_reason.empty()) j["stop_reason"] = r.stop_reason;
  j["warnings"] = r.warnings; // guards: coarse Δt, impact point on an element boundary
  j["wall_time"] = r.wall_time;
  j["contact_stiffness"] = s.k;
  j["impactor_mass"] = s.impactor.mass;
  j["impact_velocity"] = s.impactor.velocity;
  j["fundamental_period"] = r.fundamental_period;
  j["equations"] = r.dofs;
  j["inplane_dofs_eliminated"] = r.inplane_eliminated;
  j["newton_iterations_max"] = r.newton_iterations_max;
  return j;
}

PlateModel impact_model_from_deck(const Deck& deck, bool rigid_target) {
  if (rigid_target)
    return {*deck.laminate, *deck.plate, MeshSpec{1, 1}, deck.boundary.value_or(BoundaryConditions{})};
  return plate_from_deck(deck);
}

DamageOptions damage_options_from_deck(const Deck& deck) {
  DamageOptions d;
  d.every = deck.damage.every;
  d.criterion_options.delamination_ply_n =
      deck.damage.delamination_ply_n_lower ? DelaminationPlyN::lower : DelaminationPlyN::upper;
  return d;
}

std::string impact_history_csv(const ImpactResult& r) {
  std::string csv = "t_s,force_N,impactor_w_m,impactor_v_m_per_s,plate_w_m,indentation_m,plate_kinetic_J,"
                    "plate_strain_J,impactor_energy_J,contact_work_J\n";
  for (const auto& h : r.history)
    csv += fmt::format("{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e}\n", h.t,
                       h.force, h.impactor_w, h.impactor_v, h.plate_w, h.indentation, h.plate_kinetic,
                       h.plate_strain, h.impactor_energy, h.contact_work);
  return csv;
}

std::string impact_summary_text(const ImpactSettings& s, const ImpactResult& r) {
  std::string t;
  t += fmt::format(
      "impact: m = {:.4g} kg, v0 = {:.4g} m/s, k = {:.4g} N/m^1.5, dt = {:.4g} us, {} equations{}\n",
      s.impactor.mass, s.impactor.velocity, s.k, s.dt * 1e6, r.dofs,
      r.inplane_eliminated ? " (in-plane DOFs decoupled, left out)" : "");
  t += fmt::format("  peak force              {:12.2f} N at {:.2f} us\n", r.peak_force,
                   r.time_of_peak_force * 1e6);
  t += fmt::format("  contact duration        {:12.2f} us (first contact; {} contact(s))\n",
                   r.contact_duration * 1e6, r.episodes.size());
  t += fmt::format("  peak plate deflection   {:12.4f} mm at the contact point\n",
                   r.peak_contact_deflection * 1e3);
  t += fmt::format("  max indentation         {:12.4f} mm, permanent {:.4f} mm\n", r.max_indentation * 1e3,
                   r.permanent_indentation * 1e3);
  t += fmt::format("  rebound velocity        {:12.4f} m/s\n", r.rebound_velocity);
  t += fmt::format("  absorbed energy         {:12.4f} J of {:.4f} J (contact dissipation {:.4f} J)\n",
                   r.absorbed_energy, 0.5 * s.impactor.mass * s.impactor.velocity * s.impactor.velocity,
                   r.contact_dissipation);
  t += fmt::format("  steps                   {:12d} to t = {:.1f} us, wall time {:.3f} s{}\n", r.steps,
                   r.history.empty() ? 0.0 : r.history.back().t * 1e6, r.wall_time,
                   r.complete ? "" : "  INCOMPLETE");
  if (!r.stop_reason.empty()) t += "  " + r.stop_reason + "\n";
  return t;
}

void write_impact_results(const ResultsFolder& folder, const Deck& deck, const PlateModel* model,
                          const ImpactSettings& s, const ImpactResult& r,
                          const std::function<void(nlohmann::json&)>& extend) {
  folder.write_text("history.csv", impact_history_csv(r));
  if (model != nullptr)
    for (const auto& f : r.fields)
      folder.write_nodal_field(fmt::format("field_t{:.6e}.csv", f.t), *model, f.u);
  nlohmann::json j = impact_summary_json(deck, s, r);
  if (extend) extend(j);
  folder.write_json("summary.json", j); // last: its presence marks a finished write
}

} // namespace plyimpact
