#include "plyimpact/io/run/plate_analyses.hpp"

#include "plyimpact/analysis/plate_analyses/buckling_analysis.hpp"
#include "plyimpact/analysis/plate_analyses/modal_analysis.hpp"
#include "plyimpact/analysis/plate_analyses/nonlinear_static.hpp"
#include "plyimpact/analysis/plate_analyses/static_analysis.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/results/vtk_output.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iterator>

namespace plyimpact {

namespace {

/// ParaView options of the deck's [output] vtk* keys (no failure criteria outside an impact).
VtkOptions vtk_options(const Deck& deck) {
  return {deck.vtk.plies, deck.vtk.interfaces, deck.vtk.thickness_scale, {}, {}};
}

/// A deflection in metres, or what it is when the point is not on the plate (the centre of an annulus).
std::string deflection_text(double w) {
  return std::isfinite(w) ? fmt::format("{:.6e} m", w) : "none (the point is not on the plate)";
}

void print_deflections(std::string& text, double center, double load_point, double max_abs) {
  auto out = std::back_inserter(text);
  fmt::format_to(out, "  center_deflection     = {}\n", deflection_text(center));
  fmt::format_to(out, "  load_point_deflection = {}\n", deflection_text(load_point));
  fmt::format_to(out, "  max_abs_deflection    = {}\n", deflection_text(max_abs));
}

/// null where the point is not on the plate.
nlohmann::json deflection_value(double w) {
  return std::isfinite(w) ? nlohmann::json(w) : nlohmann::json(nullptr);
}

void put_deflections(nlohmann::json& j, double center, double load_point, double max_abs) {
  j["center_deflection"] = deflection_value(center);
  j["load_point_deflection"] = deflection_value(load_point);
  j["max_abs_deflection"] = deflection_value(max_abs);
}

/// The unilateral supports at the solution: how many nodes touch, how far the plate lifts off, the force.
void report_support_contacts(std::string& text, nlohmann::json& j, const StaticResult& r) {
  if (r.support_contacts.empty()) return;
  const int touching = touching_count(r.support_contacts);
  const auto nodes = static_cast<int>(r.support_contacts.size());
  fmt::format_to(std::back_inserter(text),
                 "  unilateral support: {} of {} nodes touch, {} lifted off (largest lift-off {:.6e} m), "
                 "support force {:.6e} N, {} solves\n",
                 touching, nodes, nodes - touching, largest_lift_off(r.support_contacts),
                 total_reaction(r.support_contacts), r.contact_set_solves);
  j["support_nodes"] = nodes;
  j["support_touching_nodes"] = touching;
  j["support_max_lift_off"] = largest_lift_off(r.support_contacts);
  j["support_reaction"] = total_reaction(r.support_contacts);
  j["contact_set_solves"] = r.contact_set_solves;
}

/// support_contacts.csv: one row per node of the unilateral supports.
std::string support_contacts_csv(const DiscretePlate& model, const std::vector<SupportContact>& contacts) {
  std::string csv = "node,x_m,y_m,touching,reaction_N,w_m\n";
  for (const SupportContact& c : contacts) {
    const Eigen::Vector2d p = model.mesh().node(c.node);
    fmt::format_to(std::back_inserter(csv), "{},{:.9e},{:.9e},{},{:.9e},{:.9e}\n", c.node, p.x(), p.y(),
                   c.touching ? 1 : 0, c.reaction, c.w);
  }
  return csv;
}

/// Large-deflection static analysis (SPEC §8): load stepping with Newton–Raphson.
AnalysisOutcome run_static_nonlinear(const Deck& deck, const std::optional<ResultsFolder>& folder) {
  const DiscretePlate model = plate_model(deck);
  const NonlinearStaticResult r = solve_static_nonlinear(model, *deck.load, deck.nonlinear_settings);
  AnalysisOutcome out;
  out.text = fmt::format(
      "static, non-linear ({}): {} elements, {} free DOFs, {} load steps, {} Newton iterations, {} step "
      "cuts\n",
      to_string(deck.nonlinear_settings.measure), model.mesh().element_count(), model.size(),
      r.load_deflection.size() - 1, r.newton_iterations, r.step_cuts);
  print_deflections(out.text, r.state.center_deflection, r.state.load_point_deflection,
                    r.state.max_abs_deflection);
  nlohmann::json& j = out.summary = summary_header(deck, "static");
  j["nonlinear"] = true;
  j["strain_measure"] = to_string(deck.nonlinear_settings.measure);
  put_deflections(j, r.state.center_deflection, r.state.load_point_deflection, r.state.max_abs_deflection);
  j["load_deflection"] = r.load_deflection;
  j["newton_iterations"] = r.newton_iterations;
  j["step_cuts"] = r.step_cuts;
  j["dofs"] = model.size();
  if (folder) {
    folder->write_nodal_field("displacements.csv", model, r.state.u);
    if (deck.vtk.enabled) write_static_vtk(folder->path(), model, r.state.u, vtk_options(deck));
    folder->write_summary(j);
  }
  return out;
}

} // namespace

AnalysisOutcome run_static_analysis(const Deck& deck, bool nonlinear,
                                    const std::optional<ResultsFolder>& folder) {
  if (nonlinear || deck.nonlinear) return run_static_nonlinear(deck, folder);
  const DiscretePlate model = plate_model(deck);
  const StaticResult r = solve_static(model, *deck.load);
  AnalysisOutcome out;
  out.text = fmt::format("static: {} elements, {} free DOFs\n", model.mesh().element_count(), model.size());
  if (!deck.rig_description.empty()) out.text += fmt::format("  rig: {}\n", deck.rig_description);
  print_deflections(out.text, r.center_deflection, r.load_point_deflection, r.max_abs_deflection);
  nlohmann::json& j = out.summary = summary_header(deck, "static");
  put_deflections(j, r.center_deflection, r.load_point_deflection, r.max_abs_deflection);
  report_support_contacts(out.text, j, r);
  j["dofs"] = model.size();
  if (folder) {
    folder->write_nodal_field("displacements.csv", model, r.u);
    if (!r.support_contacts.empty())
      folder->write_text("support_contacts.csv", support_contacts_csv(model, r.support_contacts));
    if (deck.vtk.enabled) write_static_vtk(folder->path(), model, r.u, vtk_options(deck));
    folder->write_summary(j);
  }
  return out;
}

AnalysisOutcome run_modal_analysis(const Deck& deck, const std::optional<ResultsFolder>& folder) {
  const DiscretePlate model = plate_model(deck);
  const ModalResult r = solve_modal(model, deck.modal.count);
  AnalysisOutcome out;
  out.text = fmt::format("modal: {} elements, {} free DOFs, {} zero-energy modes (rigid-body or spurious)\n",
                         model.mesh().element_count(), model.size(), r.zero_energy_modes);
  for (std::size_t k = 0; k < r.frequencies_hz.size(); ++k)
    fmt::format_to(std::back_inserter(out.text), "  mode {:>3}: {:12.4f} Hz\n", k + 1, r.frequencies_hz[k]);
  nlohmann::json& j = out.summary = summary_header(deck, "modal");
  j["frequencies_hz"] = r.frequencies_hz;
  j["zero_energy_modes"] = r.zero_energy_modes;
  if (folder) {
    folder->write_mode_shapes("modes.csv", model, r.modes, "mode");
    if (deck.vtk.enabled) write_modes_vtk(folder->path(), model, r.modes, vtk_options(deck));
    folder->write_summary(j);
  }
  return out;
}

AnalysisOutcome run_buckling_analysis(const Deck& deck, const std::optional<ResultsFolder>& folder) {
  const DiscretePlate model = plate_model(deck);
  const BucklingResult r = solve_buckling(model, *deck.buckling);
  const BucklingSettings& b = *deck.buckling;
  AnalysisOutcome out;
  out.text =
      fmt::format("buckling: reference load Nx = {} N/m, Ny = {} N/m, Nxy = {} N/m\n", b.Nx, b.Ny, b.Nxy);
  for (std::size_t k = 0; k < r.load_factors.size(); ++k)
    fmt::format_to(std::back_inserter(out.text), "  mode {:>3}: load factor {:12.6g}  (Nx_cr = {:.6g} N/m)\n",
                   k + 1, r.load_factors[k], r.load_factors[k] * b.Nx);
  nlohmann::json& j = out.summary = summary_header(deck, "buckling");
  j["load_factors"] = r.load_factors;
  j["reference_load"] = {{"Nx", b.Nx}, {"Ny", b.Ny}, {"Nxy", b.Nxy}};
  if (folder) {
    folder->write_mode_shapes("modes.csv", model, r.modes, "buckling");
    if (deck.vtk.enabled) write_modes_vtk(folder->path(), model, r.modes, vtk_options(deck));
    folder->write_summary(j);
  }
  return out;
}

} // namespace plyimpact
