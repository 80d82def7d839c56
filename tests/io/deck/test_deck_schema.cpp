// The deck's keys (io/deck/deck_keys.hpp) and its JSON Schema (io/deck/deck_schema.hpp): every table a key
// refers to exists and every table is reached from the top level; the parser refuses a key of no table with
// the table's closest key; the schema has one closed definition per table with the table's keys. The shipped
// decks are validated against the schema by Schemas.EveryShippedDeckValidatesAndSlipsDoNot (Python).
#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/io/deck/deck_error.hpp"
#include "plyimpact/io/deck/deck_keys.hpp"
#include "plyimpact/io/deck/deck_schema.hpp"
#include "support/cli.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace deck_schema_tests {

namespace {

using namespace plyimpact;

TEST(DeckKeys, EveryReferredTableExistsAndEveryTableIsReachedFromTheTop) {
  std::set<std::string> tables, referred{""};
  for (const DeckTable& t : deck_key_tables()) {
    EXPECT_TRUE(tables.insert(std::string(t.name)).second) << "table listed twice: " << t.name;
    std::set<std::string_view> keys;
    for (const DeckKey& k : t.keys) {
      EXPECT_TRUE(keys.insert(k.name).second) << t.name << "." << k.name << " listed twice";
      const bool has_table =
          k.kind == KeyKind::table || k.kind == KeyKind::named_tables || k.kind == KeyKind::array_of_tables;
      EXPECT_EQ(has_table, !k.table.empty()) << t.name << "." << k.name;
      if (has_table) referred.insert(std::string(k.table));
    }
  }
  EXPECT_EQ(tables, referred);
  EXPECT_THROW((void)deck_table("no such table"), std::logic_error);
}

TEST(DeckKeys, TheParserRefusesAKeyOfNoTableWithItsClosestKey) {
  const std::string deck = test::small_deck("impact", test::steel_ball_impactor("dt = 1e-6\n"));
  const std::string slip = test::with_line(deck, "velocity = 2.92", "velocty = 2.92");
  try {
    (void)parse_deck(slip, "slip.toml");
    ADD_FAILURE() << "a misspelt key was read";
  } catch (const DeckError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown key 'velocty' in [impactor] (did you mean 'velocity'?)"),
              std::string::npos)
        << e.what();
  }
}

TEST(DeckSchema, OneClosedDefinitionPerTableWithItsKeys) {
  const nlohmann::json schema = deck_json_schema();
  EXPECT_EQ(schema["$schema"], "http://json-schema.org/draft-07/schema#");
  EXPECT_EQ(schema["additionalProperties"], false);
  EXPECT_EQ(schema["definitions"].size() + 1, deck_key_tables().size());
  for (const DeckTable& t : deck_key_tables()) {
    const nlohmann::json& def = t.name.empty() ? schema : schema["definitions"][std::string(t.name)];
    ASSERT_TRUE(def.is_object()) << t.name;
    EXPECT_EQ(def["properties"].size(), t.keys.size()) << t.name;
    for (const DeckKey& k : t.keys)
      EXPECT_TRUE(def["properties"].contains(std::string(k.name))) << t.name << "." << k.name;
    EXPECT_EQ(def["additionalProperties"] == false, !t.open) << t.name;
  }
  EXPECT_EQ(schema["properties"]["materials"]["additionalProperties"]["$ref"], "#/definitions/material");
  EXPECT_EQ(schema["definitions"]["output"]["properties"]["probe"]["items"]["$ref"],
            "#/definitions/output.probe");
  EXPECT_EQ(schema["definitions"]["time"]["properties"]["dt"]["type"], nlohmann::json({"number", "string"}));
}

} // namespace

} // namespace deck_schema_tests
