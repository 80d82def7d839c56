#include "plyimpact/io/results/laminate_report.hpp"

#include "plyimpact/analysis/contact/contact_rules.hpp"
#include "plyimpact/io/deck/json_text.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace plyimpact {

double contact_stiffness(const Deck& d) {
  if (d.contact.k) return *d.contact.k;
  return automatic_contact_stiffness(*d.impactor, *d.laminate); // SPEC §4, E2 of the impacted ply
}

namespace {

nlohmann::json matrix_json(const auto& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      row.push_back(m(i, j));
    rows.push_back(row);
  }
  return rows;
}

/// Round-off below `rel` × `scale` printed as 0 (e.g. B of a symmetric laminate is 1e-16 of A·h).
double clean(double x, double scale, double rel = 1e-12) {
  return std::abs(x) <= rel * scale ? 0.0 : x;
}

std::string matrix_text(const std::string& name, const auto& m, double scale, const std::string& unit) {
  std::string s = fmt::format("  {} [{}]\n", name, unit);
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    s += "    ";
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      s += fmt::format("{:>14.6g}", clean(m(i, j), scale));
    s += "\n";
  }
  return s;
}

} // namespace

std::string laminate_report_text(const Deck& d) {
  const Laminate& L = *d.laminate;
  std::string s;
  if (!d.title.empty()) s += d.title + "\n";
  s += "Materials\n";
  s += fmt::format("  {:<14}{:>10}{:>10}{:>10}{:>10}{:>10}{:>9}{:>12}\n", "name", "E1[GPa]", "E2[GPa]",
                   "G12[GPa]", "G13[GPa]", "G23[GPa]", "nu12[-]", "rho[kg/m3]");
  for (const Material& m : L.materials())
    s += fmt::format("  {:<14}{:>10.4g}{:>10.4g}{:>10.4g}{:>10.4g}{:>10.4g}{:>9.3g}{:>12.6g}\n", m.name,
                     m.E1 / 1e9, m.E2 / 1e9, m.G12 / 1e9, m.G13 / 1e9, m.G23 / 1e9, m.nu12, m.rho);
  s += fmt::format(
      "\nLaminate {}  ({} plies, h = {:.4f} mm, K = {:.6g}{})\n",
      d.laminate_spec ? d.laminate_spec->layup : "", L.ply_count(), L.thickness() * 1e3, L.shear_correction(),
      L.stiffness_model() == ReducedStiffnessModel::poisson_free ? ", Poisson-free Q (thesis program)" : "");
  s += "  ply 1 is the impacted face (z = -h/2); z points in the impact direction\n";
  if (d.laminate_spec && d.laminate_spec->reference_angle != 0.0)
    s += fmt::format(
        "  the layup's 0 deg lies at {:.6g} deg from the plate's x axis (reference_direction); the "
        "angles below are in the plate's axes\n",
        d.laminate_spec->reference_angle);
  s += fmt::format("  {:>4}{:>11}{:>14}{:>14}{:>14}  {}\n", "ply", "angle[deg]", "t[mm]", "z_top[mm]",
                   "z_bottom[mm]", "material");
  for (std::size_t k = 0; k < L.ply_count(); ++k)
    s += fmt::format("  {:>4}{:>11.6g}{:>14.5f}{:>14.5f}{:>14.5f}  {}\n", k + 1, L.plies()[k].angle_deg,
                     L.plies()[k].thickness * 1e3, clean(L.z_top(k), L.thickness()) * 1e3,
                     clean(L.z_bottom(k), L.thickness()) * 1e3, L.material_of(k).name);
  s += "\nStiffness\n";
  const double h = L.thickness();
  const double a_max = L.A().cwiseAbs().maxCoeff();
  s += matrix_text("A", L.A(), a_max, "N/m");
  s += matrix_text("B", L.B(), a_max * h, "N");
  s += matrix_text("D", L.D(), a_max * h * h, "N*m");
  s += matrix_text("F (yz, xz)", L.F(), L.F().cwiseAbs().maxCoeff(), "N/m");
  const auto e = L.engineering_constants();
  s += fmt::format("\n  Ex = {:.5g} GPa, Ey = {:.5g} GPa, Gxy = {:.5g} GPa, nuxy = {:.4g}\n", e.Ex / 1e9,
                   e.Ey / 1e9, e.Gxy / 1e9, e.nuxy);
  s += fmt::format("  symmetric (B = 0): {}, balanced (A16 = A26 = 0): {}\n", L.is_symmetric() ? "yes" : "no",
                   L.is_balanced() ? "yes" : "no");
  const auto& I = L.inertia();
  s += fmt::format("\nInertia  I0 = {:.6g} kg/m2, I1 = {:.6g} kg/m, I2 = {:.6g} kg\n", I[0],
                   clean(I[1], I[0] * L.thickness()), I[2]);
  if (d.impactor) {
    s +=
        fmt::format("\nImpactor m = {:.6g} kg, R = {:.4g} mm, E = {:.4g} GPa, nu = {:.3g}, v0 = {:.4g} m/s\n",
                    d.impactor->mass, d.impactor->radius * 1e3, d.impactor->E / 1e9, d.impactor->nu,
                    d.impactor->velocity);
    s += fmt::format("  contact stiffness k = {:.6g} {} ({})\n", contact_stiffness(d),
                     contact_constant_unit(d.impactor->nose),
                     d.contact.k ? "given" : "modified Hertz, docs/deck.md [contact] k");
  }
  return s;
}

std::string laminate_report_json(const Deck& d) {
  const Laminate& L = *d.laminate;
  nlohmann::json j;
  j["thickness"] = L.thickness();
  j["layup"] = d.laminate_spec ? d.laminate_spec->layup : "";
  j["shear_correction"] = L.shear_correction();
  j["plies"] = nlohmann::json::array();
  for (std::size_t k = 0; k < L.ply_count(); ++k)
    j["plies"].push_back({{"angle_deg", L.plies()[k].angle_deg},
                          {"thickness", L.plies()[k].thickness},
                          {"z_top", L.z_top(k)},
                          {"z_bottom", L.z_bottom(k)},
                          {"material", L.material_of(k).name}});
  j["A"] = matrix_json(L.A());
  j["B"] = matrix_json(L.B());
  j["D"] = matrix_json(L.D());
  j["F"] = matrix_json(L.F());
  j["inertia"] = {L.inertia()[0], L.inertia()[1], L.inertia()[2]};
  const auto e = L.engineering_constants();
  j["engineering_constants"] = {{"Ex", e.Ex}, {"Ey", e.Ey}, {"Gxy", e.Gxy}, {"nuxy", e.nuxy}};
  j["symmetric"] = L.is_symmetric();
  j["balanced"] = L.is_balanced();
  if (d.impactor) j["hertz_k"] = contact_stiffness(d);
  return json_text(j, 2) + "\n";
}

} // namespace plyimpact
