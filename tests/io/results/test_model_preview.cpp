// The model before its run (io/results/model_preview.hpp): the supports are the nodes of the deck's sets by
// type, the plan draws every element, every supported node and the contact circle to the plate's scale, the
// ply stack marks the interfaces under the plies they follow, and the files are written whole: a PNG that
// gnuplot drew and an HTML page with the same pictures and the settings.
#include "plyimpact/fem/structured_mesh.hpp"
#include "plyimpact/io/results/model_preview.hpp"
#include "plyimpact/io/results/support_words.hpp"
#include "support/cli.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cstdlib>
#include <fstream>
#include <string>

namespace model_preview_tests {

namespace {

using namespace plyimpact;
using namespace plyimpact::test;

/// The number after `key="` in the first element that has it after `from`.
double attribute(const std::string& svg, std::size_t from, const std::string& key) {
  const std::size_t at = svg.find(key + "=\"", from);
  return std::strtod(svg.c_str() + at + key.size() + 2, nullptr);
}

Laminate cross_ply() {
  Material m;
  m.name = "CFRP";
  m.E1 = 140e9, m.E2 = 10e9, m.G12 = m.G13 = 5e9, m.G23 = 3.5e9, m.nu12 = 0.3, m.rho = 1600.0;
  std::vector<Ply> plies;
  for (const double angle : {0.0, 90.0, 90.0, 0.0, 30.0})
    plies.push_back({angle, 0.25e-3, 0});
  return {{m}, plies};
}

TEST(SupportWords, TypesInWordsAndSetsGroupedByTypeInTheirOrder) {
  EXPECT_EQ(held_dofs("11100"), "u, v, w held");
  EXPECT_EQ(held_dofs("00000"), "nothing held");
  EXPECT_EQ(restraint_words("ss-soft"), "simply supported, soft (w held both ways)");
  EXPECT_EQ(restraint_words("01011"), "01011 (v, θx, θy held)");
  BoundaryConditions bc = BoundaryConditions::on_edges("ss", "clamped", "ss", "free");
  const std::vector<SupportGroup> groups = support_groups(bc);
  ASSERT_EQ(groups.size(), 3U);
  EXPECT_EQ(groups[0].type, "ss");
  EXPECT_EQ(groups[0].sets, (std::vector<std::string>{"x0", "y0"}));
  EXPECT_EQ(groups[1].words(), "xa: clamped (u, v, w, θx, θy held)");
  EXPECT_EQ(supports_in_words(BoundaryConditions{}), "none (free plate)");
  bc.corners = Restraint{{true, true, true, false, false}};
  EXPECT_TRUE(supports_in_words(bc).ends_with("; corners: 11100 (u, v, w held)"));
}

TEST(ModelPreview, SupportMarksAreTheNodesOfTheSetsOfEachType) {
  // 6 × 4 elements: an edge along y holds 2·4 + 1 = 9 nodes, one along x 2·6 + 1 = 13.
  const Mesh mesh = structured_rectangle({0.12, 0.08, false}, 6, 4);
  BoundaryConditions bc = BoundaryConditions::on_edges("ss", "ss", "clamped", "free");
  bc.corners = Restraint{{true, true, true, true, true}};
  const std::vector<SupportMarks> marks = support_marks(mesh, bc);
  ASSERT_EQ(marks.size(), 4U); // ss (x0, xa), clamped (y0), free (yb), corners
  EXPECT_EQ(marks[0].points.size(), 18U);
  EXPECT_EQ(marks[1].points.size(), 13U);
  EXPECT_EQ(marks[2].points.size(), 13U);
  EXPECT_EQ(marks[3].points.size(), 4U);
  for (const Eigen::Vector2d& p : marks[0].points)
    EXPECT_TRUE(p.x() == 0.0 || std::abs(p.x() - 0.12) < 1e-15) << p.transpose();
  EXPECT_TRUE(marks[3].label.starts_with("corners: 11111"));
}

TEST(ModelPreview, ThePlanDrawsEveryElementAndSupportedNodeAndTheContactCircleToScale) {
  const Mesh mesh = structured_rectangle({0.15, 0.10, false}, 5, 4);
  const std::vector<SupportMarks> marks =
      support_marks(mesh, BoundaryConditions::on_edges("clamped", "clamped", "ss", "ss"));
  const int width = 640;
  const std::string svg = svg_model_plan({.mesh = mesh,
                                          .supports = marks,
                                          .rig = {},
                                          .impact_point = Eigen::Vector2d(0.075, 0.05),
                                          .contact_radius = 3e-3,
                                          .contact_reached = false},
                                         width);
  EXPECT_EQ(occurrences(svg, "class=\"element\""), 20U);
  EXPECT_EQ(occurrences(svg, "class=\"support\""), marks[0].points.size() + marks[1].points.size());
  // The picture maps 150 mm onto width − 2 · 20 px: the 3 mm radius is 3 · 600/150 = 12 px, centred at
  // x = 20 + 75 · 4 = 320 px.
  const std::size_t circle = svg.find("class=\"contact\"");
  ASSERT_NE(circle, std::string::npos);
  EXPECT_NEAR(attribute(svg, circle, "r"), 12.0, 0.01);
  EXPECT_NEAR(attribute(svg, circle, "cx"), 320.0, 0.1);
  EXPECT_NE(svg.find("largest contact circle expected, radius 3 mm"), std::string::npos);
  EXPECT_NE(svg.find("x0, xa: clamped"), std::string::npos);
  // No impact point (a static deck): no circle, no cross.
  const std::string plate_only = svg_model_plan({.mesh = mesh,
                                                 .supports = marks,
                                                 .rig = {},
                                                 .impact_point = std::nullopt,
                                                 .contact_radius = 0.0,
                                                 .contact_reached = false});
  EXPECT_EQ(occurrences(plate_only, "class=\"contact\""), 0U);
  EXPECT_EQ(occurrences(plate_only, "class=\"impact\""), 0U);
}

TEST(ModelPreview, TheStackMarksEachInterfaceUnderThePlyItFollows) {
  const Laminate lam = cross_ply(); // 5 plies: ply height clamp(360/5, 4, 22) = 22 px from y = 20
  const std::string svg = svg_ply_stack(lam, {1, 3});
  ASSERT_EQ(occurrences(svg, "class=\"interface\""), 2U);
  const std::size_t first = svg.find("class=\"interface\"");
  EXPECT_NEAR(attribute(svg, first, "y1"), 20.0 + 22.0 * 1, 1e-9);
  EXPECT_NEAR(attribute(svg, svg.find("class=\"interface\"", first + 1), "y1"), 20.0 + 22.0 * 3, 1e-9);
  EXPECT_NE(svg.find("the 2 interfaces that may delaminate"), std::string::npos);
  EXPECT_EQ(occurrences(svg_ply_stack(lam), "class=\"interface\""), 0U);
}

TEST(ModelPreview, PlyColoursAreHexForEveryAngle) {
  EXPECT_EQ(ply_colour(0.0), "#4e79a7");
  EXPECT_EQ(ply_colour(-90.0), "#e15759");
  EXPECT_EQ(ply_colour(135.0), "#b07aa1"); // −45°
  // 30°: hsl(230°, 45 %, 60 %) = rgb(107, 122, 199) (Python's colorsys.hls_to_rgb)
  EXPECT_EQ(ply_colour(30.0), "#6b7ac7");
}

TEST(ModelPreview, TheFilesAreWrittenAndThePngIsDrawn) {
  const fs::path dir = scratch("model-preview");
  const ModelPreview p{.title = "a <test> plate",
                       .source = "test.toml",
                       .mesh = structured_rectangle({0.15, 0.10, false}, 5, 4),
                       .supports = {},
                       .rig = {},
                       .impact_point = Eigen::Vector2d(0.075, 0.05),
                       .contact_radius = 3e-3,
                       .laminate = cross_ply(),
                       .interfaces_after_ply = {2},
                       .settings = "SETTINGS & more\n"};
  const std::string script = model_preview_script(p, "a.svg", "a.png");
  EXPECT_EQ(occurrences(script, " rect from "), 2 * 5U);       // every ply, in the SVG and the PNG drawing
  EXPECT_EQ(occurrences(script, "lc rgb '#d62728' lw 3"), 2U); // the interface, twice
  const ModelPreviewFiles files = write_model_preview(dir, p);
  EXPECT_EQ(files.warning, "");
  for (const char* name : {"preview.txt", "preview.gp", "preview.svg", "preview.png", "preview.html"})
    EXPECT_TRUE(fs::exists(dir / name)) << name;
  EXPECT_FALSE(fs::exists(dir / "preview.gp.tmp"));
  const std::string png = read_text(dir / "preview.png");
  ASSERT_GT(png.size(), 8U);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  const std::string html = read_text(dir / "preview.html");
  EXPECT_NE(html.find("Preview: a &lt;test&gt; plate"), std::string::npos);
  EXPECT_NE(html.find("SETTINGS &amp; more"), std::string::npos);
  EXPECT_EQ(occurrences(html, "class=\"element\""), 20U);
  EXPECT_EQ(read_text(dir / "preview.txt"), p.settings);
}

} // namespace

} // namespace model_preview_tests
