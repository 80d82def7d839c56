// Progress displays: the ETA is the recent rate applied to the work left; plain lines appear no more
// often than asked (CI and cluster logs), a terminal bar is redrawn in place, --quiet prints nothing;
// the impact display expects the SPEC §4 end-of-event rule for end = "auto".
#include "plyimpact/io/run/impact_progress.hpp"
#include "plyimpact/io/run/progress.hpp"

#include "plyimpact/analysis/contact/contact_rules.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace progress_tests {

namespace {

using namespace plyimpact;

/// A stream that keeps what is written to it, and a clock the test moves by hand.
struct Capture {
  std::FILE* file = std::tmpfile();
  ~Capture() { std::fclose(file); }
  Capture() = default;
  Capture(const Capture&) = delete;
  Capture& operator=(const Capture&) = delete;
  [[nodiscard]] std::string text() const {
    std::fflush(file);
    std::rewind(file);
    std::string s;
    for (int c = std::fgetc(file); c != EOF; c = std::fgetc(file))
      s += static_cast<char>(c);
    return s;
  }
};

TEST(Progress, EtaIsTheElapsedRateAppliedToTheWorkLeft) {
  Capture out;
  double now = 100.0;
  Progress p("sweep", 64.0, ProgressStyle::lines, 10.0, out.file, [&] { return now; });
  // 16 of 64 cases in 20 s: 48 left at 1.25 s each = 60 s.
  EXPECT_EQ(p.line(16.0, "16 of 64 cases", 20.0), "sweep:  25 % (16 of 64 cases), 0:20 elapsed, ETA 1:00");
  EXPECT_EQ(p.line(0.0, "starting", 3.0), "sweep:   0 % (starting), 0:03 elapsed, ETA ?");
}

TEST(Progress, LinesAppearOncePerIntervalAndEndWithASummary) {
  Capture out;
  double now = 0.0;
  {
    Progress p("impact", 1.0, ProgressStyle::lines, 10.0, out.file, [&] { return now; });
    now = 4.0;
    p.update(0.2, "a"); // too early: nothing
    now = 10.0;
    p.update(0.5, "b"); // drawn
    now = 15.0;
    p.update(0.7, "c"); // 5 s after the last line: nothing
    now = 30.0;
    p.update(0.9, "d");
    p.finish("done");
  }
  EXPECT_EQ(out.text(), "impact:  50 % (b), 0:10 elapsed, ETA 0:10\n"
                        "impact:  90 % (d), 0:30 elapsed, ETA 0:05\n"
                        "impact: done, 0:30 elapsed\n");
}

TEST(Progress, AShortRunThatNeverShowedProgressStaysSilent) {
  Capture out;
  double now = 0.0;
  Progress p("impact", 1.0, ProgressStyle::lines, 10.0, out.file, [&] { return now; });
  now = 0.5;
  p.update(1.0, "all");
  p.finish("done");
  EXPECT_EQ(out.text(), "");
}

TEST(Progress, TheTerminalBarIsRedrawnInPlaceAndClearedAtTheEnd) {
  Capture out;
  double now = 0.0;
  Progress p("sweep", 4.0, ProgressStyle::bar, 10.0, out.file, [&] { return now; });
  now = 1.0;
  p.update(2.0, "2 of 4 cases");
  const std::string drawn = out.text();
  EXPECT_EQ(drawn, "\r[############............] sweep:  50 % (2 of 4 cases), 0:01 elapsed, ETA 0:01");
  now = 2.0;
  p.finish("4 cases recorded");
  const std::string all = out.text();
  std::string blank(drawn.size() + 1, ' '); // the bar overwritten with blanks between two carriage returns
  blank.front() = '\r';
  blank.back() = '\r';
  EXPECT_NE(all.find(blank), std::string::npos);
  EXPECT_TRUE(all.ends_with("sweep: 4 cases recorded, 0:02 elapsed\n")) << all;
}

TEST(Progress, QuietPrintsNothing) {
  Capture out;
  double now = 0.0;
  Progress p("sweep", 4.0, ProgressStyle::quiet, 0.0, out.file, [&] { return now; });
  now = 100.0;
  EXPECT_FALSE(p.due());
  p.update(2.0, "2 of 4");
  p.finish("done");
  EXPECT_EQ(out.text(), "");
  EXPECT_EQ(progress_style({.quiet = true, .line_interval_s = 1.0}, out.file), ProgressStyle::quiet);
  EXPECT_EQ(progress_style({}, out.file), ProgressStyle::lines); // a file is not a terminal
}

TEST(Progress, ClockTimeIsMinutesSecondsOrHoursMinutesSeconds) {
  EXPECT_EQ(clock_time(7.4), "0:07");
  EXPECT_EQ(clock_time(725.0), "12:05");
  EXPECT_EQ(clock_time(3723.0), "1:02:03");
  EXPECT_EQ(clock_time(-1.0), "?");
  EXPECT_EQ(clock_time(std::nan("")), "?");
}

TEST(Progress, EtaFollowsTheRecentRateWhenStepsGrowDearer) {
  Capture out;
  double now = 0.0;
  Progress p("impact", 1.0, ProgressStyle::lines, 10.0, out.file, [&] { return now; });
  now = 10.0;
  p.update(0.4, "fast"); // 4 %/s so far: the average gives 15 s for the 60 % left
  EXPECT_EQ(p.eta_s(0.4, 10.0), 15.0);
  now = 40.0;
  // Since the update at 10 s (older than a quarter of 40 s): 10 % in 30 s, so the 50 % left takes 150 s,
  // where the average rate (50 % in 40 s) would promise 40 s.
  p.update(0.5, "slow");
  EXPECT_DOUBLE_EQ(p.eta_s(0.5, 40.0), 150.0);
  EXPECT_NE(out.text().find("impact:  50 % (slow), 0:40 elapsed, ETA 2:30"), std::string::npos) << out.text();
  // A fraction that fell (the event estimate grew) measures from an older, lower sample: the one at 10 s.
  EXPECT_DOUBLE_EQ(p.eta_s(0.45, 80.0), (80.0 - 10.0) * 0.55 / 0.05);
}

TEST(ImpactProgress, ExpectsTheDecksEndOrTheEndOfEventRule) {
  ImpactSettings s;
  s.impactor.mass = 6.14;
  s.impactor.velocity = 2.68;
  s.k = 0.6e9;
  StepView v;
  s.end = 3e-3;
  EXPECT_EQ(expected_run_time(s, v, -1.0, 1e-3), 3e-3);
  s.end.reset();
  // Before contact: twice the rigid-target Hertz time, when it exceeds 2 T1.
  v.impactor_v = 2.68;
  const double rigid = hertz_contact_time(6.14, 2.68, 0.6e9);
  EXPECT_DOUBLE_EQ(expected_run_time(s, v, -1.0, 0.0), 2.0 * rigid);
  // The rule's other term: out of contact for two fundamental periods when they are longer.
  EXPECT_DOUBLE_EQ(expected_run_time(s, v, -1.0, rigid), 3.0 * rigid);
  // In contact, half-sine: v = v0 cos(pi t / T) at t = T/3 gives T = 6 ms (longer than rigid).
  v.t = 2e-3;
  v.impactor_v = 2.68 * std::cos(std::numbers::pi / 3.0);
  EXPECT_NEAR(expected_run_time(s, v, -1.0, 1e-3), 12e-3, 1e-12);
  EXPECT_NEAR(expected_run_time(s, v, -1.0, 4e-3), 14e-3, 1e-12); // 6 ms + 2 x 4 ms
  // After separation at 4.27 ms: the SPEC §4 rule runs max(contact duration, 2 T1) more.
  EXPECT_DOUBLE_EQ(expected_run_time(s, v, 4.27e-3, 1e-3), 8.54e-3);
  EXPECT_DOUBLE_EQ(expected_run_time(s, v, 4.27e-3, 3e-3), 10.27e-3);
}

} // namespace

} // namespace progress_tests
