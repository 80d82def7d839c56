#include "plyimpact/io/results/summary_keys.hpp"

#include <fmt/format.h>

#include <array>
#include <map>
#include <stdexcept>
#include <utility>

namespace plyimpact {

namespace {

using json = nlohmann::json;

constexpr unsigned null = json_null, boolean = json_boolean, integer = json_integer, number = json_number,
                   string = json_string, array = json_array, object = json_object;

/// The path of `key` inside `parent` ("" is the top).
std::string joined(const std::string& parent, const std::string& key) {
  if (parent.empty()) return key;
  std::string path = parent;
  path += '/';
  path += key;
  return path;
}

/// The table, written as docs/output.md lists the keys: a parent, then its keys.
class KeyTable {
public:
  void add(std::string path, unsigned types, std::string meaning = {}) {
    keys_.push_back({std::move(path), types, std::move(meaning)});
  }
  /// An object at `path` and its keys, each a path relative to it.
  void add_object(const std::string& path, unsigned types, std::string meaning,
                  const std::vector<std::pair<std::string, unsigned>>& keys) {
    add(path, types, std::move(meaning));
    for (const auto& [key, key_types] : keys)
      add(joined(path, key), key_types);
  }
  /// A damage onset (damage_report.hpp's onset_json): where and when a criterion first reached 1.
  void add_onset(const std::string& path, unsigned types, std::string meaning) {
    add_object(path, types, std::move(meaning),
               {{"criterion", string},
                {"mode", string},
                {"ply", integer | null},
                {"interface", integer | null},
                {"element", integer},
                {"ipgs", integer},
                {"jpgs", integer},
                {"x", number},
                {"y", number},
                {"time", number},
                {"force", number},
                {"sigma22", number},
                {"tau23", number},
                {"index", number}});
  }
  /// A list of numbers.
  void add_numbers(const std::string& path, std::string meaning) {
    add(path, array, std::move(meaning));
    add(path + "/[]", number);
  }
  std::vector<SummaryKey> keys_;
};

constexpr std::array<const char*, 4> damage_modes{"fibre-tension", "fibre-compression", "matrix-tension",
                                                  "matrix-compression"};

/// The keys every analysis writes first (results.hpp's summary_header) and last.
void add_header(KeyTable& t) {
  t.add("analysis", string, "impact, static, modal, buckling or threshold");
  t.add("program", string, "plyimpact");
  t.add("version", string, "the program's version");
  t.add("deck", string, "the deck's path");
  t.add("rig", string, "what [rig] built");
  t.add("warnings", array, "each also printed on stderr as plyimpact: warning: ...");
  t.add("warnings/[]", string);
  t.add("wall_time", number, "seconds of the run [s]");
}

void add_impact_results(KeyTable& t) {
  t.add("peak_force", number, "largest contact force [N]");
  t.add("time_of_peak_force", number, "[s]");
  t.add_object("load_drop", object, "the delamination threshold load F_d read from the force history",
               {{"rule", string},
                {"force_N", number | null},
                {"time_s", number | null},
                {"detected_at_s", number | null}});
  t.add("contact_duration", number, "duration of the first contact [s]");
  t.add("episodes", array, "every contact");
  t.add_object("episodes/[]", object, "", {{"start", number}, {"end", number}, {"peak_force", number}});
  t.add("contacts", integer, "number of contact episodes");
  t.add("peak_contact_deflection", number, "largest plate deflection at the contact point [m]");
  t.add("max_indentation", number, "[m]");
  t.add("permanent_indentation", number, "[m]");
  t.add("rebound_velocity", number | null, "[m/s]; null while the impactor has not left the plate");
  t.add("absorbed_energy", number | null, "[J]; null when rebound_velocity is");
  t.add("contact_dissipation", number, "[J]");
  t.add_object("absorbed_energy_by_mechanism", object | null, "[J] each; null until the impactor has left",
               {{"contact_J", number},
                {"ply_damage_J", number},
                {"delamination_J", number},
                {"plate_vibration_J", number},
                {"unaccounted_J", number}});
  t.add("initial_energy", number, "[J]");
  t.add("impactor_mass", number, "[kg]");
  t.add("impact_velocity", number, "[m/s]");
  t.add("contact_stiffness", number, "[N/m^1.5]");
  t.add("steps", integer, "");
  t.add("dt", number, "[s]");
  t.add("end_time", number, "[s]");
  t.add("integration", string, "implicit, lagged or explicit");
  t.add_object("end_of_event", object, "what decided the end", {{"rule", string}});
  t.add_object("end_of_event/separation", object | null, "where the separation rule ended the run",
               {{"time_s", number},
                {"impactor_gap_m", number},
                {"plate_amplitude_bound_m", number},
                {"plate_energy_J", number},
                {"compliance_m_per_N", number}});
  t.add("complete", boolean, "true when the event is over");
  t.add("incomplete_reason", string | null, "");
  t.add("stop_reason", string, "only when the run was stopped before its end");
  t.add("energy_balance_error", number, "as a fraction of the impact energy");
  t.add("suspect", boolean, "");
  t.add("suspect_reason", string | null, "");
  t.add("fundamental_period", number | null, "[s]");
  t.add("equations", integer, "");
  t.add("inplane_dofs_eliminated", boolean, "");
  t.add_object("mesh", object, "the mesh that ran",
               {{"elements", integer},
                {"element", string},
                {"graded", boolean},
                {"smallest_element_m", number},
                {"largest_element_m", number}});
  t.add("contact_load", string, "");
  t.add("newton_iterations_max", integer, "of the scalar contact solve in one step");
  t.add("vtk_frames", integer, "");
}

void add_explicit_results(KeyTable& t) {
  t.add_object("stable_step", object, "explicit runs: what sets the stable step",
               {{"omega_max_rad_per_s", number}, {"stable_step_s", number}});
  t.add_object("stable_step/highest_mode_at", object, "",
               {{"sublaminate", integer}, {"dof", string}, {"x_m", number}, {"y_m", number}});
  t.add_object("mass_scaling", object, "explicit runs with [time] mass_scaling (docs/mass_scaling.md)",
               {{"kind", string},
                {"target_dt_s", number},
                {"scaled_nodes", integer},
                {"largest_factor", number},
                {"interface_mass_factor", number},
                {"added_kinetic_energy_max_J", number | null},
                {"added_kinetic_energy_fraction", number}});
  for (const char* per_sublaminate :
       {"mass_kg", "added_mass_kg", "rotary_inertia_kg_m2", "added_rotary_inertia_kg_m2"})
    t.add_numbers(fmt::format("mass_scaling/{}", per_sublaminate), "per sub-laminate");
  t.add_object("time_steps", object, "[time] adaptive = true",
               {{"adaptive", boolean},
                {"tolerance", number},
                {"largest_dt", number},
                {"smallest_allowed_dt", number},
                {"smallest_used_dt", number},
                {"rejected_steps", integer},
                {"steps_above_tolerance", integer},
                {"largest_error_ratio", number},
                {"factorizations", integer}});
  t.add("nonlinear", boolean, "geometrically non-linear runs");
  t.add("strain_measure", string, "");
  t.add("newton_iterations", integer, "");
  t.add("max_newton_iterations_per_step", integer, "");
  t.add("factorizations", integer, "");
}

void add_criteria_results(KeyTable& t) {
  t.add("first_failures", array, "[damage] criteria: the first failure of each criterion and mode");
  t.add_onset("first_failures/[]", object, "");
  t.add("first_failures/[]/at_clamp_tip", boolean, "its element holds a clamp tip of the rig");
  t.add_onset("laminate_first_failure", object | null, "the earliest onset away from a rig's clamp tips");
}

void add_lowered_strength(KeyTable& t, const std::string& path) {
  t.add_object(path, object | null, "",
               {{"strength", string},
                {"material", string},
                {"reduction_percent", number},
                {"deck_Pa", number},
                {"used_Pa", number},
                {"element", integer},
                {"x_m", number},
                {"y_m", number}});
}

void add_ply_damage_results(KeyTable& t) {
  t.add_object("damage", object, "[damage] model = \"progressive\"",
               {{"model", string},
                {"integration", string},
                {"dissipated_energy", number},
                {"projected_damage_area", number},
                {"area_threshold", number},
                {"active_elements", integer},
                {"iterations", integer},
                {"max_iterations_per_step", integer},
                {"factorizations", integer}});
  t.add("damage/dissipated_energy_by_mode", object, "[J]");
  for (const char* mode : damage_modes)
    t.add(fmt::format("damage/dissipated_energy_by_mode/{}", mode), number);
  t.add_numbers("damage/ply_damage_area", "[m²], ply 1 first");
  t.add_object("damage/first_damage", object | null, "",
               {{"mode", string}, {"ply", integer}, {"time", number}, {"contact_force", number}});
  t.add("damage/first_damage_by_mode", object, "");
  for (const char* mode : damage_modes)
    t.add_object(fmt::format("damage/first_damage_by_mode/{}", mode), object | null, "",
                 {{"ply", integer}, {"time", number}, {"contact_force", number}});
  t.add_object("damage/strength_reduction", object, "strengths lowered to the band limits",
               {{"elements_lowered", integer},
                {"largest_percent", number},
                {"largest_where_damaged_percent", number}});
  add_lowered_strength(t, "damage/strength_reduction/largest");
  add_lowered_strength(t, "damage/strength_reduction/largest_where_damaged");
}

void add_delamination_results(KeyTable& t) {
  t.add_object("delamination", object, "[delamination]",
               {{"projected_delaminated_area_m2", number},
                {"dissipated_energy_J", number},
                {"cohesive_zone_length_m", number},
                {"interface_point_spacing_m", number},
                {"penalty_stiffness_Pa_per_m", number},
                {"cracked_closing_fraction", number},
                {"normal_strength_Pa", number},
                {"shear_strength_Pa", number},
                {"G_Ic_J_per_m2", number},
                {"G_IIc_J_per_m2", number},
                {"bk_exponent", number},
                {"onset", string},
                {"points", string},
                {"supports", string},
                {"seed_radius_m", number},
                {"integration", string},
                {"iterations", integer},
                {"max_iterations_per_step", integer},
                {"factorizations", integer},
                {"factor_updates", integer}});
  t.add("delamination/interfaces_after_ply", array, "");
  t.add("delamination/interfaces_after_ply/[]", integer);
  t.add_numbers("delamination/delaminated_area_m2", "per interface");
  t.add_numbers("delamination/process_zone_area_m2", "per interface");
  t.add_object("delamination/law_defaults", object, "the law's values the deck left out, and where from",
               {{"G_Ic", string},
                {"G_IIc", string},
                {"bk_exponent", string},
                {"normal_strength", string},
                {"shear_strength", string}});
  t.add("delamination/shapes", array, "per interface from the impacted face");
  t.add_object("delamination/shapes/[]", object, "",
               {{"after_ply", integer},
                {"ply_below_angle_deg", number},
                {"area_m2", number},
                {"axis_deg", number | null},
                {"aspect_ratio", number | null},
                {"axis_to_fibre_deg", number | null}});
  t.add_object("delamination/first_growth", object | null, "", {{"time_s", number}, {"force_N", number}});
}

void add_plate_analyses(KeyTable& t) {
  t.add("center_deflection", number | null, "static [m]; null where the point is not on the plate");
  t.add("load_point_deflection", number | null, "static [m]");
  t.add("max_abs_deflection", number | null, "static [m]");
  t.add("support_nodes", integer, "static, unilateral supports");
  t.add("support_touching_nodes", integer, "");
  t.add("support_max_lift_off", number, "[m]");
  t.add("support_reaction", number, "[N]");
  t.add("contact_set_solves", integer, "");
  t.add("load_deflection", array, "static, non-linear: [λ, w(a/2, b/2) [m]] per load step");
  t.add_numbers("load_deflection/[]", "");
  t.add("step_cuts", integer, "");
  t.add("dofs", integer, "free DOFs");
  t.add_numbers("frequencies_hz", "modal [Hz]");
  t.add("zero_energy_modes", integer, "modal");
  t.add_numbers("load_factors", "buckling");
  t.add_object("reference_load", object, "buckling [N/m]", {{"Nx", number}, {"Ny", number}, {"Nxy", number}});
}

void add_threshold_results(KeyTable& t) {
  t.add("criterion", string, "threshold: the criterion searched");
  t.add("threshold_velocity", number | null, "[m/s]; null where none fails up to the limit");
  t.add_onset("first_failure", object | null, "at the threshold velocity");
  t.add_object("damage_reached", object | null, "",
               {{"mode", string},
                {"ply", integer},
                {"element", integer},
                {"time", number},
                {"force", number},
                {"projected_damage_area", number}});
  t.add("damage_area", number, "[m²]");
  t.add("lower_velocity", number, "[m/s]");
  t.add("tolerance", number, "");
  t.add("trials", array, "");
  t.add_object("trials/[]", object, "", {{"velocity", number}, {"failed", boolean}, {"peak_index", number}});
}

std::vector<SummaryKey> build_table() {
  KeyTable t;
  add_header(t);
  add_impact_results(t);
  add_explicit_results(t);
  add_criteria_results(t);
  add_ply_damage_results(t);
  add_delamination_results(t);
  add_plate_analyses(t);
  add_threshold_results(t);
  return std::move(t.keys_);
}

/// The table by path (a key listed twice with different types would be a slip of this file).
const std::map<std::string, const SummaryKey*>& keys_by_path() {
  static const std::map<std::string, const SummaryKey*> by_path = [] {
    std::map<std::string, const SummaryKey*> m;
    for (const SummaryKey& k : summary_keys())
      if (!m.emplace(k.path, &k).second)
        throw std::logic_error("summary_keys.cpp lists " + k.path + " twice");
    return m;
  }();
  return by_path;
}

unsigned type_of(const json& value) {
  switch (value.type()) {
  case json::value_t::null:
    return json_null;
  case json::value_t::boolean:
    return json_boolean;
  case json::value_t::number_integer:
  case json::value_t::number_unsigned:
    return json_integer | json_number;
  case json::value_t::number_float:
    return json_number;
  case json::value_t::string:
    return json_string;
  case json::value_t::array:
    return json_array;
  case json::value_t::object:
    return json_object;
  default:
    return 0;
  }
}

/// JSON Schema's names of the types in `types`.
json type_names(unsigned types) {
  json names = json::array();
  // "integer" is inside "number": a key that may be either is a number.
  const std::array<std::pair<unsigned, const char*>, 7> names_of{{{json_null, "null"},
                                                                  {json_boolean, "boolean"},
                                                                  {json_integer, "integer"},
                                                                  {json_number, "number"},
                                                                  {json_string, "string"},
                                                                  {json_array, "array"},
                                                                  {json_object, "object"}}};
  for (const auto& [bit, name] : names_of)
    if ((types & bit) != 0U && !(bit == json_integer && (types & json_number) != 0U)) names.push_back(name);
  return names.size() == 1 ? names.front() : names;
}

void check(const json& value, const std::string& path, std::vector<std::string>& slips) {
  const auto& by_path = keys_by_path();
  if (value.is_object()) {
    for (const auto& [key, child] : value.items()) {
      const std::string child_path = joined(path, key);
      const auto found = by_path.find(child_path);
      if (found == by_path.end()) {
        slips.push_back(child_path + ": not a key of summary.json");
        continue;
      }
      if ((type_of(child) & found->second->types) == 0U) {
        slips.push_back(fmt::format("{}: a {} where the table allows {}", child_path, child.type_name(),
                                    type_names(found->second->types).dump()));
        continue;
      }
      check(child, child_path, slips);
    }
  } else if (value.is_array()) {
    const std::string item_path = path + "/[]";
    const auto found = by_path.find(item_path);
    for (const json& item : value) {
      if (found == by_path.end()) {
        slips.push_back(item_path + ": not a key of summary.json");
        return;
      }
      if ((type_of(item) & found->second->types) == 0U) {
        slips.push_back(fmt::format("{}: a {}", item_path, item.type_name()));
        return;
      }
      check(item, item_path, slips);
    }
  }
}

/// The schema of the value at `path` (its children from the table).
json value_schema(const std::string& path, const SummaryKey* key) {
  json s = json::object();
  if (key != nullptr) {
    s["type"] = type_names(key->types);
    if (!key->meaning.empty()) s["description"] = key->meaning;
  }
  const std::string prefix = path.empty() ? std::string() : path + "/";
  json properties = json::object();
  for (const SummaryKey& k : summary_keys()) {
    if (!k.path.starts_with(prefix)) continue;
    const std::string rest = k.path.substr(prefix.size());
    if (rest.empty() || rest.find('/') != std::string::npos) continue;
    if (rest == "[]")
      s["items"] = value_schema(k.path, &k);
    else
      properties[rest] = value_schema(k.path, &k);
  }
  if (key == nullptr || (key->types & json_object) != 0U) {
    s["properties"] = properties;
    s["additionalProperties"] = false;
  }
  return s;
}

} // namespace

const std::vector<SummaryKey>& summary_keys() {
  static const std::vector<SummaryKey> table = build_table();
  return table;
}

std::vector<std::string> summary_slips(const json& summary) {
  std::vector<std::string> slips;
  if (!summary.is_object()) return {"the summary is not an object"};
  check(summary, "", slips);
  return slips;
}

json summary_json_schema() {
  json schema = value_schema("", nullptr);
  schema["$schema"] = "http://json-schema.org/draft-07/schema#";
  schema["title"] = "plyimpact summary.json";
  schema["description"] =
      "The summary of a plyimpact run, every analysis (docs/output.md). Generated by `plyimpact schema "
      "summary` from the table of keys the program checks every summary against before writing it.";
  schema["type"] = "object";
  return schema;
}

} // namespace plyimpact
