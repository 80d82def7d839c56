// The threshold search's progress measure: the bracket [no failure, failure] narrows from its first
// width w0 to the tolerance; progress is log(w0 / w) / log(w0 / tolerance), 0 before any failure.
#include "plyimpact/analysis/threshold_search.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace plyimpact;

TEST(ThresholdSearch, BracketProgressIsTheLogOfTheBracketsNarrowing) {
  std::vector<ThresholdTrial> trials{{5.0, false, 0.7}};
  EXPECT_EQ(bracket_progress(trials, 0.01), 0.0); // no failure yet: no bracket
  trials.push_back({10.0, true, 1.2});
  EXPECT_EQ(bracket_progress(trials, 0.01), 0.0); // the first bracket [5, 10]
  trials.push_back({7.5, true, 1.1});             // [5, 7.5]: halved
  EXPECT_NEAR(bracket_progress(trials, 0.01), std::log(2.0) / std::log(500.0), 1e-15);
  trials.push_back({7.49, false, 0.99}); // [7.49, 7.5]: the tolerance reached
  EXPECT_NEAR(bracket_progress(trials, 0.01), 1.0, 1e-12);
}

TEST(ThresholdSearch, BracketProgressIsCompleteWhenTheFirstBracketIsAlreadyNarrowEnough) {
  EXPECT_EQ(bracket_progress({{1.0, false, 0.9}, {1.005, true, 1.0}}, 0.01), 1.0);
}

} // namespace
