// history.csv streamed while the run goes (io/results/history_csv.hpp) holds exactly the rows and text the
// in-memory history gave (analysis/impact/recorders.hpp + impact_history_csv), for every step and every k-th.
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/results/history_csv.hpp"
#include "plyimpact/io/results/impact_report.hpp"
#include "support/cli.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace plyimpact::history_csv_tests {
namespace {

TEST(HistoryCsv, StreamedFileEqualsTheInMemoryHistoryText) {
  const std::string deck_text = test::small_deck("impact", test::steel_ball_impactor("dt = 2e-6\n"));
  const Deck deck = parse_deck(deck_text, "deck.toml");
  const ImpactCase impact(impact_case_description(deck));
  const test::fs::path dir = test::scratch("history-csv");
  for (const int every : {1, 7}) {
    const test::fs::path file = dir / ("history-" + std::to_string(every) + ".csv");
    ImpactResult streamed;
    {
      HistoryCsvWriter writer(file, every);
      RunRequest request;
      request.history_every = every; // the in-memory recorder alongside, for the comparison
      request.observers = {&writer};
      streamed = impact.run(request);
    }
    ASSERT_TRUE(streamed.complete);
    ASSERT_GT(streamed.history.size(), 10U);
    const std::string text = test::read_text(file);
    EXPECT_EQ(text, impact_history_csv(streamed)) << "every " << every;
    // the header, the initial state, every k-th step and the last step
    const auto rows = static_cast<long>(std::count(text.begin(), text.end(), '\n')) - 1;
    EXPECT_EQ(rows, streamed.steps / every + 1 + (streamed.steps % every != 0 ? 1 : 0)) << every;
  }
}

TEST(HistoryCsv, RowsAreTheShortestTextThatReadsBackAsTheSameDouble) {
  ImpactSample s;
  s.t = 1e-6;
  s.force = 12345.678901234;
  s.impactor_v = 0.1 + 0.2; // 0.30000000000000004: every digit is kept, nothing is invented
  s.contact_work = -0.5;
  const std::string row = history_csv_row(s);
  EXPECT_EQ(row, "1e-06,12345.678901234,0,0.30000000000000004,0,0,0,0,0,-0.5\n");
  EXPECT_EQ(std::stod(row.substr(row.find(',') + 1)), s.force);
}

} // namespace
} // namespace plyimpact::history_csv_tests
