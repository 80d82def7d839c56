// Damage maps are drawn by gnuplot from generated scripts: the images exist, are not blank, and the
// SVG is an SVG document.
#include "plyimpact/fem/structured_mesh.hpp"
#include "plyimpact/io/results/damage_maps.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace plyimpact::damage_maps_tests {
namespace {

TEST(DamageMaps, OneMapPerCriterionAndLayerWithTheFailedPoints) {
  const Mesh mesh = structured_rectangle({0.127, 0.0762}, 15, 11);
  std::vector<DamageOnset> onsets(3);
  onsets[0].ply = 3, onsets[0].x = 0.06, onsets[0].y = 0.038, onsets[0].time = 12.69e-6;
  onsets[1].ply = 3, onsets[1].x = 0.066, onsets[1].y = 0.038, onsets[1].time = 12.96e-6;
  onsets[2].criterion = Criterion::choi_chang_delamination, onsets[2].interface = 2, onsets[2].x = 0.0635,
  onsets[2].y = 0.04, onsets[2].time = 13e-6;
  const auto dir = std::filesystem::temp_directory_path() / "plyimpact-maps";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const DamageMapFiles files = write_damage_maps(dir, mesh, onsets);
  ASSERT_TRUE(files.warning.empty()) << files.warning;
  EXPECT_EQ(files.scripts.size(), 2U);
  ASSERT_EQ(files.images.size(), 4U);
  const auto svg = dir / "damage_map_choi-chang-matrix_ply3.svg";
  std::ifstream in(svg);
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_NE(ss.str().find("<svg"), std::string::npos);
  EXPECT_NE(ss.str().find("</svg>"), std::string::npos);
  const auto png = dir / "damage_map_choi-chang-matrix_ply3.png";
  std::ifstream p(png, std::ios::binary);
  std::string head(8, '\0');
  p.read(head.data(), 8);
  EXPECT_EQ(head, std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_GT(std::filesystem::file_size(png), 5000U); // axes, grid, points and colour bar drawn
  const std::string script = damage_map_script(mesh, {onsets[0]}, "t", "a.svg", "a.png");
  EXPECT_NE(script.find("60.000000 38.000000 12.6900"), std::string::npos); // points in mm and µs
  EXPECT_EQ(script.find("$clamps"), std::string::npos) << "no rig, no outline";
}

TEST(DamageMaps, OnARigTheClampTipsAndTheWindowAreDrawnAndNamed) {
  // The onsets around the clamp tips are the point supports' singular stresses: the map circles the
  // tips, names them in its key, and dashes the window's edge (closed: its first corner again).
  const Mesh mesh = structured_rectangle({0.150, 0.100}, 6, 4);
  std::vector<DamageOnset> onsets(1);
  onsets[0].ply = 1, onsets[0].x = 0.025, onsets[0].y = 0.00625, onsets[0].time = 1e-4;
  RigOutline rig;
  rig.window = {{0.0125, 0.0125}, {0.1375, 0.0125}, {0.1375, 0.0875}, {0.0125, 0.0875}};
  rig.clamp_tips = {{0.025, 0.00625}, {0.125, 0.00625}, {0.125, 0.09375}, {0.025, 0.09375}};
  const std::string script = damage_map_script(mesh, onsets, "t", "a.svg", "a.png", rig);
  EXPECT_NE(script.find("$clamps << EOD\n25.000000 6.250000\n125.000000 6.250000\n"), std::string::npos);
  EXPECT_NE(script.find("$window << EOD\n12.500000 12.500000\n"), std::string::npos);
  EXPECT_NE(script.find("87.500000\n12.500000 12.500000\nEOD"), std::string::npos) << "closed";
  EXPECT_NE(script.find(clamp_tip_note), std::string::npos);
  const auto dir = std::filesystem::temp_directory_path() / "plyimpact-maps-rig";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const DamageMapFiles files = write_damage_maps(dir, mesh, onsets, rig);
  EXPECT_TRUE(files.warning.empty()) << files.warning; // gnuplot draws it
  EXPECT_EQ(files.images.size(), 2U);
}

} // namespace
} // namespace plyimpact::damage_maps_tests
