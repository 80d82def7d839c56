#include "plyimpact/io/results/impact_text_report.hpp"

#include "plyimpact/fem/stacked_plate.hpp"
#include "plyimpact/io/results/damage_report.hpp"
#include "plyimpact/io/results/impact_report.hpp"
#include "plyimpact/io/results/laminate_report.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <numbers>

namespace plyimpact {
namespace {

std::string heading(const std::string& title) {
  return fmt::format("\n{}\n{}\n", title, std::string(title.size(), '-'));
}

std::string mesh_section(const DiscretePlate& model) {
  const Mesh& mesh = model.mesh();
  const DofMap& dofs = model.dofs();
  int restrained_nodes = 0;
  for (int n = 0; n < mesh.node_count(); ++n)
    for (int d = 0; d < dofs_per_node; ++d)
      if (dofs.equation(n, d) < 0) {
        ++restrained_nodes;
        break;
      }
  std::string s = heading("PLATE AND MESH");
  const BoundingBox& box = mesh.bounds();
  s += fmt::format("  plate a x b                 {:.4f} x {:.4f} mm\n", (box.x_max - box.x_min) * 1e3,
                   (box.y_max - box.y_min) * 1e3);
  const std::string grid =
      mesh.grid() ? fmt::format("{} x {} = ", mesh.grid()->nx, mesh.grid()->ny) : std::string();
  s += fmt::format("  elements                    {}{} ({}), 9 nodes each\n", grid, mesh.element_count(),
                   model.formulation() == ElementFormulation::mitc9 ? "MITC9" : "Q9");
  if (!model.single_section())
    s += fmt::format("  laminates                   {} (regions of [[region]])\n", model.laminates().size());
  s += fmt::format("  nodal points                {}\n", mesh.node_count());
  s += fmt::format("  restrained nodes            {}\n", restrained_nodes);
  s += fmt::format("  equations                   {} (5 DOF per node: u v w thetax thetay)\n",
                   dofs.free_count());
  s += fmt::format("  mass matrix                 {}\n",
                   model.mass_kind() == MassMatrix::lumped ? "lumped (Lobatto)" : "consistent");
  s += "  restraint codes (u v w thetax thetay; 1 = held)\n";
  for (const SetRestraint& r : model.boundary().sets)
    s += fmt::format("    edge {:<3}                  {}\n", r.set, resolve_restraint(mesh, r).code());
  if (model.boundary().corners)
    s += fmt::format("    corners                   {}\n", model.boundary().corners->code());
  return s;
}

std::string integrator_words(Integrator i) {
  switch (i) {
  case Integrator::implicit:
    return "implicit (Newmark)";
  case Integrator::lagged:
    return "lagged (Newmark, the ply laws a step behind)";
  case Integrator::central_difference:
    return "explicit (central differences, lumped mass)";
  }
  return "";
}

/// The plate model's physics: kinematics, ply damage and the interfaces that may delaminate.
std::string model_section(const ImpactSettings& s) {
  std::string t = heading("PLATE MODEL");
  t += fmt::format("  kinematics                  {}\n",
                   s.nonlinear ? "large deflections (von Karman)" : "linear (small deflections)");
  t += fmt::format("  ply damage                  {}\n",
                   s.progressive_damage ? "progressive (docs/progressive_damage.md)" : "none");
  if (!s.delamination) return t + "  delamination                none (one laminate)\n";
  const std::vector<int> after = interfaces_after_ply(s.delamination->stack.cuts);
  return t + fmt::format("  delamination                {} cohesive interfaces, under plies {}\n",
                         after.size(), fmt::join(after, ", "));
}

std::string impactor_section(const ImpactSettings& s, bool stable_step_pending) {
  const Impactor& i = s.impactor;
  std::string t = heading("IMPACTOR AND CONTACT");
  t += fmt::format("  impactor mass               {:.6g} kg\n", i.mass);
  if (i.nose == NoseShape::cone)
    t += fmt::format("  impactor nose               cone, half-angle {:.6g} deg\n",
                     i.half_angle * 180.0 / std::numbers::pi);
  else if (i.nose == NoseShape::flat)
    t += fmt::format("  impactor nose               flat, radius {:.6g} mm\n", i.radius * 1e3);
  else
    t += fmt::format("  impactor radius             {:.6g} mm\n", i.radius * 1e3);
  t += fmt::format("  impactor E, nu              {:.6g} GPa, {:.4g}\n", i.E * 1e-9, i.nu);
  t += fmt::format("  initial velocity            {:.6g} m/s ({:.6g} J)\n", i.velocity,
                   0.5 * i.mass * i.velocity * i.velocity);
  t += fmt::format("  impact point (x, y)         ({:.4f}, {:.4f}) mm\n", i.x * 1e3, i.y * 1e3);
  if (i.nose == NoseShape::hemisphere)
    t += fmt::format("  Hertz contact constant k    {:.5e} N/m^1.5\n", s.k);
  else
    t += fmt::format("  contact constant k          {:.5e} {} (F = k alpha^{:g})\n", s.k,
                     contact_constant_unit(i.nose), contact_exponent(i.nose));
  t += fmt::format("  unloading                   {}",
                   s.contact.unloading == UnloadingLaw::tan_sun ? "Tan-Sun" : "elastic");
  if (s.contact.unloading == UnloadingLaw::tan_sun)
    t += fmt::format(" (q = {:.4g}, beta = {:.4g}, alpha_cr = {:.4g} mm)", s.contact.q, s.contact.beta,
                     s.contact.alpha_cr * 1e3);
  t += fmt::format("\n  contact load                {}\n",
                   s.contact.load == ContactLoad::point ? "point force" : "Hertz pressure");
  t += heading("TIME STEPPING");
  if (stable_step_pending)
    t += fmt::format(
        "  time increment dt           at most {:.6g} us: the explicit stable step 0.9 * 2/omega_max, "
        "found when the run starts\n",
        s.dt * 1e6);
  else
    t += fmt::format("  time increment dt           {:.6g} us\n", s.dt * 1e6);
  t += fmt::format("  Newmark beta, gamma         {:.4g}, {:.4g}\n", s.newmark_beta, s.newmark_gamma);
  t += s.end ? fmt::format("  end                         {:.6g} us\n", *s.end * 1e6)
             : std::string("  end                         automatic (SPEC section 4)\n");
  t += fmt::format("  integrator                  {}\n", integrator_words(s.integration));
  return t + model_section(s);
}

std::string displacement_section(const DiscretePlate& model, const NodalSnapshot& snap) {
  std::string s = heading(fmt::format("DISPLACEMENTS AT t = {:.4f} us", snap.t * 1e6));
  s += fmt::format("  {:>6} {:>10} {:>10} {:>13} {:>13} {:>13} {:>13} {:>13}\n", "node", "x[mm]", "y[mm]",
                   "u[m]", "v[m]", "w[m]", "thetax[rad]", "thetay[rad]");
  const Eigen::VectorXd full = model.to_nodal(snap.u);
  for (int n = 0; n < model.mesh().node_count(); ++n) {
    const Eigen::Vector2d& p = model.mesh().node(n);
    s += fmt::format("  {:6d} {:10.4f} {:10.4f}", n + 1, p.x() * 1e3, p.y() * 1e3);
    for (int d = 0; d < dofs_per_node; ++d)
      s += fmt::format(" {:13.5e}", full(n * dofs_per_node + d));
    s += "\n";
  }
  return s;
}

} // namespace

std::string plate_input_text(const Deck& deck, const DiscretePlate& model) {
  std::string s = fmt::format("deck: {}\n", deck.source);
  if (!deck.rig_description.empty()) s += fmt::format("rig: {}\n", deck.rig_description);
  return s + heading("MATERIALS AND LAMINATE") + laminate_report_text(deck) + mesh_section(model);
}

std::string impact_input_text(const Deck& deck, const DiscretePlate& model, const ImpactSettings& settings,
                              bool stable_step_pending) {
  return plate_input_text(deck, model) + impactor_section(settings, stable_step_pending);
}

std::string impact_report_text(const Deck& deck, const DiscretePlate& model, const ImpactSettings& settings,
                               const ImpactResult& result, const std::vector<DamageOnset>& first_failures,
                               const std::vector<int>& clamp_tip_elements,
                               const std::optional<DamageOnset>& laminate_first_failure,
                               const std::optional<NodalSnapshot>& displacements) {
  std::string s =
      fmt::format("***** plyimpact {}: IMPACT ANALYSIS OF A LAMINATED PLATE *****\n", PLYIMPACT_VERSION);
  s += impact_input_text(deck, model, settings);
  s += heading("RESULTS") + impact_summary_text(settings, result);
  s += heading("FIRST FAILURES");
  s += deck.damage.criteria.empty() ? std::string("  no failure criteria requested ([damage] criteria)\n")
       : first_failures.empty()
           ? std::string("  none: no criterion reached 1\n")
           : first_failures_text(first_failures, clamp_tip_elements, laminate_first_failure);
  if (displacements) s += displacement_section(model, *displacements);
  return s;
}

} // namespace plyimpact
