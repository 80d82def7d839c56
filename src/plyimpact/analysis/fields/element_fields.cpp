#include "plyimpact/analysis/fields/element_fields.hpp"

#include "plyimpact/analysis/fields/stress_recovery.hpp"
#include "plyimpact/fem/quadrature.hpp"

#include <algorithm>
#include <limits>
#include <set>
#include <tuple>

namespace plyimpact {
namespace {

/// Heights of the N − 1 interfaces, from the top.
std::vector<double> interface_heights(const Laminate& lam) {
  std::vector<double> z;
  for (std::size_t k = 0; k + 1 < lam.ply_count(); ++k)
    z.push_back(lam.z_bottom(k));
  return z;
}

/// A criterion's index for a ply, or 0 when the ply's material lacks a strength it needs.
double ply_index(Criterion c, const PlyStress& s, const Material& m, const CriterionOptions& options) {
  if (!missing_strengths(c, m.strength).empty()) return 0.0;
  return evaluate(c, s, m, options).index;
}

double interface_index(Criterion c, const PlyStress& upper, const Material& mu, const PlyStress& lower,
                       const Material& ml, const CriterionOptions& options) {
  if (!missing_strengths(c, mu.strength).empty() || !missing_strengths(c, ml.strength).empty()) return 0.0;
  return choi_chang_delamination(upper, mu.strength, lower, ml.strength, options.delamination_ply_n).index;
}

} // namespace

ElementCentreFields element_centre_fields(const DiscretePlate& model, const Eigen::VectorXd& u,
                                          const std::vector<Criterion>& criteria,
                                          const CriterionOptions& options) {
  const Mesh& mesh = model.mesh();
  ElementCentreFields f;
  f.elements = mesh.element_count();
  for (const Laminate& l : model.laminates())
    f.plies = std::max(f.plies, static_cast<int>(l.ply_count()));
  f.criteria = criteria;
  const auto E = std::size_t(f.elements), N = std::size_t(f.plies);
  // A ply or interface that an element's laminate does not have (regions with fewer plies) is NaN.
  constexpr double none = std::numeric_limits<double>::quiet_NaN();
  f.ply_stress.assign(N * E, PlyStress{none, none, none, none, none});
  f.interface_shear.assign((N - 1) * E, Eigen::Vector2d(none, none));
  f.index.assign(criteria.size() * N * E, none);
  for (int e = 0; e < f.elements; ++e) {
    const Laminate& lam = model.laminate_of(e);
    const std::size_t plies = lam.ply_count();
    const std::vector<double> z_interfaces = interface_heights(lam);
    const ElementCoordinates xy = mesh.element_coordinates(e);
    const ElementVector ue = model.element_dofs(u, e);
    const GeneralizedStrains strains = model.element().strains(xy, ue, 0.0, 0.0);
    for (std::size_t k = 0; k < plies; ++k)
      f.ply_stress[k * E + std::size_t(e)] =
          to_material_axes(ply_average_stress(lam, k, strains), lam.plies()[k].angle_deg);
    if (plies > 1) {
      // Equilibrium shear scaled to the constitutive resultants Q = F γ (SPEC §5).
      const Eigen::Vector2d Q = lam.F() * strains.shear;
      const std::vector<Eigen::Vector2d> tau =
          equilibrium_transverse_shear(lam, strain_gradients(xy, ue, 0.0, 0.0), Q, z_interfaces);
      for (std::size_t i = 0; i + 1 < plies; ++i)
        f.interface_shear[i * E + std::size_t(e)] = tau[i];
    }
    for (std::size_t c = 0; c < criteria.size(); ++c)
      for (std::size_t k = 0; k < plies; ++k) {
        double& index = f.index[(c * N + k) * E + std::size_t(e)];
        if (!is_interface_criterion(criteria[c]))
          index = ply_index(criteria[c], f.ply_stress[k * E + std::size_t(e)], lam.material_of(k), options);
        else
          index = k + 1 < plies
                      ? interface_index(criteria[c], f.ply_stress[k * E + std::size_t(e)], lam.material_of(k),
                                        f.ply_stress[(k + 1) * E + std::size_t(e)], lam.material_of(k + 1),
                                        options)
                      : 0.0;
      }
  }
  return f;
}

DamageFractions damage_fractions(const std::vector<DamageOnset>& onsets, int elements, int plies, double t) {
  DamageFractions d;
  d.elements = elements;
  const auto E = std::size_t(elements), N = std::size_t(plies);
  d.ply.assign(N * E, 0.0);
  d.interface.assign(N > 0 ? (N - 1) * E : 0, 0.0);
  // A Gauss point counts once per layer whatever the number of criteria it failed in.
  std::set<std::tuple<int, int, int, int, int>> seen; // (is interface, layer, element, ipgs, jpgs)
  for (const DamageOnset& o : onsets) {
    if (o.time > t) continue;
    const bool ply = o.ply > 0;
    const int layer = (ply ? o.ply : o.interface) - 1;
    if (!seen.insert({ply ? 0 : 1, layer, o.element, o.ipgs, o.jpgs}).second) continue;
    auto& v = ply ? d.ply : d.interface;
    v[std::size_t(layer) * E + std::size_t(o.element - 1)] += 1.0; // failed points, divided below
  }
  // Counted, then divided once: nine additions of 1/9 gave 1.0000000000000002 for a whole element.
  const double points = static_cast<double>(gauss3x3.size());
  for (auto* v : {&d.ply, &d.interface})
    for (double& f : *v)
      f = std::min(f / points, 1.0);
  return d;
}

} // namespace plyimpact
