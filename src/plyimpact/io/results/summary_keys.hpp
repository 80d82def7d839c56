#pragma once
// The keys of summary.json (docs/output.md, SPEC §10's result keys), every analysis together: the one table
// that the writer checks every summary against before it writes it (ResultsFolder::write_summary) and from
// which `plyimpact schema summary` generates the JSON Schema that tools validate a summary with
// (docs/schemas.md). A key added to a summary is added here, or the run says so on stderr.
#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace plyimpact {

/// The JSON types a key's value may take, as a set of bits: a key that may be null says so.
enum JsonType : unsigned {
  json_null = 1U << 0U,
  json_boolean = 1U << 1U,
  json_integer = 1U << 2U,
  json_number = 1U << 3U, ///< a number, integer or not
  json_string = 1U << 4U,
  json_array = 1U << 5U,
  json_object = 1U << 6U,
};

/// One key of summary.json.
struct SummaryKey {
  /// Where it lies, from the top: names separated by '/', "[]" for every element of an array
  /// ("episodes/[]/peak_force").
  std::string path;
  unsigned types = 0;  ///< JsonType bits
  std::string meaning; ///< the unit and a few words (docs/output.md has the whole text)
};

/// Every key of summary.json, parents before their keys.
[[nodiscard]] const std::vector<SummaryKey>& summary_keys();

/// Every place of `summary` whose key is not in summary_keys(), or whose value is of a type the table does
/// not allow for it, in words ("damage/first_damage/tme: not a key of summary.json"); empty when it fits.
[[nodiscard]] std::vector<std::string> summary_slips(const nlohmann::json& summary);

/// The JSON Schema (draft-07) of summary.json: every object of the table closed to keys outside it.
[[nodiscard]] nlohmann::json summary_json_schema();

} // namespace plyimpact
