// Plates meshed by gmsh on the fly ([mesh] geo, io/mesh/gmsh_mesh.hpp): the size field graded toward the
// impact point, and the ASTM D7136 coupon (examples/meshes/astm-d7136-coupon.geo) resting on its window.
//
// A support the plate may lift off holds a subset of what the bilateral window ("ss-soft") holds, and a
// plate held at fewer points is softer under the same force (the work of the load is the largest
// over the smaller set of constraints), so under a central force
//   clamped window < bilateral window ≤ unilateral window ≤ window held only where it surely touches
// (the middle thirds of its edges). The plate lifts off at the window's corners, between the clamps.
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/analysis/plate_analyses/static_analysis.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/io/mesh/gmsh_mesh.hpp"
#include "support/decks.hpp"
#include "support/gmsh_meshes.hpp"
#include "test_paths.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace plyimpact::gmsh_geometry_tests {
namespace {

namespace fs = std::filesystem;

const fs::path coupon_geo = fs::path(PLYIMPACT_SOURCE_DIR) / "examples/meshes/astm-d7136-coupon.geo";
constexpr double a = 0.150, b = 0.100, wa = 0.125, wb = 0.075, P = 1000.0;

/// The coupon's mesh, 2 mm elements at the centre growing to 5 mm.
Mesh coupon_mesh() {
  GeometryMeshing how;
  how.size_at_point = 2e-3;
  how.max_size = 5e-3;
  return mesh_gmsh_geometry(coupon_geo, how);
}

/// T300/976 [45/0/-45/90]2s, 4 mm, as examples/static-astm-d7136-window.toml; the clamps hold u, v, w.
StaticResult centre_loaded(Mesh mesh, std::string_view window, const std::string& window_set = "window") {
  BoundaryConditions bc;
  bc.set("clamps", "11100");
  bc.set(window_set, window);
  const DiscretePlate model(
      std::move(mesh), PlateSections{{test::laminate_of(test::t300_976(), "[45/0/-45/90]2s", 0.25e-3)}, {}},
      Discretization{}, std::move(bc));
  StaticLoad load;
  load.point = PointLoad{a / 2, b / 2, P};
  return solve_static(model, load);
}

/// The window's nodes in the middle third of each of its edges.
std::vector<int> window_middle_thirds(const Mesh& mesh) {
  std::vector<int> nodes;
  const double x0 = (a - wa) / 2, y0 = (b - wb) / 2;
  for (const int n : mesh.node_set("window")) {
    const Eigen::Vector2d p = mesh.node(n);
    const bool along_x =
        std::abs(p.x() - a / 2) < wa / 6 && (std::abs(p.y() - y0) < 1e-9 || std::abs(p.y() - y0 - wb) < 1e-9);
    const bool along_y =
        std::abs(p.y() - b / 2) < wb / 6 && (std::abs(p.x() - x0) < 1e-9 || std::abs(p.x() - x0 - wa) < 1e-9);
    if (along_x || along_y) nodes.push_back(n);
  }
  return nodes;
}

// The element count a size field asks for (estimated_element_count), which refuses a field of more than 10^6
// elements before gmsh meshes: against the integral of 1/h² done by hand.
TEST(EstimatedElementCount, AUniformSizeGivesTheAreaOverTheSquareOfTheSize) {
  GeometryMeshing how;
  how.size_at_point = 0.004;
  how.growth = 1.0; // h = 4 mm everywhere: 0.1 x 0.08 m / (4 mm)² = 500
  const BoundingBox box{0.0, 0.1, 0.0, 0.08};
  EXPECT_NEAR(estimated_element_count(box, {0.03, 0.05}, how), 500.0, 5.0);
  EXPECT_NEAR(estimated_element_count(box, {0.2, -1.0}, how), 500.0, 5.0); // a point off the box: clamped
  how.size_at_point.reset(); // the geometry's own sizes: not estimated
  EXPECT_EQ(estimated_element_count(box, {0.03, 0.05}, how), 0.0);
}

TEST(EstimatedElementCount, AGradedSizeGivesTheDiskIntegralInsideAndTheCapOutside) {
  // h = s + a r up to H: inside r_H = (H − s)/a the integral 2π ∫ r dr/(s + a r)² is
  // 2π/a² [ln(H/s) + s/H − 1]; outside, the rest of the 1 x 1 m box at H: (1 − π r_H²)/H².
  GeometryMeshing how;
  how.size_at_point = 1e-3;
  how.growth = 1.25;
  how.max_size = 1e-2;
  const double slope = 0.25, s = 1e-3, H = 1e-2, r_H = (H - s) / slope;
  const double inside = 2.0 * M_PI / (slope * slope) * (std::log(H / s) + s / H - 1.0);
  const double outside = (1.0 - M_PI * r_H * r_H) / (H * H);
  const double n = estimated_element_count({0.0, 1.0, 0.0, 1.0}, {0.5, 0.5}, how);
  std::printf("  estimated %.1f, by hand %.1f (%.1f inside r_H = %.3f m)\n", n, inside + outside, inside,
              r_H);
  EXPECT_NEAR(n, inside + outside, 0.01 * (inside + outside));
}

TEST(GmshGeometry, TheSizeFieldGradesTheElementsTowardTheImpactPoint) {
  const Mesh mesh = coupon_mesh();
  const Eigen::Vector2d centre(a / 2, b / 2);
  double smallest_near = 1.0, largest_far = 0.0;
  for (int e = 0; e < mesh.element_count(); ++e) {
    const Eigen::Vector2d c = mesh.node(mesh.element_nodes(e)[8]);
    const double size = std::sqrt(mesh.element_area(e));
    if ((c - centre).norm() < 4e-3) smallest_near = std::min(smallest_near, size);
    if ((c - centre).norm() > 40e-3) largest_far = std::max(largest_far, size);
  }
  EXPECT_LT(smallest_near, 3e-3) << "about size_at_impact = 2 mm at the impact point";
  EXPECT_GT(largest_far, 3.5e-3) << "toward max_size = 5 mm far from it";
  EXPECT_LT(largest_far, 7e-3);
  for (const char* set : {"edges", "window", "clamps", "centre", "plate"})
    EXPECT_TRUE(mesh.has_node_set(set)) << set;
  EXPECT_EQ(mesh.node_set("clamps").size(), 4U);
}

TEST(GmshGeometry,
     TheCouponOnItsWindowLiesBetweenTheBilateralAndTheMiddleThirdsSupportsAndLiftsAtTheCorners) {
  const Mesh mesh = coupon_mesh();
  const double clamped = centre_loaded(mesh, "clamped").load_point_deflection;
  const double bilateral = centre_loaded(mesh, "ss-soft").load_point_deflection;
  const StaticResult resting = centre_loaded(mesh, "unilateral");
  Mesh thirds = mesh;
  thirds.add_node_set("window thirds", window_middle_thirds(mesh));
  const double held_in_thirds = centre_loaded(thirds, "ss-soft", "window thirds").load_point_deflection;
  const double w = resting.load_point_deflection;
  std::printf(
      "  centre deflection [m]: clamped window %.6e, bilateral %.6e, unilateral %.6e (%d of %zu nodes "
      "touch, largest lift-off %.3e m), middle thirds only %.6e\n",
      clamped, bilateral, w, touching_count(resting.support_contacts), resting.support_contacts.size(),
      largest_lift_off(resting.support_contacts), held_in_thirds);
  EXPECT_LT(clamped, bilateral);
  EXPECT_LT(bilateral, w) << "lifting off makes the plate softer";
  EXPECT_LT(w, held_in_thirds) << "it touches at least the middle thirds of the window's edges";

  // Lift-off at the window's four corners (w < 0, no force); the support pushes (R ≤ 0) where it touches.
  const double x0 = (a - wa) / 2, y0 = (b - wb) / 2;
  int corners = 0;
  for (const SupportContact& c : resting.support_contacts) {
    const Eigen::Vector2d p = mesh.node(c.node);
    const bool corner = (std::abs(p.x() - x0) < 1e-9 || std::abs(p.x() - x0 - wa) < 1e-9) &&
                        (std::abs(p.y() - y0) < 1e-9 || std::abs(p.y() - y0 - wb) < 1e-9);
    if (corner) {
      ++corners;
      EXPECT_FALSE(c.touching) << "corner (" << p.x() << ", " << p.y() << ")";
      EXPECT_LT(c.w, 0.0);
      EXPECT_EQ(c.reaction, 0.0);
    }
    EXPECT_LE(c.reaction, 0.0) << "the window only pushes, node " << c.node;
    EXPECT_LE(c.w, 1e-12 * w) << "the plate never sinks into the window, node " << c.node;
  }
  EXPECT_EQ(corners, 4);
  EXPECT_GT(touching_count(resting.support_contacts), 0);
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("plyimpact-geo-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// The coupon deck of examples/static-astm-d7136-window.toml with its [mesh] and [boundary] replaced.
std::string coupon_deck(const std::string& analysis, const std::string& mesh, const std::string& boundary) {
  return fmt::format(R"(analysis = "{}"
[materials.T300_976]
E1 = 144.8e9
E2 = 9.65e9
G12 = 7.10e9
nu12 = 0.30
rho = 1389.2
[laminate]
material = "T300_976"
layup = "[45/0/-45/90]2s"
ply_thickness = 0.25e-3
[mesh]
{}
[boundary]
{}
[load.point]
x = 0.075
y = 0.050
force = 1000.0
[impactor]
mass = 5.5
radius = 0.008
E = 210e9
velocity = 1.0
)",
                     analysis, mesh, boundary);
}

/// The message of the error that parsing (and, for an impact, building the case of) `deck` throws.
std::string deck_error(const std::string& deck, const fs::path& where) {
  try {
    const Deck d = parse_deck(deck, (where / "deck.toml").string());
    if (d.analysis == AnalysisKind::impact) (void)ImpactCase(impact_case_description(d));
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no error)";
}

const std::string coupon_mesh_keys =
    fmt::format("geo = \"{}\"\nsize_at_impact = 4e-3\nmax_size = 8e-3", coupon_geo.string());

TEST(GmshGeometry, BadGeometriesAndKeysAreRefusedWithWhatIsWrong) {
  const fs::path dir = scratch("bad");
  const std::string clamps = "clamps = \"11100\"";
  std::ofstream(dir / "broken.geo") << "Point(1) = {0, 0, 0;\n";
  const std::string broken = deck_error(coupon_deck("static", "geo = \"broken.geo\"", clamps), dir);
  EXPECT_NE(broken.find("mesh.geo = \"broken.geo\""), std::string::npos) << broken;
  const std::string missing = deck_error(coupon_deck("static", "geo = \"missing.geo\"", clamps), dir);
  EXPECT_NE(missing.find("cannot open the geometry file"), std::string::npos) << missing;
  const std::string not_geo = deck_error(coupon_deck("static", "geo = \"panel.msh\"", clamps), dir);
  EXPECT_NE(not_geo.find("mesh.geo must be a gmsh geometry script (.geo)"), std::string::npos) << not_geo;
  const std::string both =
      deck_error(coupon_deck("static", "file = \"a.msh\"\ngeo = \"a.geo\"", clamps), dir);
  EXPECT_NE(both.find("not both"), std::string::npos) << both;
  const std::string counts = deck_error(coupon_deck("static", coupon_mesh_keys + "\nnx = 10", clamps), dir);
  EXPECT_NE(counts.find("mesh.nx shapes the structured rectangle, but mesh.geo gives the plate"),
            std::string::npos)
      << counts;
  const std::string growth = deck_error(
      coupon_deck("static", fmt::format("geo = \"{}\"\ngrowth = 1.5", coupon_geo.string()), clamps), dir);
  EXPECT_NE(growth.find("give it too"), std::string::npos) << growth;
}

TEST(GmshGeometry, AnImpactOnAWindowItMayLiftOffIsRefusedUntilTheTimeLoopSolvesTheContactSet) {
  const fs::path dir = scratch("impact");
  const std::string boundary = "clamps = \"11100\"\nwindow = \"unilateral\"";
  EXPECT_EQ(deck_error(coupon_deck("static", coupon_mesh_keys, boundary), dir), "(no error)");
  const std::string impact = deck_error(coupon_deck("impact", coupon_mesh_keys, boundary), dir);
  EXPECT_NE(impact.find("boundary.window = \"unilateral\""), std::string::npos) << impact;
  EXPECT_NE(impact.find("give \"ss-soft\""), std::string::npos) << impact;
  EXPECT_EQ(
      deck_error(coupon_deck("impact", coupon_mesh_keys, "clamps = \"11100\"\nwindow = \"ss-soft\""), dir),
      "(no error)");
}

TEST(GmshGeometry, TheExampleDeckMeshesTheGeometryBesideIt) {
  const Deck deck = load_deck(fs::path(PLYIMPACT_SOURCE_DIR) / "examples/static-astm-d7136-window.toml");
  ASSERT_TRUE(deck.file_mesh);
  EXPECT_EQ(deck.file_mesh->node_set("clamps").size(), 4U);
  EXPECT_NEAR(deck.file_mesh->bounds().x_max, a, 1e-12);
}

} // namespace
} // namespace plyimpact::gmsh_geometry_tests

