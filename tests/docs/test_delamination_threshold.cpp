// docs/delamination_threshold.md: the energy release rate of n central circular delaminations in a
// clamped circular plate under a central load is (n + 2) P²/(32π² D) whatever their radius — the
// two-region Kirchhoff plate solved numerically by the note's script agrees with the closed form to
// 1e-6 for n = 1, 2, 3, ν = 0 and 0.3, a/R from 0.01 to 0.8 (and the sliding-front model with its own
// closed form). The script exits non-zero otherwise.
#include "support/cli.hpp"

#include <gtest/gtest.h>

#include <string>

namespace delamination_threshold_tests {

namespace {

using namespace plyimpact::test;

TEST(DelaminationThreshold, EnergyReleaseRateOfACentralDelaminationIsIndependentOfItsRadius) {
  const CommandResult r =
      shell("python3 '" + std::string(PLYIMPACT_SOURCE_DIR) + "/docs/notes/decks/delamination_threshold.py'");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("largest relative difference from the closed forms"), std::string::npos) << r.out;
}

} // namespace

} // namespace delamination_threshold_tests
