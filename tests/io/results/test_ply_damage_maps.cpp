// damage_elements.csv and the per-ply damage maps (io/results/ply_damage_maps): the file lists every element
// and ply of a 4 × 3 mesh with the damage it was given, at element centres and corners worked out by
// hand; the projected damage is the largest over the plies; each map fills one polygon per element with
// that element's value.
#include "plyimpact/io/results/plots.hpp"
#include "plyimpact/io/results/ply_damage_maps.hpp"
#include "support/decks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

namespace plyimpact::ply_damage_maps_tests {
namespace {

namespace fs = std::filesystem;

/// The 200 × 150 mm [0/90]s plate on a 4 × 3 mesh: 50 × 50 mm elements, numbered along x first.
DiscretePlate four_by_three(const Laminate& lam) {
  return DiscretePlate(lam, {0.2, 0.15}, {4, 3, MassMatrix::lumped, ElementFormulation::q9},
                       test::all_edges("ss"));
}

/// Element 3 (0-based 2) damaged in plies 2 and 4, element 6 (0-based 5) in ply 1.
std::vector<ElementPlyDamage> three_damaged() {
  return {{2, 3, {{0.1, 0.2, 0.7, 0.0}}}, {5, 0, {{0.9, 0.0, 0.0, 0.3}}}, {2, 1, {{0.0, 0.4, 0.0, 0.0}}}};
}

std::vector<DamageElementRow> written_and_read(const std::string& name) {
  const Laminate lam = test::laminate_of(test::t300_976(), "[0/90]s", 0.25e-3);
  const DiscretePlate model = four_by_three(lam);
  const fs::path dir = fs::temp_directory_path() / ("plyimpact-damage-maps-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / damage_elements_file)
      << damage_elements_csv(model, PlyDamageTable(model, three_damaged()));
  return read_damage_elements_csv(dir / damage_elements_file);
}

const DamageElementRow& row_of(const std::vector<DamageElementRow>& rows, int element, int ply) {
  const auto it = std::find_if(rows.begin(), rows.end(),
                               [&](const auto& r) { return r.element == element && r.ply == ply; });
  EXPECT_NE(it, rows.end()) << element << " " << ply;
  return *it;
}

TEST(PlyDamageMaps, DamageElementsCsvListsEveryElementAndPlyWithItsDamageCentreAndCorners) {
  const auto rows = written_and_read("csv");
  ASSERT_EQ(rows.size(), 48U); // 12 elements × 4 plies
  const DamageElementRow& e3p4 = row_of(rows, 3, 4);
  EXPECT_EQ(e3p4.damage.values,
            (std::array<double, 4>{0.1, 0.2, 0.7, 0.0})); // shortest text reads back exactly
  EXPECT_EQ(row_of(rows, 6, 1).damage.values, (std::array<double, 4>{0.9, 0.0, 0.0, 0.3}));
  EXPECT_EQ(row_of(rows, 3, 2).damage.values, (std::array<double, 4>{0.0, 0.4, 0.0, 0.0}));
  const auto zero = std::count_if(rows.begin(), rows.end(), [](const auto& r) { return r.largest() == 0.0; });
  EXPECT_EQ(zero, 45);
  // Element 3: third along x in the first row, 100–150 mm × 0–50 mm.
  EXPECT_NEAR(e3p4.centre.x(), 0.125, 1e-15);
  EXPECT_NEAR(e3p4.centre.y(), 0.025, 1e-15);
  const std::array<Eigen::Vector2d, 4> corners{{{0.10, 0.0}, {0.15, 0.0}, {0.15, 0.05}, {0.10, 0.05}}};
  for (std::size_t a = 0; a < 4; ++a)
    EXPECT_LT((e3p4.corners[a] - corners[a]).norm(), 1e-15) << a;
  EXPECT_EQ(row_of(rows, 7, 2).angle_deg, 90.0); // [0/90]s
  EXPECT_EQ(row_of(rows, 7, 4).angle_deg, 0.0);
}

TEST(PlyDamageMaps, ProjectedDamageIsTheLargestOverPliesAndModes) {
  const auto projected = projected_damage(written_and_read("projected"));
  ASSERT_EQ(projected.size(), 12U);
  for (const auto& [element, d] : projected)
    EXPECT_EQ(d, element == 3 ? 0.7 : element == 6 ? 0.9 : 0.0) << "element " << element;
}

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++n;
  return n;
}

TEST(PlyDamageMaps, OneMapPerPlyAndTheProjectedOneEachWithAPolygonPerElementFilledWithItsValue) {
  const auto rows = written_and_read("specs");
  const auto specs = ply_damage_map_plots(rows, MapMarks{Eigen::Vector2d(0.1, 0.075), {}});
  ASSERT_EQ(specs.size(), 5U);
  const std::array<const char*, 5> names{"damage_map_ply01", "damage_map_ply02", "damage_map_ply03",
                                         "damage_map_ply04", "damage_map_projected"};
  for (std::size_t i = 0; i < specs.size(); ++i) {
    EXPECT_EQ(specs[i].name, names[i]);
    EXPECT_EQ(occurrences(specs[i].extra, "set object "), 12U) << names[i];
    EXPECT_NE(specs[i].extra.find("set cbrange [0:1]"), std::string::npos) << names[i];
    ASSERT_EQ(specs[i].curves.size(), 3U) << names[i]; // element centres, the marker's disc, the marker
    EXPECT_EQ(specs[i].curves[2].title, "impact point");
    EXPECT_NE(specs[i].curves[2].data.find("100.000000,75.000000"), std::string::npos) << names[i]; // in mm
  }
  // Element 3's polygon (100–150 mm × 0–50 mm) in ply 4 is filled with 0.7, the largest of its variables.
  EXPECT_NE(
      specs[3].extra.find("polygon from 100.000000,0.000000 to 150.000000,0.000000 to 150.000000,50.000000 "
                          "to 100.000000,50.000000 to 100.000000,0.000000 fc palette cb 0.7 "),
      std::string::npos);
  EXPECT_EQ(occurrences(specs[3].extra, "cb 0 "), 11U);
  EXPECT_EQ(occurrences(specs[2].extra, "cb 0 "), 12U); // ply 3 has no damage
  EXPECT_NE(specs[2].title.find("max 0)"), std::string::npos) << specs[2].title;
  EXPECT_NE(specs[1].title.find("Ply 2 of 4 (90 deg)"), std::string::npos) << specs[1].title;
  EXPECT_NE(specs[1].extra.find("cb 0.4 "), std::string::npos);
  // Projected: 0.7 in element 3 (ply 4 over ply 2's 0.4), 0.9 in element 6, 0 in the other ten.
  EXPECT_EQ(occurrences(specs[4].extra, "cb 0.7 "), 1U);
  EXPECT_EQ(occurrences(specs[4].extra, "cb 0.9 "), 1U);
  EXPECT_EQ(occurrences(specs[4].extra, "cb 0 "), 10U);
  EXPECT_EQ(occurrences(specs[4].extra, "cb 0.4 "), 0U);
  // Without an impact point there is no marker.
  EXPECT_EQ(ply_damage_map_plots(rows, MapMarks{}).front().curves.size(), 1U);
  // On a rig: the window's edge, closed (5 corners), and the clamp tips named as what they are.
  RigOutline rig;
  rig.window = {{0.0125, 0.0125}, {0.1375, 0.0125}, {0.1375, 0.0875}, {0.0125, 0.0875}};
  rig.clamp_tips = {{0.025, 0.00625}, {0.125, 0.09375}};
  const auto on_rig = ply_damage_map_plots(rows, MapMarks{std::nullopt, rig});
  ASSERT_EQ(on_rig.front().curves.size(), 3U); // element centres, window, clamp tips
  EXPECT_EQ(on_rig.front().curves[1].title, "window edge");
  EXPECT_EQ(occurrences(on_rig.front().curves[1].data, "\n"), 6U); // header + 5 corners
  EXPECT_EQ(on_rig.front().curves[2].title, clamp_tip_note);
  EXPECT_NE(on_rig.front().curves[2].data.find("25.000000,6.250000\n125.000000,93.750000"),
            std::string::npos);
}

TEST(PlyDamageMaps, AMapOnARigIsDrawnByGnuplot) {
  // The window edge and the clamp tips carry their own line width: gnuplot refuses a style that names lw
  // twice ("duplicate or conflicting arguments in style specification"), and `plyimpact plot` of every
  // progressive run on a rig failed so until 2026-12-01.
  RigOutline rig;
  rig.window = {{0.0125, 0.0125}, {0.1375, 0.0125}, {0.1375, 0.0875}, {0.0125, 0.0875}};
  rig.clamp_tips = {{0.025, 0.00625}, {0.125, 0.09375}};
  std::vector<PlotSpec> maps = ply_damage_map_plots(written_and_read("rig"), MapMarks{std::nullopt, rig});
  maps.resize(1);
  const fs::path out = fs::temp_directory_path() / "plyimpact-damage-maps-rig-drawn";
  fs::remove_all(out);
  PlotFiles files;
  EXPECT_NO_THROW(files = draw_plots(maps, out));
  ASSERT_EQ(files.images.size(), 2U); // svg and png
  for (const fs::path& image : files.images)
    EXPECT_GT(fs::file_size(image), 1000U) << image;
}

TEST(PlyDamageMaps, AFolderWithoutDamageElementsHasNoMaps) {
  const fs::path dir = fs::temp_directory_path() / "plyimpact-damage-maps-none";
  fs::remove_all(dir);
  fs::create_directories(dir);
  EXPECT_TRUE(ply_damage_map_plots(dir).empty());
}

TEST(PlyDamageMaps, AValueThatIsNotANumberIsNamedWithItsLine) {
  const fs::path dir = fs::temp_directory_path() / "plyimpact-damage-maps-bad";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / damage_elements_file)
      << "element,ply,angle_deg,x_m,y_m,d_ft,d_fc,d_mt,d_mc,x1_m,y1_m,x2_m,y2_m,x3_m,y3_m,x4_m,y4_m\n"
      << "1,1,0,0.5,0.5,0,0,0,0,0,0,1,0,1,1,0,1\n"
      << "2,1,0,1.5,0.5,0,zero,0,0,1,0,2,0,2,1,1,1\n";
  try {
    (void)read_damage_elements_csv(dir / damage_elements_file);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("damage_elements.csv:3: d_fc is not a number"), std::string::npos)
        << e.what();
  }
}

} // namespace
} // namespace plyimpact::ply_damage_maps_tests