namespace plyimpact::gmsh_geometry_tests {
namespace {

// gmsh runs in a child process (io/system/child_process.hpp; docs/robustness.md, "gmsh in a child process").

TEST(GmshIsolation, AGeometryThatEndsTheProcessIsRefusedNotObeyed) {
  // `Exit;` makes gmsh call exit(0): before, the program ended with status 0 and wrote nothing. The .geo
  // policy refuses the command before gmsh reads it (test_geo_script.cpp); trusted, gmsh runs it in its
  // child process, which ends alone.
  const fs::path dir = scratch("gmsh-exit");
  std::ofstream(dir / "exits.geo") << "Point(1) = {0, 0, 0};\nExit;\n";
  const test::TrustedGeoScripts trusted;
  try {
    (void)mesh_gmsh_geometry(dir / "exits.geo", GeometryMeshing{});
    ADD_FAILURE() << "expected MeshFileError";
  } catch (const MeshFileError& e) {
    const std::string what = e.what();
    // (exit code 0 from gmsh; under the leak sanitizer its check at exit may set another)
    EXPECT_NE(what.find("exits.geo: error: gmsh: it ended the process itself with exit code"),
              std::string::npos)
        << what;
  }
}

TEST(GmshIsolation, AFifoGivenAsTheMeshFileIsRefusedWithoutBlocking) {
  const fs::path dir = scratch("gmsh-fifo");
  const fs::path fifo = dir / "mesh.msh";
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  try {
    (void)read_gmsh_mesh(fifo);
    ADD_FAILURE() << "expected MeshFileError";
  } catch (const MeshFileError& e) {
    EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace plyimpact::gmsh_geometry_tests
