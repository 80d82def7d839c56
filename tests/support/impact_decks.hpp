#pragma once
// Impact decks for tests that run the engine from TOML text: the shipped examples read as text with a
// key replaced, the thesis §3.6 plate and the rigid target written out in full, and the run of a deck.
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/deck/deck.hpp"
#include "test_paths.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace plyimpact::test {

/// The text of examples/<file>.
inline std::string example_text(const std::string& file) {
  std::ifstream in(std::string(PLYIMPACT_SOURCE_DIR) + "/examples/" + file);
  EXPECT_TRUE(in.good()) << file;
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The line `key = value` replaced (the first line that starts with "key = ").
inline std::string with_key(std::string text, const std::string& key, const std::string& value) {
  const std::size_t at = text.find("\n" + key + " = ");
  EXPECT_NE(at, std::string::npos) << key;
  if (at == std::string::npos) return text;
  const std::size_t end = text.find('\n', at + 1);
  return text.replace(at + 1, end - at - 1, key + " = " + value);
}

/// A deck of the T300/976 damage examples with every strength 1000 times the deck's (Xt, Xc, Yt, Yc,
/// S12, S23 as examples/damage-progressive.toml gives them): plies that never crack.
inline std::string unbreakable_t300_976(std::string text) {
  for (const auto& [key, value] : {std::pair{"Xt", "1.5e12"},
                                   {"Xc", "1.2e12"},
                                   {"Yt", "55.2e9"},
                                   {"Yc", "294.0e9"},
                                   {"S12", "101.1e9"},
                                   {"S23", "32.94e9"}})
    text = with_key(text, key, value);
  return text;
}

/// One run of the impact case of a deck text.
inline ImpactResult run_deck(const std::string& text, const std::string& name = "test.toml") {
  const Deck deck = parse_deck(text, name);
  return ImpactCase(impact_case_description(deck)).run();
}

/// Thesis §3.6 plate (Table 3.1) with a steel sphere (radius 12.7 mm); `impactor` holds its mass and
/// velocity keys, `extra` is appended (TOML keys override), `mesh` is "nx, ny", `edge` every edge's support.
inline std::string thesis_3_6_deck(const std::string& impactor, const std::string& extra = "",
                                   const std::string& mesh = "15, 11", const std::string& edge = "ss") {
  const auto comma = mesh.find(',');
  return R"(
[materials.m]
E1 = 129.0e9
E2 = 7.5e9
G12 = 3.5e9
nu12 = 0.33
rho = 1540.0
[laminate]
material = "m"
layup = "[45/90/-45/0]3s"
ply_thickness = 0.19375e-3
[plate]
a = 0.127
b = 0.0762
[mesh]
nx = )" + mesh.substr(0, comma) +
         "\nny = " + mesh.substr(comma + 1) + R"(
[boundary]
x0 = ")" +
         edge + R"("
xa = ")" +
         edge + R"("
y0 = ")" +
         edge + R"("
yb = ")" +
         edge + R"("
[impactor]
radius = 12.7e-3
E = 207e9
nu = 0.3
)" + impactor +
         "\n" + extra;
}

/// The §4.2 impactor (0.314 kg at 2.92 m/s, k = 0.6e9, elastic unloading) on a rigid target;
/// `time` is the body of the [time] table.
inline std::string rigid_target_deck(const std::string& time) {
  return R"(
[materials.m]
E1 = 129.0e9
E2 = 7.5e9
G12 = 3.5e9
nu12 = 0.33
rho = 1540.0
[laminate]
material = "m"
layup = "[0]"
ply_thickness = 1e-3
[plate]
a = 0.1
b = 0.1
rigid = true
[impactor]
mass = 0.314
radius = 12.7e-3
E = 207e9
velocity = 2.92
[contact]
k = 0.6e9
unloading = "elastic"
[time]
)" + time;
}

} // namespace plyimpact::test
