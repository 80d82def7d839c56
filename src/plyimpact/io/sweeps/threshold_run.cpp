#include "plyimpact/io/sweeps/threshold_run.hpp"

#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/deck/deck_error.hpp"
#include "plyimpact/io/results/damage_report.hpp"
#include "plyimpact/io/results/results.hpp"

#include <fmt/format.h>

namespace plyimpact {

ThresholdCriterion threshold_criterion(const Deck& deck, const std::string& name, const std::string& option) {
  if (deck.time.adaptive)
    throw DeckError(
        fmt::format("{}: error: [time] adaptive = true: a threshold search evaluates its criterion at "
                    "every step of one Δt; remove adaptive = true (and give dt)",
                    deck.source));
  std::string chosen = !name.empty() ? name : deck.threshold.criterion;
  if (chosen.empty() && !deck.damage.criteria.empty()) chosen = deck.damage.criteria.front();
  if (chosen.empty())
    throw DeckError(fmt::format("{}: error: give {} NAME or [threshold] criterion", deck.source, option));
  if (const auto c = parse_criterion(chosen)) return {chosen, *c};
  const auto kind = parse_damage_criterion(chosen);
  if (!kind) throw DeckError(unknown_threshold_criterion(deck.source + ": error: " + option, chosen));
  if (!deck.damage.progressive)
    throw DeckError(
        fmt::format("{}: error: criterion \"{}\" looks for ply damage, which only the progressive "
                    "damage model computes: set [damage] model = \"progressive\"",
                    deck.source, chosen));
  DamageCriterion damage{*kind, 0.0};
  if (*kind == DamageCriterion::Kind::damage_area) {
    if (!deck.threshold.damage_area)
      throw DeckError(fmt::format("{}: error: criterion \"damage-area\" needs [threshold] damage_area, the "
                                  "projected damaged area to exceed",
                                  deck.source));
    damage.area = *deck.threshold.damage_area;
  }
  return {chosen, damage};
}

ThresholdResult search_threshold(const ImpactCase& impact, const ThresholdCriterion& criterion,
                                 const ThresholdOptions& options, const std::atomic<bool>* cancel) {
  return std::visit([&](const auto& c) { return find_threshold_velocity(impact, c, options, cancel); },
                    criterion.criterion);
}

namespace {

nlohmann::json damage_reached_json(const DamageReached& d) {
  return {{"mode", std::string(to_string(d.mode))},
          {"ply", d.ply},
          {"element", d.element},
          {"time", d.time},
          {"force", d.force},
          {"projected_damage_area", d.projected_area}};
}

} // namespace

void put_threshold_summary(nlohmann::json& j, const ThresholdCriterion& criterion, const ThresholdResult& r) {
  j["criterion"] = criterion.name;
  j["threshold_velocity"] = r.found ? nlohmann::json(r.velocity) : nlohmann::json(nullptr);
  j["first_failure"] = r.first_failure ? onset_json(*r.first_failure) : nlohmann::json(nullptr);
  const auto* damage = std::get_if<DamageCriterion>(&criterion.criterion);
  if (damage == nullptr) return;
  j["damage_reached"] = r.damage ? damage_reached_json(*r.damage) : nlohmann::json(nullptr);
  if (damage->kind == DamageCriterion::Kind::damage_area) j["damage_area"] = damage->area;
}

ThresholdOptions threshold_options(const Deck& deck, double tolerance) {
  ThresholdOptions options;
  options.tolerance = tolerance > 0.0 ? tolerance : deck.threshold.tolerance;
  options.max_velocity = deck.threshold.max_velocity;
  options.damage = damage_options_from_deck(deck);
  return options;
}

nlohmann::json threshold_summary_json(const Deck& deck, const ThresholdCriterion& criterion,
                                      const ThresholdOptions& options, const ThresholdResult& r) {
  nlohmann::json j = summary_header(deck, "threshold");
  put_threshold_summary(j, criterion, r);
  j["lower_velocity"] = r.lower;
  j["tolerance"] = options.tolerance;
  j["trials"] = nlohmann::json::array();
  for (const auto& t : r.trials)
    j["trials"].push_back({{"velocity", t.velocity}, {"failed", t.failed}, {"peak_index", t.peak_index}});
  return j;
}

} // namespace plyimpact
