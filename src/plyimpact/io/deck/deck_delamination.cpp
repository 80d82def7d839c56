// [delamination] (docs/deck.md, docs/delamination.md): where the laminate may delaminate, the cohesive law
// of its interfaces, and how the stacked plate is held and stepped.
#include "plyimpact/analysis/impact/capabilities.hpp"
#include "plyimpact/fem/stacked_plate.hpp"
#include "plyimpact/io/deck/deck_tables.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace plyimpact::deck_tables {

namespace {

/// "orientation-changes" (the default) or a list of 1-based plies after which the laminate is cut,
/// returned as split_laminate's 0-based cuts.
std::vector<int> read_interfaces(const TableReader& t, const Laminate& laminate) {
  const int plies = static_cast<int>(laminate.ply_count());
  const toml::node* n = t.node("interfaces");
  if (n == nullptr || (n->as_string() != nullptr && n->as_string()->get() == "orientation-changes")) {
    std::vector<int> cuts = interfaces_between_orientations(laminate);
    if (!cuts.empty()) return cuts;
    const std::string why = "[delamination]: every ply of the layup has the same orientation, so there is no "
                            "interface between plies of different orientation to cut: list the interfaces, "
                            "e.g. interfaces = [2] for a cut after ply 2";
    if (n != nullptr) t.fail_at("interfaces", why);
    t.fail_here(why);
  }
  const toml::array* list = n->as_array();
  if (list == nullptr || list->empty())
    t.fail_at("interfaces", "delamination.interfaces must be \"orientation-changes\" or a list of the plies "
                            "after which the laminate may delaminate, e.g. [2, 4] (1 = the impacted ply)");
  std::vector<int> cuts;
  for (const toml::node& item : *list) {
    const auto* i = item.as_integer();
    if (i == nullptr)
      fail(t.file(), item.source(),
           fmt::format("delamination.interfaces: expected ply numbers (integers), got {}", type_name(item)));
    const long after = i->get();
    if (after < 1 || after >= plies)
      fail(t.file(), item.source(),
           fmt::format("delamination.interfaces: {} is not an interface of the {}-ply laminate: an interface "
                       "lies after ply 1 to {} (1 = the impacted ply)",
                       after, plies, plies - 1));
    if (!cuts.empty() && after - 1 <= cuts.back())
      fail(t.file(), item.source(),
           "delamination.interfaces must be listed once each, from the impacted face down (increasing)");
    cuts.push_back(static_cast<int>(after - 1));
  }
  return cuts;
}

/// The five values of the interface law: the deck's, else what the plies at the interfaces give
/// (interface_values_from_plies), Turon's shear strength and the default B-K exponent. Refuses a table
/// for which some remain unknown, naming all of them in one message (a user who left out three should not
/// meet them one run at a time) with the ply data that would give them. `defaults` receives the values
/// taken from elsewhere than the deck, with their origin.
CohesiveParameters law_values(const TableReader& t, const Laminate& laminate, const std::vector<int>& cuts,
                              std::vector<std::pair<std::string, std::string>>& defaults) {
  const PlyInterfaceValues plies = interface_values_from_plies(laminate, cuts);
  std::vector<std::string> missing;
  // `fallback` NaN: none.
  const auto value = [&](const char* key, const char* unit, double fallback, const char* origin,
                         const char* what) {
    if (t.has(key)) return t.positive(key, unit);
    if (!std::isnan(fallback)) {
      defaults.emplace_back(key, origin);
      return fallback;
    }
    missing.push_back(fmt::format("{} ({})", key, what));
    return 0.0;
  };
  CohesiveParameters law;
  law.G_Ic = value("G_Ic", "J/m^2", plies.G_Ic.value_or(NAN), "G_mt of the plies at the interfaces",
                   "mode I toughness, J/m^2; or G_mt of every ply at an interface");
  law.G_IIc = value("G_IIc", "J/m^2", plies.G_IIc.value_or(NAN), "G_mc of the plies at the interfaces",
                    "mode II toughness, J/m^2; or G_mc of every ply at an interface");
  law.bk_exponent = value("bk_exponent", "-", default_bk_exponent,
                          "IM7/8552 carbon/epoxy (Camanho et al. 2013)", "Benzeggagh-Kenane exponent eta, -");
  law.normal_strength =
      value("normal_strength", "Pa", plies.normal_strength.value_or(NAN), "Yt of the plies at the interfaces",
            "interlaminar tensile strength, Pa; or Yt of every ply at an interface");
  const double turon = law.normal_strength > 0.0 && law.G_Ic > 0.0 && law.G_IIc > 0.0
                           ? turon_shear_strength(law.normal_strength, law.G_Ic, law.G_IIc)
                           : NAN;
  law.shear_strength =
      value("shear_strength", "Pa", turon, "normal_strength x sqrt(G_IIc / G_Ic) (Turon et al. 2010)",
            "interlaminar shear strength, Pa; or the three values it follows from");
  if (!missing.empty())
    t.fail_here(
        fmt::format("[delamination] needs the interface law's 5 values; {} unknown: {} (the deck gives "
                    "them, or the ply data they follow from: docs/deck.md, \"[delamination]\"; "
                    "docs/delamination.md, \"Values from the plies\")",
                    missing.size(), fmt::join(missing, ", ")));
  return law;
}

CohesiveParameters read_law(const TableReader& t, const Laminate& laminate, const std::vector<int>& cuts,
                            std::vector<std::pair<std::string, std::string>>& defaults) {
  CohesiveParameters law = law_values(t, laminate, cuts, defaults);
  law.onset =
      t.optional_choice<CohesiveOnset>("onset", {{"turon-bk", CohesiveOnset::turon_bk},
                                                 {"camanho-quadratic", CohesiveOnset::camanho_quadratic}})
          .value_or(CohesiveOnset::turon_bk);
  law.penalty_stiffness =
      t.positive_or_auto("penalty_stiffness", "Pa/m").value_or(turon_penalty_stiffness(laminate, cuts));
  try {
    (void)CohesiveLaw(law); // the law's own checks: K large enough for the triangle to peak before its end
  } catch (const std::invalid_argument& e) {
    t.fail_here(fmt::format("[delamination]: {}", e.what()));
  }
  return law;
}

} // namespace

