// report.html (io/results/html_report.hpp, io/results/svg_plot.hpp): the tick rule, the thinned history
// behind the curves, and the report of the §4.3 run (damage tracked) — self-contained, complete, and rendered
// by headless Chromium without console errors (the screenshot is docs/images/report-html.png); a sweep's
// report opened the same way (docs/images/sweep-report-html.png).
#include "plyimpact/analysis/impact/recorders.hpp"
#include "plyimpact/fem/structured_mesh.hpp"
#include "plyimpact/io/results/svg_plot.hpp"
#include "support/browser.hpp"
#include "support/cli.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace html_report_tests {

namespace {

using namespace plyimpact;
using namespace plyimpact::test;

TEST(SvgPlot, TicksAreOneTwoFiveStepsThatEncloseTheRange) {
  // 12 661.7 N over about 5 intervals: raw step 2532 rounds up to 5000; 0 … 15 000 encloses it.
  EXPECT_EQ(nice_ticks(0.0, 12661.7), (std::vector<double>{0.0, 5000.0, 10000.0, 15000.0}));
  // 0 … 4.312 ms: raw 0.86 → 1.
  EXPECT_EQ(nice_ticks(0.0, 4.312), (std::vector<double>{0.0, 1.0, 2.0, 3.0, 4.0, 5.0}));
  // A negative range and a zero-width one.
  EXPECT_EQ(nice_ticks(-0.3, 0.1), (std::vector<double>{-0.3, -0.2, -0.1, 0.0, 0.1}));
  const std::vector<double> flat = nice_ticks(2.0, 2.0);
  EXPECT_LE(flat.front(), 2.0);
  EXPECT_GE(flat.back(), 2.0);
  EXPECT_GE(flat.size(), 2U);
}

TEST(SvgPlot, TextIsEscapedAndEveryPointIsInsideThePicture) {
  EXPECT_EQ(xml_escaped("a < b & \"c\" > d"), "a &lt; b &amp; &quot;c&quot; &gt; d");
  const std::string svg =
      svg_line_plot({"F <t>", "t [ms]", "F [kN]", {{"", {0.0, 1.0, 2.0}, {0.0, 5.0, 1.0}}}});
  EXPECT_NE(svg.find("F &lt;t&gt;"), std::string::npos);
  // The polyline's points "x,y x,y ...", read by hand (std::regex trips GCC 12's -Wmaybe-uninitialized
  // under the sanitizers).
  const std::size_t from = svg.find("points=\"") + 8;
  std::istringstream list(svg.substr(from, svg.find('"', from) - from));
  int points = 0;
  for (std::string pair; list >> pair; ++points) {
    const double x = std::stod(pair.substr(0, pair.find(','))),
                 y = std::stod(pair.substr(pair.find(',') + 1));
    EXPECT_GE(x, 0.0);
    EXPECT_LE(x, 640.0);
    EXPECT_GE(y, 0.0);
    EXPECT_LE(y, 360.0);
  }
  EXPECT_EQ(points, 3);
}

TEST(SvgPlot, APointThatIsNotFiniteIsAGapBetweenTwoLines) {
  // Five points, the third NaN: two lines of two points each, not one line drawn across the gap.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::string svg =
      svg_line_plot({"", "x", "y", {{"", {0.0, 1.0, nan, 3.0, 4.0}, {0.0, 1.0, 2.0, 1.0, 0.0}}}});
  EXPECT_EQ(occurrences(svg, "<polyline"), 2U);
  EXPECT_EQ(occurrences(svg, ","), 4U) << "one comma per point drawn";
}

/// The first legend line's (x1, y1) in an SVG plot (the first 2 px wide line; the grid's are thinner).
std::array<double, 2> legend_at(const std::string& svg) {
  const std::size_t at = svg.rfind("<line x1=\"", svg.find("stroke-width=\"2\""));
  const std::size_t y = svg.find("y1=\"", at);
  return {std::stod(svg.substr(at + 10)), std::stod(svg.substr(y + 4))};
}

TEST(SvgPlot, TheLegendGoesWhereItCoversNoCurve) {
  // Two curves on 640 x 360 px: a line across the top-right corner sends the legend to the top left; curves
  // through all four corners and across the middle of the left side send it to the middle of the right,
  // which the energy plot of a rebound leaves free (issue 82).
  std::vector<double> t(201);
  for (std::size_t i = 0; i < t.size(); ++i)
    t[i] = 0.01 * static_cast<double>(i); // 0 ... 2
  const auto curve = [&](const std::function<double(double)>& y, const char* label) {
    PlotSeries c{label, t, {}, "#1f77b4"};
    for (const double x : t)
      c.y.push_back(y(x));
    return c;
  };
  const PlotSeries flat = curve([](double) { return 0.0; }, "flat");
  const PlotSeries rising = curve([](double x) { return x > 1.0 ? 10.0 * (x - 1.0) : 0.0; }, "rising");
  const std::array<double, 2> free_left = legend_at(svg_line_plot({"", "x", "y", {flat, rising}}));
  EXPECT_LT(free_left[0], 100.0) << "left";
  EXPECT_LT(free_left[1], 60.0) << "top";
  // Level lines at 1 and 9 across the whole width cover the corners and the middles of the top and bottom;
  // a line at 5 up to x = 1.2 covers the middle of the left side and the centre: the middle of the right
  // side is left, as the energy plot of a rebound leaves it (issue 82).
  const PlotSeries low = curve([](double) { return 1.0; }, "low");
  const PlotSeries high = curve([](double) { return 9.0; }, "high");
  const PlotSeries half = curve([](double x) { return x < 1.2 ? 5.0 : NAN; }, "half");
  // (the fourth, a diagonal from (0, 0) to (2, 10), fixes the axes and passes through the centre)
  const PlotSeries diagonal{"diagonal", {0.0, 2.0}, {0.0, 10.0}};
  const std::array<double, 2> middle_right =
      legend_at(svg_line_plot({"", "x", "y", {low, high, half, diagonal}}));
  EXPECT_GT(middle_right[0], 400.0) << "right";
  EXPECT_GT(middle_right[1], 100.0) << "not at the top";
  EXPECT_LT(middle_right[1], 220.0) << "not at the bottom";
}

TEST(SvgPlot, TheOnsetMapOnARigCirclesTheClampTipsAndDashesTheWindow) {
  const Mesh mesh = structured_rectangle({0.150, 0.100}, 6, 4);
  RigOutline rig;
  rig.window = {{0.0125, 0.0125}, {0.1375, 0.0125}, {0.1375, 0.0875}, {0.0125, 0.0875}};
  rig.clamp_tips = {{0.025, 0.00625}, {0.125, 0.00625}, {0.125, 0.09375}, {0.025, 0.09375}};
  const std::string svg = svg_onset_map(mesh, {}, 0.075, 0.05, rig);
  EXPECT_EQ(occurrences(svg, "class=\"clamp\""), 4U);
  EXPECT_EQ(occurrences(svg, "class=\"window\""), 1U);
  EXPECT_NE(svg.find(xml_escaped(clamp_tip_note)), std::string::npos);
  const std::string bare = svg_onset_map(mesh, {}, 0.075, 0.05);
  EXPECT_EQ(occurrences(bare, "class=\"clamp\""), 0U);
  EXPECT_EQ(occurrences(bare, "class=\"window\""), 0U);
}

TEST(SvgPlot, TheCscanShowsTheShallowestDelaminatedInterfaceAtEachPoint) {
  // Three interfaces over four points: at point 0 none has delaminated (d = 0.999 is a process zone, not
  // a crack), at 1 the first and third (the first hides the third), at 2 the second and third, at 3 only
  // the third. The picture fills the three delaminated points' cells in their interface's colour and
  // gives each interface the area it shows.
  const std::vector<std::vector<double>> d{
      {0.0, 1.0, 0.3, 0.0}, {0.999, 0.5, 1.0, 0.0}, {0.2, 1.0, 1.0, 1.0}};
  const std::vector<int> shallowest = shallowest_delaminated(d);
  EXPECT_EQ(shallowest, (std::vector<int>{0, 1, 2, 3}));
  std::vector<std::array<Eigen::Vector2d, 4>> cells;
  for (int q = 0; q < 4; ++q)
    cells.push_back({Eigen::Vector2d(q * 1e-3, 0.0), Eigen::Vector2d((q + 1) * 1e-3, 0.0),
                     Eigen::Vector2d((q + 1) * 1e-3, 1e-3), Eigen::Vector2d(q * 1e-3, 1e-3)});
  const std::vector<double> area{1e-6, 2e-6, 3e-6, 4e-6};
  const std::vector<int> after_ply{2, 4, 6};
  const std::string svg = svg_cscan_map({cells, area, shallowest, after_ply, 2e-3, 0.5e-3, {}});
  for (int i = 1; i <= 3; ++i)
    EXPECT_EQ(occurrences(svg, fmt::format("<polygon fill=\"{}\"", cscan_colour(i))), 1U) << i;
  EXPECT_NE(svg.find("interface after ply 2: 2 mm² seen"), std::string::npos) << svg;
  EXPECT_NE(svg.find("interface after ply 4: 3 mm² seen"), std::string::npos) << svg;
  EXPECT_NE(svg.find("interface after ply 6: 4 mm² seen"), std::string::npos) << svg;
  EXPECT_STRNE(cscan_colour(1), cscan_colour(2));
  EXPECT_STREQ(cscan_colour(11), cscan_colour(1)); // ten colours, then again
}

TEST(ThinnedHistory, KeepsABoundedEvenlySpacedSubsetOfTheSteps) {
  // 10 000 steps into 64 samples: the stride doubles to 256, every kept step is a multiple of it, and the
  // last step is always there.
  ThinnedHistory h(64);
  StepView v;
  v.step = 0;
  h.on_start(v);
  for (long s = 1; s <= 10000; ++s) {
    v.step = s;
    v.t = static_cast<double>(s);
    h.on_step(v);
  }
  h.on_finish(v, ImpactResult{});
  ASSERT_LT(h.samples().size(), 64U);
  ASSERT_GE(h.samples().size(), 32U);
  for (std::size_t i = 0; i + 1 < h.samples().size(); ++i)
    EXPECT_EQ(static_cast<long>(h.samples()[i].t) % 256, 0) << i;
  EXPECT_EQ(h.samples().back().t, 10000.0);
}

/// The §4.3 example (damage tracked) run into a folder of its own for each test (ctest runs the tests
/// of this file side by side).
fs::path thesis_4_3_results(const std::string& test) {
  const fs::path dir = scratch("html-report-" + test) / "thesis-4.3";
  const CommandResult r =
      run(std::string("impact ") + PLYIMPACT_SOURCE_DIR + "/examples/thesis-4.3.toml -q -o " + dir.string());
  EXPECT_EQ(r.status, 0) << r.out;
  return dir;
}

std::string read(const fs::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(HtmlReport, IsOneSelfContainedFileWithEveryPlotAndTable) {
  const fs::path dir = thesis_4_3_results("content");
  const std::string html = read(dir / "report.html");
  ASSERT_FALSE(html.empty());
  EXPECT_EQ(occurrences(html, "<svg"), 6U) << "three curves, the ply stack, the plan and the onset map";
  EXPECT_EQ(occurrences(html, "class=\"plot\""), 3U);
  EXPECT_EQ(occurrences(html, "class=\"plies\""), 1U);
  EXPECT_EQ(occurrences(html, "class=\"plan\""), 1U);
  EXPECT_EQ(occurrences(html, "class=\"map\""), 1U);
  EXPECT_EQ(occurrences(html, "<table class=\"summary\">"), 1U);
  EXPECT_EQ(occurrences(html, "<table class=\"onsets\">"), 1U);
  EXPECT_EQ(occurrences(html, "<th>where</th>"), 0U) << "no rig, no clamp tips: no column for them";
  // No script and nothing fetched: the only URL is the SVG namespace.
  EXPECT_EQ(occurrences(html, "<script"), 0U);
  EXPECT_EQ(occurrences(html, "http"), occurrences(html, "xmlns=\"http://www.w3.org/2000/svg\""));
  EXPECT_EQ(occurrences(html, "src="), 0U);
  // The numbers are summary.json's: the peak force to 5 digits.
  const nlohmann::json summary = nlohmann::json::parse(read(dir / "summary.json"));
  // The plan's contact circle is the run's largest, √(R α_max) with the deck's R = 6.35 mm, and the 127 mm
  // plate spans the plan's 640 − 2 · 20 px.
  const double radius = std::sqrt(6.35e-3 * summary["max_indentation"].get<double>());
  EXPECT_NE(html.find(fmt::format("largest contact circle of the run, radius {:.3g} mm", radius * 1e3)),
            std::string::npos);
  const std::size_t circle = html.find("class=\"contact\"");
  ASSERT_NE(circle, std::string::npos);
  const std::size_t r_at = html.find("r=\"", circle) + 3;
  EXPECT_NEAR(std::strtod(html.c_str() + r_at, nullptr), radius * 600.0 / 0.127, 0.01);
  EXPECT_NE(html.find(fmt::format("{:.5g} N", summary["peak_force"].get<double>())), std::string::npos);
  EXPECT_NE(html.find("[0_2/90_4/0_2]"), std::string::npos);
  // What report.txt prints beside them (issue 82): the first load drop F_d; the absorbed energy by
  // mechanism only once the impactor has left, which it has not at the §4.3 run's end.
  EXPECT_NE(
      html.find(fmt::format("first load drop F<sub>d</sub></th><td class=\"number\">{:.5g} N at {:.4g} ms",
                            summary["load_drop"]["force_N"].get<double>(),
                            summary["load_drop"]["time_s"].get<double>() * 1e3)),
      std::string::npos);
  ASSERT_TRUE(summary["absorbed_energy_by_mechanism"].is_null());
  EXPECT_EQ(occurrences(html, "absorbed by ply damage"), 0U);
}

TEST(HtmlReport, FirstFailuresAtTheRigsClampTipsAreMarkedAndAreNotTheLaminatesFirstFailure) {
  // The coupon of bench/decks/coupon-onset.toml (25 J on the ASTM D7136 rig, Hashin and Choi-Chang tracked)
  // to 250 us: by then the clamp tip at (125, 93.75) mm has reached both criteria in several plies (its
  // point support's stress is singular), beside the matrix cracks under the impactor from 70 us on.
  const fs::path dir = scratch("html-report-clamp-tips");
  fs::create_directories(dir);
  std::ofstream(dir / "coupon.toml") << read(fs::path(PLYIMPACT_SOURCE_DIR) / "bench/decks/coupon-onset.toml")
                                     << "\n[time]\nend = 0.25e-3\n";
  const CommandResult r =
      run("impact " + (dir / "coupon.toml").string() + " -q -o " + (dir / "out").string());
  ASSERT_EQ(r.status, 0) << r.out;
  const nlohmann::json summary = nlohmann::json::parse(read(dir / "out" / "summary.json"));
  const std::array<Eigen::Vector2d, 4> tips = {
      Eigen::Vector2d(0.025, 0.00625), Eigen::Vector2d(0.125, 0.00625), Eigen::Vector2d(0.125, 0.09375),
      Eigen::Vector2d(0.025, 0.09375)};
  const auto to_nearest_tip = [&](const nlohmann::json& onset) {
    const Eigen::Vector2d p(onset["x"].get<double>(), onset["y"].get<double>());
    double gap = INFINITY;
    for (const Eigen::Vector2d& tip : tips)
      gap = std::min(gap, (p - tip).norm());
    return gap;
  };
  int marked = 0;
  for (const nlohmann::json& f : summary["first_failures"]) {
    // a marked row's Gauss point lies in an element at a tip: within the rig's largest element (9.4 mm)
    // times the square root of two of it
    if (f["at_clamp_tip"].get<bool>()) {
      EXPECT_LT(to_nearest_tip(f), 0.0134) << f.dump();
    }
    marked += f["at_clamp_tip"].get<bool>() ? 1 : 0;
  }
  EXPECT_GE(marked, 4);
  // The laminate's first failure lies under the impactor, and comes first among the rows not marked.
  const nlohmann::json& first = summary["laminate_first_failure"];
  ASSERT_FALSE(first.is_null());
  EXPECT_GT(to_nearest_tip(first), 0.03);
  for (const nlohmann::json& f : summary["first_failures"])
    if (!f["at_clamp_tip"].get<bool>()) {
      EXPECT_LE(first["time"].get<double>(), f["time"].get<double>());
    }
  // The HTML marks the same rows and says which failure is the laminate's.
  const std::string html = read(dir / "out" / "report.html");
  EXPECT_EQ(occurrences(html, "<td>clamp tip</td>"), static_cast<std::size_t>(marked));
  EXPECT_NE(html.find(fmt::format("The laminate's first failure: {} {} in ply {}, element {}",
                                  first["criterion"].get<std::string>(), first["mode"].get<std::string>(),
                                  first["ply"].get<int>(), first["element"].get<int>())),
            std::string::npos);
  EXPECT_NE(html.find(fmt::format("{} of the {} first failures below lie at the rig's clamp tips", marked,
                                  summary["first_failures"].size())),
            std::string::npos);
  // and so does report.txt
  EXPECT_NE(read(dir / "out" / "report.txt")
                .find(fmt::format("{} of {} rows at clamp tips", marked, summary["first_failures"].size())),
            std::string::npos);
}

TEST(HtmlReport, ForceDisplacementIsTheContactLoopWithoutTheReboundFlight) {
  // The §3.6 impactor rebounds and flies back for the rest of the event, its displacement far below
  // zero; a drop-weight report plots force against displacement while in contact only (α ≥ 0), the
  // loading and unloading loop. So the plot's x axis ends one tick below the lowest displacement in
  // contact (the plate springs back slightly past zero before the impactor leaves it), far above the
  // flight's.
  const fs::path dir = scratch("html-report-loop") / "thesis-3.6-v268";
  ASSERT_EQ(run(std::string("impact ") + PLYIMPACT_SOURCE_DIR + "/examples/thesis-3.6-v268.toml -q -o " +
                dir.string())
                .status,
            0);
  const std::string html = read(dir / "report.html");
  const std::size_t from = html.find("aria-label=\"Force–displacement (impactor, in contact)\"");
  ASSERT_NE(from, std::string::npos);
  const std::string svg = html.substr(from, html.find("</svg>", from) - from);
  std::vector<double> ticks_mm; // the x axis's labels (text-anchor middle; the y axis's are anchored end)
  const std::string label = "text-anchor=\"middle\">";
  for (std::size_t at = svg.find(label); at != std::string::npos; at = svg.find(label, at + 1))
    ticks_mm.push_back(std::stod(svg.substr(at + label.size())));
  ASSERT_GE(ticks_mm.size(), 2U);
  double in_contact = 0.0, overall = 0.0; // lowest impactor displacement [mm]
  std::ifstream history(dir / "history.csv");
  std::string line;
  std::getline(history, line); // t_s,force_N,impactor_w_m,impactor_v_m_per_s,plate_w_m,indentation_m,...
  for (; std::getline(history, line);) {
    std::vector<double> v;
    for (std::size_t a = 0, b = 0; v.size() < 6; a = b + 1) {
      b = line.find(',', a);
      v.push_back(std::stod(line.substr(a, b - a)));
    }
    overall = std::min(overall, 1e3 * v[2]);
    if (v[5] >= 0.0) in_contact = std::min(in_contact, 1e3 * v[2]);
  }
  const double step = ticks_mm[1] - ticks_mm[0];
  std::printf(
      "[ measured ] x ticks %g ... %g mm; lowest impactor displacement %g mm in contact, %g mm in all\n",
      ticks_mm.front(), ticks_mm.back(), in_contact, overall);
  EXPECT_LE(ticks_mm.front(), in_contact);
  EXPECT_GT(ticks_mm.front(), in_contact - step - 1e-9);
  EXPECT_LT(overall, ticks_mm.front() - 5.0) << "the flight, left out, goes far lower";
  EXPECT_GE(occurrences(svg, "<polyline"), 1U);
  // The time plots end a fifth past the last contact (4.3 ms), not at the run's end (8.6 ms): the contact
  // force plot's last x tick is the first at or past 1.2 times the contact's end.
  const nlohmann::json run_summary = nlohmann::json::parse(read(dir / "summary.json"));
  const double contact_end_ms = 1e3 * run_summary["contact_duration"].get<double>();
  const std::size_t force_at = html.find("aria-label=\"Contact force\"");
  ASSERT_NE(force_at, std::string::npos);
  const std::string force_svg = html.substr(force_at, html.find("</svg>", force_at) - force_at);
  std::vector<double> ticks_ms;
  for (std::size_t at = force_svg.find(label); at != std::string::npos; at = force_svg.find(label, at + 1))
    ticks_ms.push_back(std::stod(force_svg.substr(at + label.size())));
  ASSERT_GE(ticks_ms.size(), 2U);
  std::printf("[ measured ] contact ends at %g ms, the run at %g ms; force plot ticks to %g ms\n",
              contact_end_ms, 1e3 * run_summary["end_time"].get<double>(), ticks_ms.back());
  EXPECT_GE(ticks_ms.back(), 1.2 * contact_end_ms * (1.0 - 1e-3));
  EXPECT_LT(ticks_ms[ticks_ms.size() - 2], 1.2 * contact_end_ms);
  EXPECT_LT(ticks_ms.back(), 1e3 * run_summary["end_time"].get<double>());
  EXPECT_NE(html.find("The time plots end at"), std::string::npos);
  // The impactor rebounds: the absorbed energy by mechanism, a row each, as summary.json gives it.
  const nlohmann::json mechanism =
      nlohmann::json::parse(read(dir / "summary.json"))["absorbed_energy_by_mechanism"];
  ASSERT_FALSE(mechanism.is_null());
  EXPECT_NE(html.find(fmt::format("absorbed by contact (indentation)</th><td class=\"number\">{:.5g} J",
                                  mechanism["contact_J"].get<double>())),
            std::string::npos);
  EXPECT_NE(html.find(fmt::format("left in plate vibration</th><td class=\"number\">{:.5g} J",
                                  mechanism["plate_vibration_J"].get<double>())),
            std::string::npos);
  EXPECT_EQ(occurrences(html, "absorbed by ply damage"), 1U);
  EXPECT_EQ(occurrences(html, "absorbed by delamination"), 1U);
}

TEST(HtmlReport, OpensInHeadlessChromiumWithoutConsoleErrors) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "the browser check runs in the release build";
#endif
  ASSERT_EQ(shell("command -v chromium").status, 0)
      << "chromium is missing: scripts/install-deps installs it";
  const fs::path dir = thesis_4_3_results("chromium");
  const fs::path png = dir / "report.png";
  const BrowserView view = open_in_headless_chromium(dir / "report.html", png, 1100, 4200);
  ASSERT_EQ(view.screenshot.status, 0) << view.screenshot.out;
  expect_no_console_errors(view.screenshot);
  ASSERT_TRUE(fs::exists(png)) << view.screenshot.out;
  EXPECT_GT(fs::file_size(png), 50'000U);
  // The DOM the browser built holds every plot and table.
  ASSERT_EQ(view.dom.status, 0) << view.dom.out;
  expect_no_console_errors(view.dom);
  EXPECT_EQ(occurrences(view.dom.out, "class=\"plot\""), 3U);
  EXPECT_EQ(occurrences(view.dom.out, "<table class=\"summary\">"), 1U);
  EXPECT_EQ(occurrences(view.dom.out, "<table class=\"onsets\">"), 1U);
  if (const char* keep = std::getenv("PLYIMPACT_KEEP_REPORT_PNG"))
    fs::copy_file(png, keep, fs::copy_options::overwrite_existing);
}

TEST(HtmlReport, SweepReportOpensInHeadlessChromiumWithEveryPlotAndCase) {
  // examples/sweep-4.2-table4.1.toml: three plate widths x two masses. Its report.html, as the browser
  // builds it: peak force and absorbed energy against both swept keys, and the six cases in the table.
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "the browser check runs in the release build";
#endif
  ASSERT_EQ(shell("command -v chromium").status, 0)
      << "chromium is missing: scripts/install-deps installs it";
  const fs::path dir = scratch("html-report-sweep") / "table4.1";
  const CommandResult r = run(std::string("sweep ") + PLYIMPACT_SOURCE_DIR +
                              "/examples/sweep-4.2-table4.1.toml -q --jobs 2 -o " + dir.string());
  ASSERT_EQ(r.status, 0) << r.out;
  const fs::path png = dir / "report.png";
  const BrowserView view = open_in_headless_chromium(dir / "report.html", png, 1100, 1320);
  ASSERT_EQ(view.screenshot.status, 0) << view.screenshot.out;
  expect_no_console_errors(view.screenshot);
  EXPECT_GT(fs::file_size(png), 50'000U);
  ASSERT_EQ(view.dom.status, 0) << view.dom.out;
  expect_no_console_errors(view.dom);
  EXPECT_EQ(occurrences(view.dom.out, "class=\"plot\""), 4U);
  EXPECT_EQ(occurrences(view.dom.out, "<table class=\"cases\">"), 1U);
  EXPECT_EQ(occurrences(view.dom.out, "<td>ok</td>"), 6U);
  if (const char* keep = std::getenv("PLYIMPACT_KEEP_SWEEP_REPORT_PNG"))
    fs::copy_file(png, keep, fs::copy_options::overwrite_existing);
}

} // namespace

} // namespace html_report_tests
