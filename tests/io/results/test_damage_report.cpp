// damage_onsets.csv and damage_area.csv (io/results/damage_report): every number is the shortest text that
// reads back as the same double (issue 17), not a fixed 9 or 6 digits.
#include "plyimpact/io/results/damage_report.hpp"

#include <gtest/gtest.h>

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

} // namespace
} // namespace plyimpact::damage_report_tests
