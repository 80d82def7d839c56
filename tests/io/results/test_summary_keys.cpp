// The table of summary.json's keys (io/results/summary_keys.hpp): every key's parent is in it as an object
// or a list, no key is listed twice; summary_slips() names a misspelt key, a key at the wrong level, a
// value of a type the table does not allow and an item of a list; the schema generated from the table is
// closed and types each key as the table does; ResultsFolder::write_summary writes the summary whole and
// says on stderr which key is outside the table. The summaries of the shipped examples are validated
// against the schema by Schemas.EveryExampleSummaryValidatesAndSlipsDoNot (Python's jsonschema).
#include "plyimpact/io/results/results.hpp"
#include "plyimpact/io/results/summary_keys.hpp"
#include "support/cli.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace summary_keys_tests {

namespace {

using namespace plyimpact;
using json = nlohmann::json;

/// A summary as an impact run writes its first keys, by hand.
json small_summary() {
  return {{"analysis", "impact"},
          {"peak_force", 12661.7},
          {"steps", 2000},
          {"rebound_velocity", nullptr},
          {"episodes", json::array({{{"start", 0.0}, {"end", 1e-3}, {"peak_force", 12661.7}}})},
          {"mesh", {{"elements", 600}, {"element", "Q4"}}},
          {"damage", {{"first_damage", {{"mode", "matrix-tension"}, {"ply", 3}}}}}};
}

TEST(SummaryKeys, EveryParentIsAnObjectOrAListOfTheTableAndNoKeyIsListedTwice) {
  std::set<std::string> paths;
  for (const SummaryKey& k : summary_keys()) {
    EXPECT_TRUE(paths.insert(k.path).second) << k.path << " listed twice";
    EXPECT_NE(k.types, 0U) << k.path;
    const std::size_t slash = k.path.rfind('/');
    if (slash == std::string::npos) continue;
    const std::string parent = k.path.substr(0, slash);
    ASSERT_TRUE(paths.contains(parent)) << k.path << " comes before its parent " << parent;
    const bool item = k.path.substr(slash + 1) == "[]";
    for (const SummaryKey& p : summary_keys()) {
      if (p.path == parent) {
        EXPECT_NE(p.types & (item ? json_array : json_object), 0U) << parent << " holds " << k.path;
      }
    }
  }
  EXPECT_GT(paths.size(), 200U); // every analysis's keys, docs/output.md
}

TEST(SummaryKeys, ASummaryOfTheTablesKeysHasNoSlip) {
  EXPECT_TRUE(summary_slips(small_summary()).empty());
}

TEST(SummaryKeys, SlipsAreNamedWithTheirPlace) {
  json misspelt = small_summary();
  misspelt["peak_forse"] = misspelt["peak_force"];
  EXPECT_EQ(summary_slips(misspelt), std::vector<std::string>{"peak_forse: not a key of summary.json"});

  json wrong_level = small_summary();
  wrong_level["mesh"]["peak_force"] = 1.0;
  EXPECT_EQ(summary_slips(wrong_level),
            std::vector<std::string>{"mesh/peak_force: not a key of summary.json"});

  json in_a_list = small_summary();
  in_a_list["episodes"][0]["pek_force"] = 1.0;
  EXPECT_EQ(summary_slips(in_a_list),
            std::vector<std::string>{"episodes/[]/pek_force: not a key of summary.json"});

  json wrong_type = small_summary();
  wrong_type["steps"] = 2000.5; // a count is an integer
  ASSERT_EQ(summary_slips(wrong_type).size(), 1U);
  EXPECT_EQ(summary_slips(wrong_type)[0].rfind("steps: a number where the table allows \"integer\"", 0), 0U)
      << summary_slips(wrong_type)[0];

  json not_nullable = small_summary();
  not_nullable["peak_force"] = nullptr; // rebound_velocity may be null, the peak force may not
  EXPECT_EQ(summary_slips(not_nullable).size(), 1U);
}

TEST(SummaryKeys, TheSchemaIsClosedAndTypesEachKeyAsTheTableDoes) {
  const json schema = summary_json_schema();
  EXPECT_EQ(schema["$schema"], "http://json-schema.org/draft-07/schema#");
  EXPECT_EQ(schema["additionalProperties"], false);
  EXPECT_EQ(schema["properties"]["peak_force"]["type"], "number");
  EXPECT_EQ(schema["properties"]["steps"]["type"], "integer");
  EXPECT_EQ(schema["properties"]["rebound_velocity"]["type"], json::array({"null", "number"}));
  const json& episode = schema["properties"]["episodes"]["items"];
  EXPECT_EQ(episode["additionalProperties"], false);
  EXPECT_EQ(episode["properties"].size(), 3U); // start, end, peak_force
  const json& first_damage = schema["properties"]["damage"]["properties"]["first_damage"];
  EXPECT_EQ(first_damage["type"], json::array({"null", "object"}));
  EXPECT_TRUE(first_damage["properties"].contains("contact_force"));
  EXPECT_EQ(first_damage["additionalProperties"], false);
}

TEST(SummaryKeys, WriteSummaryWritesItWholeAndSaysWhichKeyIsOutsideTheTable) {
  const auto dir = test::scratch("summary-keys");
  Deck deck;
  deck.text = "analysis = \"impact\"\n";
  const ResultsFolder folder(dir, deck);
  json summary = small_summary();
  summary["peak_forse"] = 1.0;
  testing::internal::CaptureStderr();
  folder.write_summary(summary);
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(test::read_json(dir / "summary.json"), summary);
  EXPECT_NE(err.find("plyimpact: warning: summary.json: peak_forse: not a key of summary.json"),
            std::string::npos)
      << err;
}

} // namespace

} // namespace summary_keys_tests
