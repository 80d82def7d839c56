// damage_onsets.csv and damage_area.csv (io/results/damage_report): every number is the shortest text that
// reads back as the same double (issue 17), not a fixed 9 or 6 digits.
#include "plyimpact/io/results/damage_report.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace plyimpact::damage_report_tests {
namespace {

TEST(DamageReport, CsvNumbersAreTheShortestRoundTripText) {
  DamageOnset o;
  o.criterion = Criterion::choi_chang_matrix;
  o.mode = FailureMode::matrix_cracking;
  o.ply = 6;
  o.element = 83;
  o.ipgs = 1;
  o.jpgs = 2;
  o.x = 0.06;
  o.y = 0.1 + 0.2; // 0.30000000000000004: the double's own shortest text, not rounded to 9 digits
  o.time = 1.242e-05;
  o.force = 1102.5;
  o.sigma22 = 3508184.8362368853;
  o.tau23 = -3.3e7;
  o.index = 1.0010408151861678; // was written with 6 decimals: 1.001041
  EXPECT_EQ(
      damage_onsets_csv({o}),
      "criterion,mode,ply,interface,element,ipgs,jpgs,x_m,y_m,time_s,force_N,sigma22_Pa,tau23_Pa,index\n"
      "choi-chang-matrix,matrix-cracking,6,,83,1,2,0.06,0.30000000000000004,1.242e-05,1102.5,"
      "3508184.8362368853,-33000000,1.0010408151861678\n");
  DamageAreaSample a;
  a.time = 2.5e-05;
  a.interface = 3;
  a.criterion = Criterion::choi_chang_delamination;
  a.area = 1.5e-06;
  EXPECT_EQ(damage_area_csv({a}),
            "time_s,criterion,ply,interface,failed_area_m2\n2.5e-05,choi-chang-delamination,,3,1.5e-06\n");
}

DamageOnset onset_at(int element, double time, int ply) {
  DamageOnset o;
  o.criterion = Criterion::hashin;
  o.mode = FailureMode::matrix_tension;
  o.ply = ply;
  o.element = element;
  o.time = time;
  return o;
}

TEST(DamageReport, TheLaminatesFirstFailureIsTheEarliestOnsetAwayFromTheClampTips) {
  // Elements 23 and 40 hold clamp tips; the onsets there come first (a point support's singular stress),
  // the laminate's first failure is the earliest elsewhere: element 7 at 90 us, not element 9 at 95 us
  // listed before it.
  const std::vector<int> tips = {23, 40};
  const std::vector<DamageOnset> onsets = {onset_at(23, 10e-6, 1), onset_at(40, 20e-6, 2),
                                           onset_at(9, 95e-6, 3), onset_at(7, 90e-6, 4),
                                           onset_at(7, 90e-6, 5)};
  const std::optional<DamageOnset> first = laminate_first_failure(onsets, tips);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(first->element, 7);
  EXPECT_EQ(first->ply, 4) << "the first listed of two at the same time";
  EXPECT_TRUE(at_clamp_tip(onsets[0], tips));
  EXPECT_FALSE(at_clamp_tip(onsets[2], tips));
  // Without a rig the first failure is the earliest onset; none where every onset is at a tip.
  EXPECT_EQ(laminate_first_failure(onsets, {})->element, 23);
  EXPECT_FALSE(laminate_first_failure({onsets[0], onsets[1]}, tips).has_value());
  EXPECT_FALSE(laminate_first_failure({}, tips).has_value());
}

TEST(DamageReport, TheFirstFailureTableMarksTheRowsAtClampTipsAndCountsThem) {
  const std::vector<DamageOnset> first = {onset_at(23, 10e-6, 1), onset_at(7, 90e-6, 4)};
  const std::string rig = first_failures_text(first, {23}, first[1]);
  EXPECT_NE(rig.find("  where\n"), std::string::npos);
  EXPECT_EQ(rig.find("clamp tip\n"), rig.find("\n", rig.find("  where\n") + 8) - 9)
      << "the first row, element 23, is marked\n"
      << rig;
  EXPECT_NE(rig.find("1 of 2 rows at clamp tips"), std::string::npos) << rig;
  EXPECT_NE(rig.find("laminate's first failure away from the clamp tips: hashin matrix-tension in ply 4, "
                     "element 7 at (0.0, 0.0) mm, t = 90.00 us"),
            std::string::npos)
      << rig;
  // Without a rig the table is the thesis's, with no column or line more.
  const std::string plain = first_failures_text(first);
  EXPECT_EQ(plain.find("where"), std::string::npos);
  EXPECT_EQ(plain.find("clamp"), std::string::npos);
  EXPECT_EQ(std::count(plain.begin(), plain.end(), '\n'), 3);
}

} // namespace
} // namespace plyimpact::damage_report_tests
