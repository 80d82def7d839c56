// `plyimpact init` (io/deck/starting_deck.hpp, docs/deck.md "A starting deck"): the deck it writes is read
// by the parser for both coupon rigs and every library card (refused, with the library's message, where
// the card has no density), names its rig and card, and the default deck runs to the end unchanged.
#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/io/deck/material_library.hpp"
#include "plyimpact/io/deck/starting_deck.hpp"
#include "plyimpact/io/mesh/test_rigs.hpp"
#include "support/cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>

namespace plyimpact::starting_deck_tests {
namespace {

namespace fs = std::filesystem;

TEST(StartingDeck, BothCouponRigsGiveADeckTheParserReads) {
  for (const auto& [rig, kind] :
       {std::pair{"astm-d7136", RigKind::astm_d7136}, std::pair{"aitm-1-0010", RigKind::aitm_1_0010}}) {
    const Deck d = parse_deck(starting_deck({rig, "T300-976"}), "init.toml");
    ASSERT_TRUE(d.rig.has_value()) << rig;
    EXPECT_EQ(d.rig->kind, kind);
    ASSERT_TRUE(d.impactor.has_value());
    EXPECT_DOUBLE_EQ(d.impactor->radius, 0.008);
    EXPECT_DOUBLE_EQ(d.laminate->thickness(), 4e-3);
  }
}

TEST(StartingDeck, EveryCardIsTakenOrItsMissingDensityIsAskedFor) {
  const toml::table library = material_library();
  for (const std::string& card : material_library_names()) {
    const std::string text = starting_deck({"aitm-1-0010", card});
    if (library[card].as_table()->contains("rho")) {
      const Deck d = parse_deck(text, "init.toml");
      EXPECT_EQ(d.material_cards.at(0).second, card);
      EXPECT_EQ(d.materials.at(0).E1, library[card]["E1"].value_or(0.0)) << card;
      continue;
    }
    try {
      (void)parse_deck(text, "init.toml");
      ADD_FAILURE() << card << ": a card without a density ran";
    } catch (const DeckError& e) {
      EXPECT_NE(std::string(e.what()).find("gives no density"), std::string::npos) << e.what();
    }
  }
}

TEST(StartingDeck, AnUnknownRigOrCardIsRefusedWithTheChoices) {
  EXPECT_THROW((void)starting_deck({"circular", "T300-976"}), std::invalid_argument);
  try {
    (void)starting_deck({"aitm-1-0010", "T300/976"});
    ADD_FAILURE() << "an unknown card was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("T300-976"), std::string::npos) << e.what();
  }
  EXPECT_EQ(test::run("init --material unobtainium").status, 2);
}

TEST(StartingDeck, TheDefaultDeckRunsToTheEndUnchanged) {
  const fs::path dir = test::scratch("init");
  const fs::path deck = dir / "first.toml";
  const test::CommandResult written = test::run("init " + deck.string());
  ASSERT_EQ(written.status, 0) << written.out;
  EXPECT_EQ(test::run("init " + deck.string()).status, 2) << "an existing file is not replaced";
  const test::CommandResult r = test::run("impact " + deck.string() + " -o " + (dir / "out").string());
  ASSERT_EQ(r.status, 0) << r.out;
  const nlohmann::json summary = test::read_json(dir / "out" / "summary.json");
  EXPECT_TRUE(summary.at("complete").get<bool>());
  EXPECT_LT(summary.at("energy_balance_error").get<double>(), 0.01);
}

} // namespace
} // namespace plyimpact::starting_deck_tests
