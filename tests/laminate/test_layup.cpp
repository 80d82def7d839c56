// Stacking-sequence notation (SPEC §1).
#include "plyimpact/laminate/layup.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace plyimpact::layup_tests {
namespace {

using Angles = std::vector<double>;

TEST(Layup, ExpandsRepeatsGroupsAndSymmetry) {
  EXPECT_EQ(parse_layup("[0_2/90_4/0_2]"), (Angles{0, 0, 90, 90, 90, 90, 0, 0}));
  EXPECT_EQ(parse_layup("[0/±45/90]s"), (Angles{0, 45, -45, 90, 90, -45, 45, 0}));
  EXPECT_EQ(parse_layup("[0/+-45/90]s"), parse_layup("[0/±45/90]s"));
  EXPECT_EQ(parse_layup("[∓30]"), (Angles{-30, 30}));
  EXPECT_EQ(parse_layup("[0/45/0/-45/0]2s").size(), 20U);
  EXPECT_EQ(parse_layup("[(0/90)_2/45]"), (Angles{0, 90, 0, 90, 45}));
  EXPECT_EQ(parse_layup("[ 0 / 90 ]_2"), (Angles{0, 90, 0, 90}));
  EXPECT_EQ(parse_layup("[22.5/-67.5]"), (Angles{22.5, -67.5}));
}

TEST(Layup, ThesisValidationLayupIs24PliesMirrored) {
  const Angles a = parse_layup("[45/90/-45/0]3s");
  ASSERT_EQ(a.size(), 24U);
  const Angles head{45, 90, -45, 0};
  for (std::size_t i = 0; i < 12; ++i)
    EXPECT_EQ(a[i], head[i % 4]);
  for (std::size_t i = 0; i < 24; ++i)
    EXPECT_EQ(a[i], a[23 - i]);
}

TEST(Layup, StarMarksTheUnrepeatedMiddlePlyOfAnOddSymmetricLayup) {
  EXPECT_EQ(parse_layup("[0/45/90*]s"), (Angles{0, 45, 90, 45, 0}));
}

struct BadLayup {
  const char* text;
  std::size_t column;
  const char* expected;
};

class LayupErrors : public ::testing::TestWithParam<BadLayup> {};

TEST_P(LayupErrors, PointAtTheOffendingCharacter) {
  const BadLayup& c = GetParam();
  try {
    (void)parse_layup(c.text);
    FAIL() << "accepted " << c.text;
  } catch (const LayupError& e) {
    EXPECT_EQ(e.column(), c.column) << e.what();
    EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Layup, LayupErrors,
    ::testing::Values(BadLayup{"0/90", 1, "'['"}, BadLayup{"[0/90", 6, "']'"},
                      BadLayup{"[0//90]", 4, "ply angle"}, BadLayup{"[0/9x0]", 5, "']'"},
                      BadLayup{"[0_/90]", 4, "repeat count"}, BadLayup{"[0_0/90]", 4, "at least 1"},
                      BadLayup{"[0/90]q", 7, "end of layup"}, BadLayup{"[0/400]", 4, "between -360 and 360"},
                      BadLayup{"[0/±45*]s", 7, "single ply"}, BadLayup{"[0/90*]", 6, "symmetric"},
                      BadLayup{"[0/90]s 3", 9, "end of layup"}, BadLayup{"[±]", 3, "ply angle"},
                      BadLayup{"[]", 2, "ply angle"}, BadLayup{"[0_99999999]", 4, "below 100000"},
                      BadLayup{"", 1, "'['"}, BadLayup{"[1.2.3]", 2, "ply angle"}));

} // namespace
} // namespace plyimpact::layup_tests