DelaminationSettings read_delamination(const TableReader& t, Deck& d, bool plies_given) {
  t.only_keys_of("delamination");
  if (!d.laminate) t.fail_here("[delamination] needs the [laminate] it cuts into sub-laminates");
  DelaminationSettings s;
  s.stack.cuts = read_interfaces(t, *d.laminate);
  s.stack.interface = read_law(t, *d.laminate, s.stack.cuts, s.law_defaults);
  s.stack.rule = t.optional_choice<CohesiveQuadrature>(
                      "points", {{"nodal", CohesiveQuadrature::nodal}, {"gauss", CohesiveQuadrature::gauss}})
                     .value_or(CohesiveQuadrature::nodal);
  s.supports_on_all =
      t.optional_choice<bool>("supports", {{"all", true}, {"bottom", false}}).value_or(s.supports_on_all);
  // A disk delaminated from the start in every interface, centred under the impactor (case_from_deck).
  s.stack.seed_radius = t.optional_positive("seed_radius", "m").value_or(0.0);
  // The plate steps with one integrator: left out, the interfaces' step is [time]'s where that is explicit,
  // else the plies' where [damage] gives it, else lagged (and the plies then follow, deck.cpp).
  const std::optional<Integrator> plies =
      d.damage.progressive && plies_given ? d.time.laws : std::optional<Integrator>();
  const Integrator interfaces = optional_law_integrator(t).value_or(
      d.time.integration == TimeScheme::central_difference ? Integrator::central_difference
                                                           : plies.value_or(Integrator::lagged));
  // The one table of what runs (analysis/impact/capabilities.hpp).
  const ModelKind kind{false, d.nonlinear, d.damage.progressive.has_value(), true};
  try {
    const Integrator integrator = resolve_integrator(kind, d.time.integration, plies, interfaces);
    if (auto why = refusal(kind, integrator)) t.fail_here(fmt::format("[delamination]: {}", *why));
  } catch (const std::invalid_argument& e) {
    t.fail_here(fmt::format("[delamination]: {}", e.what()));
  }
  d.time.laws = interfaces; // plies that leave their integration out follow the interfaces'
  return s;
}

} // namespace plyimpact::deck_tables
