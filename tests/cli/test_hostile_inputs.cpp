// The hostile-input suite (docs/robustness.md, "Hostile inputs"): hundreds of faulty, absurd or malicious
// inputs — gmsh scripts and mesh files, rig presets struck anywhere, impactor noses, ply damage and
// delamination values, sweeps and command-line values — each run through the program as a user would run
// it, with a time limit. Whatever the input, the program must end with the exit code its documentation
// gives (0 done, 1 failed run, 2 bad input, 3 stopped at the step limit), say what it says for that
// input, and
//   - never crash, abort or take internal-error exit 4 (no 134, 139, 4),
//   - never hang (killed after the suite's limit: 137),
//   - never succeed silently: a run that exits 0 or 3 has written its summary.json,
//   - never run a shell command from a deck: no file "pwned" appears in the case's folder.
// Each case is its own test (HostileInputs/Case.Survives/<name>), so that ctest times and runs them in
// parallel, and the ASan/UBSan run checks every one under the sanitizers too.
#include "support/cli.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace plyimpact::test::hostile_inputs_tests {
namespace {

/// A file the case writes into its folder before the run: a name and its text; "{dir}" in the text
/// stands for the case's folder. A text of "<fifo>" makes a named pipe, "<dir>" a folder, "<link>TARGET" a
/// symbolic link to TARGET.
struct CaseFile {
  std::string name;
  std::string text;
};

struct HostileCase {
  HostileCase(std::string name_, std::string args_, std::vector<CaseFile> files_, int exit_,
              std::string says_, std::string env_ = {})
      : name(std::move(name_)), args(std::move(args_)), files(std::move(files_)), exit(exit_),
        says(std::move(says_)), env(std::move(env_)) {}
  std::string name;            ///< the test's name: letters, digits and '_'
  std::string args;            ///< after "plyimpact"; "{dir}" stands for the case's folder
  std::vector<CaseFile> files; ///< written into the folder first
  int exit = 0;                ///< the exit status the documentation gives for this input
  std::string says;            ///< a fragment its output (stdout and stderr) must hold
  std::string env;             ///< extra "NAME=value" words before the command
};

/// gtest prints a case by its name (not its bytes).
void PrintTo(const HostileCase& k, std::ostream* os) {
  *os << k.name;
}

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

// ---------------------------------------------------------------------------------------------------
// Decks the cases start from.

constexpr const char* t300_damage = R"(Xt = 1.5e9
Xc = 1.2e9
Yt = 55.2e6
Yc = 294.0e6
S12 = 101.1e6
S23 = 32.94e6
G_ft = 91.6e3
G_fc = 79.9e3
G_mt = 277.0
G_mc = 788.0
)";

/// The first microseconds of an impact: enough to build, factor and step, short enough for hundreds of
/// cases (the run ends in contact, with a warning and exit 0).
constexpr const char* first_steps = "[time]\ndt = 1e-6\nend = 4e-6\n";

/// The coupon on a rig preset, struck at (x, y) [m] (centre when NaN), plus `extra`.
std::string rig_deck(const std::string& rig, double x, double y, const std::string& extra = "") {
  std::string d = coupon_laminate() + "[rig]\n" + rig + "\n[impactor]\nmass = 5.5\nE = 210e9\nnu = 0.3\n";
  if (rig.find("circular") != std::string::npos)
    d += "radius = 0.008\nenergy = 1.0\n"; // the ASTM rig gives both
  if (!std::isnan(x)) d += fmt::format("x = {:.17g}\ny = {:.17g}\n", x, y);
  return d + extra + (extra.find("[time]") == std::string::npos ? first_steps : "");
}

/// The coupon meshed from a gmsh file: `mesh_keys` in [mesh] (e.g. geo = "plate.geo"), its edges clamped.
std::string mesh_deck(const std::string& mesh_keys, const std::string& impactor_extra = "",
                      const std::string& extra = "") {
  return coupon_laminate() + "[mesh]\n" + mesh_keys + "\n[boundary]\nedges = \"clamped\"\n" +
         "[impactor]\nmass = 2.0\nradius = 0.008\nE = 210e9\nnu = 0.3\nenergy = 1.0\n" + impactor_extra +
         first_steps + extra;
}

/// small_deck's 6 x 4 Annex 2 plate struck by the tests' steel ball for a few steps, plus `extra`.
std::string plate_deck(const std::string& extra = "", const std::string& impactor_extra = "") {
  return small_deck("impact", steel_ball_impactor("dt = 1e-6\nend = 5e-6\n") + impactor_extra + extra);
}

/// `deck` with the line starting with `key =` in section `[section]` replaced by `key = value` (added
/// at the section's start when absent).
std::string set_key(std::string deck, const std::string& section, const std::string& key,
                    const std::string& value) {
  const std::string header = "[" + section + "]\n";
  const std::size_t start = deck.find(header);
  if (start == std::string::npos) return deck + header + key + " = " + value + "\n";
  const std::size_t body = start + header.size();
  std::size_t end = deck.find("\n[", body);
  if (end == std::string::npos) end = deck.size();
  const std::size_t line = deck.find("\n" + key + " =", body - 1);
  if (line != std::string::npos && line < end) {
    const std::size_t eol = deck.find('\n', line + 1);
    deck.replace(line + 1, eol - line - 1, key + " = " + value);
  } else {
    deck.insert(body, key + " = " + value + "\n");
  }
  return deck;
}

/// A rectangle 0.1 x 0.08 m for gmsh's built-in kernel, physical groups "edges" and "plate"; `before`
/// and `after` are lines around it.
std::string rectangle_geo(const std::string& before = "", const std::string& after = "", double lc = 0.01) {
  return before +
         fmt::format(R"(lc = {};
Point(1) = {{0, 0, 0, lc}}; Point(2) = {{0.1, 0, 0, lc}}; Point(3) = {{0.1, 0.08, 0, lc}}; Point(4) = {{0, 0.08, 0, lc}};
Line(1) = {{1, 2}}; Line(2) = {{2, 3}}; Line(3) = {{3, 4}}; Line(4) = {{4, 1}};
Curve Loop(1) = {{1, 2, 3, 4}};
Plane Surface(1) = {{1}};
Physical Curve("edges") = {{1, 2, 3, 4}};
Physical Surface("plate") = {{1}};
)",
                     lc) +
         after;
}

/// A 2-node... a gmsh 2.2 ASCII mesh of the rectangle a x b as nx x ny QUAD9 elements, edges in the
/// physical curve "edges", the surface in "plate". `node` may change a node's coordinates line.
std::string rectangle_msh(double a, double b, int nx, int ny,
                          const std::function<std::string(int, double, double)>& node = {}) {
  const int cols = 2 * nx + 1, rows = 2 * ny + 1;
  const auto id = [&](int i, int j) { return 1 + i + j * cols; };
  std::string s = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n1 1 \"edges\"\n2 2 \"plate\"\n"
                  "$EndPhysicalNames\n$Nodes\n" +
                  std::to_string(cols * rows) + "\n";
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) {
      const double x = a * i / (cols - 1), y = b * j / (rows - 1);
      s += node ? node(id(i, j), x, y) : fmt::format("{} {:.17g} {:.17g} 0\n", id(i, j), x, y);
    }
  s += "$EndNodes\n$Elements\n";
  std::vector<std::string> lines;
  const auto line3 = [&](int entity, int i0, int j0, int i1, int j1) { // end, end, middle
    lines.push_back(
        fmt::format("8 2 1 {} {} {} {}", entity, id(i0, j0), id(i1, j1), id((i0 + i1) / 2, (j0 + j1) / 2)));
  };
  for (int e = 0; e < nx; ++e) {
    line3(1, 2 * e, 0, 2 * e + 2, 0);
    line3(3, 2 * e + 2, rows - 1, 2 * e, rows - 1);
  }
  for (int e = 0; e < ny; ++e) {
    line3(2, cols - 1, 2 * e, cols - 1, 2 * e + 2);
    line3(4, 0, 2 * e + 2, 0, 2 * e);
  }
  for (int ey = 0; ey < ny; ++ey)
    for (int ex = 0; ex < nx; ++ex) {
      const int i = 2 * ex, j = 2 * ey;
      lines.push_back(fmt::format("10 2 2 1 {} {} {} {} {} {} {} {} {}", id(i, j), id(i + 2, j),
                                  id(i + 2, j + 2), id(i, j + 2), id(i + 1, j), id(i + 2, j + 1),
                                  id(i + 1, j + 2), id(i, j + 1), id(i + 1, j + 1)));
    }
  s += std::to_string(lines.size()) + "\n";
  for (std::size_t k = 0; k < lines.size(); ++k)
    s += std::to_string(k + 1) + " " + lines[k] + "\n";
  return s + "$EndElements\n";
}

/// The 150 x 100 mm coupon as 6 x 4 elements.
std::string coupon_msh(const std::function<std::string(int, double, double)>& node = {}) {
  return rectangle_msh(0.15, 0.1, 6, 4, node);
}

/// `value` as part of a test's name: every character but letters and digits made '_'.
std::string name_part(std::string value) {
  for (char& ch : value)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return value;
}

std::string impact(const std::string& options = "") {
  return "impact deck.toml -o out" + options;
}

/// The gmsh time limit a case runs under (PLYIMPACT_GMSH_TIME_LIMIT_S): 10 s where the script would never
/// finish (the case expects "time limit"), so that the case ends soon; 60 s for the others, whose script
/// finishes in about a second, so that a slow moment of a loaded machine is not read as a script that would
/// not finish (sandbox_save, whose Save meshes the plate, took 11 s under the sanitizers and ctest -j2 once
/// and failed the CI of stop 90 on the 10 s limit).
std::string gmsh_time_limit(const std::string& says) {
  return says.find("time limit") != std::string::npos ? "PLYIMPACT_GMSH_TIME_LIMIT_S=10"
                                                      : "PLYIMPACT_GMSH_TIME_LIMIT_S=60";
}

// ---------------------------------------------------------------------------------------------------
// The cases, by the input they attack.

/// gmsh scripts: commands with side effects, crashes, endless work, broken geometry.
std::vector<HostileCase> geo_cases() {
  const std::string deck = mesh_deck("geo = \"plate.geo\"\nsize_at_impact = 0.01\nmax_size = 0.02");
  const std::string own_sizes = mesh_deck("geo = \"plate.geo\"");
  const auto script = [&](const std::string& name, const std::string& geo, int exit, const std::string& says,
                          const std::string& with = "") {
    return HostileCase{
        name, impact(), {{"deck.toml", with.empty() ? deck : with}, {"plate.geo", geo}}, exit, says};
  };
  const std::string refused = "plyimpact does not let a geometry script run programs";
  std::vector<HostileCase> c = {
      script("geo_control", rectangle_geo(), 0, "mesh:"),
      script("geo_control_own_sizes", rectangle_geo(), 0, "mesh:", own_sizes),
      script("geo_system", rectangle_geo("System \"touch {dir}/pwned\";\n"), 2,
             "System runs a shell command"),
      script("geo_system_after", rectangle_geo("", "System \"touch {dir}/pwned\";\n"), 2, refused),
      script("geo_systemcall", rectangle_geo("SystemCall \"touch {dir}/pwned\";\n"), 2, refused),
      script("geo_nonblocking", rectangle_geo("NonBlockingSystemCall \"touch {dir}/pwned\";\n"), 2, refused),
      script("geo_onelab_run", rectangle_geo("OnelabRun(\"x\", \"touch {dir}/pwned\");\n"), 2, refused),
      script("geo_create_dir", rectangle_geo("CreateDir \"{dir}/pwned\";\n"), 2, refused),
      script("geo_delete_file", rectangle_geo("DeleteFile \"{dir}/deck.toml\";\n"), 2, refused),
      script("geo_rename_file", rectangle_geo("RenameFile \"{dir}/deck.toml\", \"{dir}/pwned\";\n"), 2,
             refused),
      script("geo_save", rectangle_geo("", "Save \"{dir}/pwned\";\n"), 2, refused),
      script("geo_print", rectangle_geo("", "Print \"{dir}/pwned.png\";\n"), 2, refused),
      script("geo_printf_to_file", rectangle_geo("Printf(\"x\") > \"{dir}/pwned\";\n"), 2, refused),
      script("geo_printf_append", rectangle_geo("Printf(\"x\") >> \"{dir}/pwned\";\n"), 2, refused),
      script("geo_exit", rectangle_geo("Exit;\n"), 2, "Exit"),
      script("geo_exit_after", rectangle_geo("", "Exit;\n"), 2, "Exit"),
      script("geo_include_absolute", rectangle_geo("Include \"/etc/hostname\";\n"), 2, "Include"),
      script("geo_include_parent", rectangle_geo("Include \"../outside.geo\";\n"), 2, "Include"),
      script("geo_include_computed", rectangle_geo("Include StrCat(\"/etc/\", \"hostname\");\n"), 2,
             "Include"),
      script("geo_merge_absolute", rectangle_geo("", "Merge \"/etc/hostname\";\n"), 2, "Merge"),
      script("geo_system_in_macro",
             rectangle_geo("Macro M\nSystem \"touch {dir}/pwned\";\nReturn\n", "Call M;\n"), 2, refused),
      script("geo_system_in_loop", rectangle_geo("For i In {1:2}\nSystem \"touch {dir}/pwned\";\nEndFor\n"),
             2, refused),
      script("geo_system_uppercase", rectangle_geo("SYSTEM \"touch {dir}/pwned\";\n"), 2, "gmsh"),
      script("geo_system_in_comment", rectangle_geo("// System \"touch {dir}/pwned\";\n/* Exit; */\n"), 0,
             "mesh:"),
      script("geo_system_in_string", rectangle_geo("Printf(\"System Exit Include\");\n"), 0, "mesh:"),
      script("geo_printf_to_terminal", rectangle_geo("Printf(\"lc = %g\", 0.01);\n"), 0, "mesh:"),
      script("geo_quad_algorithm_8",
             rectangle_geo("Mesh.Algorithm = 8;\nMesh.RecombineAll = 1;\nMesh.RecombinationAlgorithm = 3;\n"),
             2, "Mesh.Algorithm"),
      script("geo_occ_disk_algorithm_8",
             "SetFactory(\"OpenCASCADE\");\nDisk(1) = {0.05, 0.05, 0, 0.04};\nMesh.Algorithm = 8;\n"
             "Recombine Surface{1};\nPhysical Curve(\"edges\") = {1};\nPhysical Surface(\"plate\") = {1};\n",
             2, "Mesh.Algorithm"),
      script("geo_negative_length", rectangle_geo("", "", -0.01), 2, "gmsh", own_sizes),
      script("geo_tiny_length", rectangle_geo("", "", 1e-7), 2, "the time limit", own_sizes),
      script("geo_tiny_size_field", rectangle_geo(), 2, "mesh.size_at_impact = 1e-06 m is below",
             mesh_deck("geo = \"plate.geo\"\nsize_at_impact = 1e-6")),
      script("geo_endless_loop", rectangle_geo("For i In {1:1e12}\nEndFor\n"), 2, "time limit"),
      script("geo_syntax_error", "Point(1) = {0, 0\n", 2, "gmsh"),
      script("geo_empty", "", 2, "could not read or mesh it"),
      script("geo_binary",
             std::string("\x7f"
                         "ELF\x02\x01\x01\0\0\0garbage\xff\xfe",
                         20),
             2, "gmsh"),
      script("geo_lines_only",
             "Point(1) = {0, 0, 0, 0.01}; Point(2) = {0.1, 0, 0, 0.01};\nLine(1) = {1, 2};\n"
             "Physical Curve(\"edges\") = {1};\n",
             2, "no surface elements"),
      script("geo_no_groups",
             replace_all(replace_all(rectangle_geo(), "Physical Curve(\"edges\") = {1, 2, 3, 4};", ""),
                         "Physical Surface(\"plate\") = {1};", ""),
             2, "no physical groups"),
      script(
          "geo_tilted_plane",
          replace_all(rectangle_geo(), "Point(3) = {0.1, 0.08, 0, lc}", "Point(3) = {0.1, 0.08, 0.01, lc}"),
          2, "z = 0"),
      script("geo_volume",
             "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 0.1, 0.08, 0.004};\n"
             "Physical Surface(\"edges\") = {1};\nPhysical Volume(\"plate\") = {1};\n",
             2, "9-node quadrilaterals"),
      script("geo_reversed", rectangle_geo("", "Reverse Surface{1};\n"), 2, "inverted"),
      script("geo_huge_plate", replace_all(rectangle_geo("", "", 1e8), "0.1, ", "1e9, "), 2, "crashed",
             own_sizes),
      script("geo_unknown_group", rectangle_geo(), 2, "edges",
             replace_all(deck, "edges = \"clamped\"", "rim = \"clamped\"")),
      script("geo_impact_off_plate", rectangle_geo(), 2, "lies outside the mesh",
             mesh_deck("geo = \"plate.geo\"\nsize_at_impact = 0.01", "x = 0.5\ny = 0.04\n")),
      script("geo_long_line", rectangle_geo("// " + std::string(1 << 20, 'x') + "\n"), 0, "mesh:"),
      script("geo_many_points",
             rectangle_geo("For i In {1:20000}\nPoint(100 + i) = {0.05, 0.04, 0, 0.01};\nEndFor\n"), 0,
             "mesh:"),
      script("geo_unicode", rectangle_geo("// plaque trouée, épaisseur 4 mm — ±45°\n"), 0, "mesh:"),
  };
  // Include and Merge inside the script's folder are allowed; out of it, or through itself, refused.
  c.push_back({"geo_include_sibling",
               impact(),
               {{"deck.toml", deck}, {"plate.geo", "Include \"rect.geo\";\n"}, {"rect.geo", rectangle_geo()}},
               0,
               "mesh:"});
  c.push_back({"geo_include_itself",
               impact(),
               {{"deck.toml", deck}, {"plate.geo", "Include \"plate.geo\";\n"}},
               2,
               "Include"});
  c.push_back({"geo_include_sibling_with_system",
               impact(),
               {{"deck.toml", deck},
                {"plate.geo", "Include \"rect.geo\";\n"},
                {"rect.geo", rectangle_geo("System \"touch {dir}/pwned\";\n")}},
               2,
               refused});
  c.push_back({"geo_missing", impact(), {{"deck.toml", deck}}, 2, "cannot open the geometry file"});
  c.push_back({"geo_is_a_folder",
               impact(),
               {{"deck.toml", deck}, {"plate.geo", "<dir>"}},
               2,
               "cannot open the geometry file"});
  c.push_back({"geo_is_a_fifo",
               impact(),
               {{"deck.toml", deck}, {"plate.geo", "<fifo>"}},
               2,
               "cannot open the geometry file"});
  c.push_back(
      {"geo_hole_impact_in_hole",
       impact(),
       {{"deck.toml", mesh_deck("geo = \"plate.geo\"\nsize_at_impact = 0.003", "x = 0.125\ny = 0.075\n")},
        {"plate.geo", read_text(fs::path(PLYIMPACT_SOURCE_DIR) / "examples/meshes/plate-with-hole.geo")}},
       2,
       "lies outside the mesh"});
  // The panel with a hole struck at a seeded sample of points: on the panel it runs, in the hole it is
  // refused (points within 1 mm of an edge are left out: the curved edge is meshed by quadratic elements).
  const std::string hole_geo =
      read_text(fs::path(PLYIMPACT_SOURCE_DIR) / "examples/meshes/plate-with-hole.geo");
  std::mt19937_64 random(53);
  const auto u = [&] { return static_cast<double>(random() >> 11) * 0x1.0p-53; };
  for (int i = 0; i < 10;) {
    const double x = 0.005 + 0.24 * u(), y = 0.005 + 0.14 * u();
    const double r = std::hypot(x - 0.125, y - 0.075);
    if (std::abs(r - 0.015) < 1e-3) continue;
    const bool in_hole = r < 0.015;
    c.push_back({fmt::format("geo_hole_random_{}", i++),
                 impact(),
                 {{"deck.toml", mesh_deck("geo = \"plate.geo\"\nsize_at_impact = 0.004\nmax_size = 0.02",
                                          fmt::format("x = {:.17g}\ny = {:.17g}\n", x, y))},
                  {"plate.geo", hole_geo}},
                 in_hole ? 2 : 0,
                 in_hole ? "lies outside the mesh" : "mesh:"});
  }
  // and inside the hole, always refused
  for (int i = 0; i < 3; ++i) {
    const double r = 0.013 * std::sqrt(u()), t = 2.0 * M_PI * u();
    c.push_back({fmt::format("geo_hole_random_in_hole_{}", i),
                 impact(),
                 {{"deck.toml", mesh_deck("geo = \"plate.geo\"\nsize_at_impact = 0.004\nmax_size = 0.02",
                                          fmt::format("x = {:.17g}\ny = {:.17g}\n", 0.125 + r * std::cos(t),
                                                      0.075 + r * std::sin(t)))},
                  {"plate.geo", hole_geo}},
                 2,
                 "lies outside the mesh"});
  }
  for (auto& k : c)
    k.env = gmsh_time_limit(k.says);
  return c;
}

/// A script that tries to reach outside drawing a geometry (issue 77): its text before and after the
/// rectangle, the files beside it, what the check says of it, and what the sandbox alone makes of it.
struct Attack {
  std::string name;
  std::string before;
  std::string after;
  std::vector<CaseFile> files; ///< beside plate.geo (included scripts, links, FIFOs)
  std::string check_says;      ///< the check's message (the lexer on)
  int sandbox_exit = 2;        ///< the exit with the check off (PLYIMPACT_TEST_ONLY_SKIP_GEO_CHECK=1)
  std::string sandbox_says;    ///< and what the run says then
};

/// What the run says when the kernel stopped a program (SIGSYS) and when gmsh ended itself.
constexpr const char* sandbox_stopped = "the sandbox stopped it";
constexpr const char* ended_itself = "ended the process itself";

/// At least thirty ways to run a command, end gmsh, write or read a file: quoting and escaping tricks,
/// macros, conditions, loops, includes, computed names, options. Each runs twice: with the check (its
/// message), and with the check switched off, where the sandbox alone must stop it — no file made, no
/// command run.
std::vector<Attack> attacks() {
  const std::string touch = "touch {dir}/pwned";
  const std::string long_string = std::string(1023, 'x');
  std::vector<Attack> a = {
      {"system", "System \"" + touch + "\";\n", "", {}, "System runs a shell command", 2, sandbox_stopped},
      {"system_single_quotes", "System '" + touch + "';\n", "", {}, "System runs", 2, sandbox_stopped},
      {"systemcall_single_quotes",
       "SystemCall '" + touch + "';\n",
       "",
       {},
       "SystemCall runs",
       2,
       sandbox_stopped},
      {"nonblocking_single_quotes",
       "NonBlockingSystemCall '" + touch + "';\n",
       "",
       {},
       "NonBlockingSystemCall runs",
       2,
       sandbox_stopped},
      {"system_quote_in_single_quotes",
       "s = '\"'; System \"" + touch + "\"; t = '\"';\n",
       "",
       {},
       "System runs",
       2,
       sandbox_stopped},
      {"system_backslash_before_quote",
       "s = \"a\\\"; System \"" + touch + "\"; t = \"b\";\n",
       "",
       {},
       "System runs",
       2,
       sandbox_stopped},
      {"system_strcat",
       "System StrCat(\"tou\", \"ch {dir}/pwned\");\n",
       "",
       {},
       "System runs",
       2,
       sandbox_stopped},
      {"system_sprintf",
       "System Sprintf(\"touch %s\", \"{dir}/pwned\");\n",
       "",
       {},
       "System runs",
       2,
       "gmsh could not read or mesh it"},
      {"system_in_macro",
       "Macro M\nSystem '" + touch + "';\nReturn\n",
       "Call M;\n",
       {},
       "System runs",
       2,
       sandbox_stopped},
      {"system_in_function_called_by_string",
       "Function F\nSystem \"" + touch + "\";\nReturn\n",
       "Call 'F';\n",
       {},
       "System runs",
       2,
       sandbox_stopped},
      {"system_in_if",
       "If (1)\nSystem \"" + touch + "\";\nEndIf\n",
       "",
       {},
       "System runs",
       2,
       sandbox_stopped},
      {"system_in_else",
       "If (0)\nx = 1;\nElse\nSystem \"" + touch + "\";\nEndIf\n",
       "",
       {},
       "System runs",
       2,
       sandbox_stopped},
      {"system_in_loop",
       "For i In {1:2}\nSystem '" + touch + "';\nEndFor\n",
       "",
       {},
       "System runs",
       2,
       sandbox_stopped},
      {"system_after_long_string",
       "s = \"" + long_string + ";System \"" + touch + "\";//\";\n",
       "",
       {},
       "gmsh reads at most 1023",
       2,
       "gmsh could not read or mesh it"},
      {"system_after_nul",
       std::string("s = \"a") + '\0' + "\"; System \"" + touch + "\"; t = \"\";\n",
       "",
       {},
       "NUL byte",
       2,
       "gmsh could not read or mesh it"},
      {"system_glued_to_number", "x = 1;\n2e0System \"" + touch + "\";\n", "", {}, "System runs", 2, "gmsh"},
      {"system_in_comment_trick",
       "/* \" */ System \"" + touch + "\"; /* \" */\n",
       "",
       {},
       "System runs",
       2,
       sandbox_stopped},
      {"system_in_included_script",
       "Include \"inc.geo\";\n",
       "",
       {{"inc.geo", "System \"" + touch + "\";\n"}},
       "whose line 1 holds System",
       2,
       sandbox_stopped},
      {"system_in_nested_include",
       "Include 'a.geo';\n",
       "",
       {{"a.geo", "Include \"b.geo\";\n"}, {"b.geo", "x = 1;\nSystemCall \"" + touch + "\";\n"}},
       "whose line 1 holds Include",
       2,
       sandbox_stopped},
      {"onelab_run",
       "OnelabRun(\"x\", \"" + touch + "\");\n",
       "",
       {},
       "OnelabRun runs a program",
       2,
       "Couldn't create socket"},
      {"onelab_run_single_quotes",
       "OnelabRun('" + touch + "');\n",
       "",
       {},
       "OnelabRun runs",
       2,
       "Couldn't create socket"},
      {"solver_executable",
       "Solver.Executable0 = \"/bin/sh\";\nOnelabRun(\"x\");\n",
       "",
       {},
       "Executable0 sets an option",
       2,
       "Couldn't create socket"},
      {"exit", "Exit;\n", "", {}, "Exit ends gmsh", 2, ended_itself},
      {"exit_with_code", "Exit 3;\n", "", {}, "Exit ends gmsh", 2, "gmsh could not read or mesh it"},
      {"exit_in_if", "If (1)\nExit;\nEndIf\n", "", {}, "Exit ends gmsh", 2, ended_itself},
      {"exit_in_included_script",
       "Include \"inc.geo\";\n",
       "",
       {{"inc.geo", "Exit;\n"}},
       "whose line 1 holds Exit",
       2,
       ended_itself},
      {"save", "", "Save \"{dir}/pwned.msh\";\n", {}, "Save writes a file", 2, "Unable to open file"},
      {"save_single_quotes_in_macro",
       "Macro W\nSave '{dir}/pwned.msh';\nReturn\n",
       "Call W;\n",
       {},
       "Save writes",
       2,
       "Unable to open file"},
      {"print",
       "",
       "Print \"{dir}/pwned.svg\";\n",
       {},
       "Print writes a file",
       2,
       "gmsh could not read or mesh it"},
      {"printf_to_file_single_quotes",
       "Printf('x') > '{dir}/pwned';\n",
       "",
       {},
       "Printf writes",
       2,
       "Unable to open file"},
      {"printf_append",
       "Printf(\"x\") >> \"{dir}/pwned\";\n",
       "",
       {},
       "Printf writes",
       2,
       "Unable to open file"},
      {"printf_to_computed_file",
       "Printf(\"x\") > Sprintf(\"%s/pwned\", \"{dir}\");\n",
       "",
       {},
       "Printf writes",
       2,
       "gmsh could not read or mesh it"},
      {"create_dir", "CreateDir '{dir}/pwned';\n", "", {}, "CreateDir creates a folder", 0, "mesh:"},
      {"options_file",
       "General.OptionsFileName = \"{dir}/pwned\";\nGeneral.SaveOptions = 1;\n",
       "",
       {},
       "OptionsFileName sets an option",
       0,
       "mesh:"},
      {"include_passwd_single_quotes",
       "Include '/etc/passwd';\n",
       "",
       {},
       "outside the script's folder",
       2,
       "gmsh"},
      {"include_link_out_of_folder",
       "Include \"link.geo\";\n",
       "",
       {{"link.geo", "<link>/etc/passwd"}},
       "outside the script's folder",
       2,
       "gmsh"},
      {"include_fifo",
       "Include \"pipe.geo\";\n",
       "",
       {{"pipe.geo", "<fifo>"}},
       "not a regular file",
       2,
       "the time limit"},
      {"merge_hostname_single_quotes",
       "",
       "Merge '/etc/hostname';\n",
       {},
       "outside the script's folder",
       2,
       "Unable to open file '/etc/hostname'"},
      {"shape_from_file",
       "SetFactory(\"OpenCASCADE\");\nv() = ShapeFromFile(\"/etc/passwd\");\n",
       "",
       {},
       "ShapeFromFile reads",
       2,
       "gmsh"},
      {"list_from_file",
       "x() = ListFromFile(\"/etc/passwd\");\n",
       "",
       {},
       "ListFromFile reads",
       2,
       "Could not open file '/etc/passwd'"},
  };
  return a;
}

/// Each attack with the check on (its message, exit 2) and with the check off (the sandbox alone).
std::vector<HostileCase> sandbox_cases() {
  const std::string deck = mesh_deck("geo = \"plate.geo\"\nsize_at_impact = 0.01\nmax_size = 0.02");
  std::vector<HostileCase> c;
  for (const Attack& k : attacks()) {
    std::vector<CaseFile> files = {{"deck.toml", deck}, {"plate.geo", rectangle_geo(k.before, k.after)}};
    files.insert(files.end(), k.files.begin(), k.files.end());
    c.push_back({"check_" + k.name, impact(), files, 2, k.check_says, gmsh_time_limit(k.check_says)});
    c.push_back({"sandbox_" + k.name, impact(), files, k.sandbox_exit, k.sandbox_says,
                 gmsh_time_limit(k.sandbox_says) + " PLYIMPACT_TEST_ONLY_SKIP_GEO_CHECK=1"});
  }
  return c;
}

/// gmsh mesh files: broken, absurd, not meshes at all.
std::vector<HostileCase> msh_cases() {
  const std::string deck = mesh_deck("file = \"plate.msh\"");
  const auto mesh = [&](const std::string& name, const std::string& msh, int exit, const std::string& says,
                        const std::string& with = "") {
    return HostileCase{
        name, impact(), {{"deck.toml", with.empty() ? deck : with}, {"plate.msh", msh}}, exit, says};
  };
  const auto node_at = [](int which, const std::string& coords) {
    return [=](int id, double x, double y) {
      return id == which ? fmt::format("{} {}\n", id, coords)
                         : fmt::format("{} {:.17g} {:.17g} 0\n", id, x, y);
    };
  };
  // node 1 is a corner (on the boundary), node 20 the centre of the first row's second element
  const std::string ok = coupon_msh();
  std::vector<HostileCase> c = {
      mesh("msh_control", ok, 0, "mesh:"),
      mesh("msh_nan_boundary_node", coupon_msh(node_at(1, "nan 0 0")), 2, "node 1"),
      mesh("msh_nan_interior_node", coupon_msh(node_at(20, "0.03 nan 0")), 2, "node 20"),
      mesh("msh_inf_node", coupon_msh(node_at(20, "inf 0.01 0")), 2, "node 20"),
      mesh("msh_node_off_plane", coupon_msh(node_at(20, "0.0375 0.0125 0.001")), 2, "z = 0"),
      mesh("msh_empty", "", 2, "not a gmsh mesh file"),
      mesh("msh_header_only", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n", 2, "plate.msh"),
      mesh("msh_truncated_nodes", ok.substr(0, ok.find("$EndNodes") / 2), 2, "plate.msh"),
      mesh("msh_truncated_elements", ok.substr(0, ok.size() - 200), 2, "plate.msh"),
      mesh("msh_missing_node", replace_all(ok, "\n20 ", "\n9999 "), 2, "plate.msh"),
      mesh("msh_duplicate_node", replace_all(ok, "\n21 ", "\n20 "), 2, "plate.msh"),
      mesh("msh_garbage_numbers", replace_all(ok, "\n20 ", "\n20 abc "), 2, "plate.msh"),
      mesh("msh_version_1", replace_all(ok, "2.2 0 8", "1.0 0 8"), 2, "plate.msh"),
      mesh("msh_version_99", replace_all(ok, "2.2 0 8", "99 0 8"), 2, "plate.msh"),
      mesh("msh_binary_flag", replace_all(ok, "2.2 0 8", "2.2 1 8"), 2, "plate.msh"),
      mesh("msh_no_elements", ok.substr(0, ok.find("$Elements")) + "$Elements\n0\n$EndElements\n", 2,
           "no surface elements"),
      mesh("msh_no_groups",
           replace_all(
               replace_all(ok, "$PhysicalNames\n2\n1 1 \"edges\"\n2 2 \"plate\"\n$EndPhysicalNames\n", ""),
               " 2 2 1 ", " 2 0 1 "),
           2, "physical group"),
      mesh("msh_quad4", replace_all(ok, "10 2 2 1", "3 2 2 1"), 2, "plate.msh"),
      mesh("msh_inverted",
           rectangle_msh(0.15, 0.1, 6, 4,
                         [](int id, double x, double y) {
                           return fmt::format("{} {:.17g} {:.17g} 0\n", id, x,
                                              -y); // mirrored: every element clockwise
                         }),
           2, "inverted"),
      mesh("msh_degenerate", coupon_msh(node_at(15, "0 0 0")), 2, "degenerate"),
      mesh("msh_huge_plate", rectangle_msh(1.5e9, 1e9, 6, 4), 0, "implausible"),
      mesh("msh_tiny_plate", rectangle_msh(1.5e-6, 1e-6, 6, 4), 0, "implausible"),
      mesh("msh_script_disguised", "$MeshFormat\nSystem \"touch {dir}/pwned\";\n", 2, "plate.msh"),
      mesh("msh_not_a_mesh", "Point(1) = {0, 0, 0};\nSystem \"touch {dir}/pwned\";\n", 2,
           "not a gmsh mesh file"),
      mesh("msh_impact_off_mesh", ok, 2, "lies outside the mesh",
           mesh_deck("file = \"plate.msh\"", "x = 0.3\ny = 0.05\n")),
      mesh("msh_unknown_group", ok, 2, "edges",
           replace_all(deck, "edges = \"clamped\"", "rim = \"clamped\"")),
  };
  c.push_back({"msh_missing", impact(), {{"deck.toml", deck}}, 2, "plate.msh"});
  c.push_back(
      {"msh_is_a_folder", impact(), {{"deck.toml", deck}, {"plate.msh", "<dir>"}}, 2, "not a regular file"});
  c.push_back(
      {"msh_is_a_fifo", impact(), {{"deck.toml", deck}, {"plate.msh", "<fifo>"}}, 2, "not a regular file"});
  c.push_back({"msh_geo_given_as_file",
               impact(),
               {{"deck.toml", mesh_deck("file = \"plate.geo\"")},
                {"plate.geo", rectangle_geo("System \"touch {dir}/pwned\";\n")}},
               2,
               "mesh.file"});
  // A mesh far larger than the memory the run may use is refused before its matrices are assembled,
  // with advice that fits a mesh file (not [mesh] nx, ny).
  c.push_back({"msh_larger_than_memory",
               impact(),
               {{"deck.toml", deck}, {"plate.msh", rectangle_msh(0.15, 0.1, 60, 40)}},
               1,
               "coarser mesh in the file",
               "PLYIMPACT_MEMORY_LIMIT_BYTES=3e7"});
  for (auto& k : c)
    k.env += " " + gmsh_time_limit(k.says);
  return c;
}

/// The rig presets struck anywhere on the plate (a seeded sample), off it, and with absurd sizes.
std::vector<HostileCase> rig_cases() {
  std::vector<HostileCase> c;
  const auto rig = [&](const std::string& name, const std::string& deck, int exit, const std::string& says) {
    c.push_back({name, impact(), {{"deck.toml", deck}}, exit, says});
  };
  const std::string astm = "preset = \"astm-d7136\"";
  const std::string disk = "preset = \"circular\"\ndiameter = 0.0762";
  // Random points inside the ASTM window (12.5 … 137.5 mm by 12.5 … 87.5 mm) and the 76.2 mm disk;
  // the seed is fixed, so the sample is the same on every run and every machine (mt19937_64 and our own
  // mapping to [0, 1)).
  std::mt19937_64 random(20261129);
  const auto u = [&] { return static_cast<double>(random() >> 11) * 0x1.0p-53; };
  for (int i = 0; i < 12; ++i) {
    const double x = 0.0125 + 0.125 * u(), y = 0.0125 + 0.075 * u();
    rig(fmt::format("rig_astm_random_{}", i), rig_deck(astm, x, y), 0, "rig: ASTM D7136");
  }
  for (int i = 0; i < 8; ++i) {
    const double r = 0.0381 * std::sqrt(u()) * 0.97, t = 2.0 * M_PI * u();
    rig(fmt::format("rig_circular_random_{}", i), rig_deck(disk, r * std::cos(t), r * std::sin(t)), 0,
        "rig:");
  }
  // The audit's points (they aborted the program), the window's corners and the coupon's centre.
  const std::vector<std::pair<double, double>> audit = {{0.075, 0.020},   {0.040, 0.020},   {0.075, 0.012},
                                                        {0.030, 0.00625}, {0.0126, 0.0126}, {0.1374, 0.0874}};
  for (std::size_t i = 0; i < audit.size(); ++i)
    rig(fmt::format("rig_astm_audit_{}", i), rig_deck(astm, audit[i].first, audit[i].second), 0, "rig:");
  rig("rig_circular_audit", rig_deck(disk, -0.02, -0.02), 0, "rig:");
  rig("rig_astm_off_the_coupon", rig_deck(astm, 0.2, 0.05), 2, "lies outside the mesh");
  rig("rig_astm_negative_point", rig_deck(astm, -0.01, 0.05), 2, "lies outside the mesh");
  rig("rig_astm_nan_point", rig_deck(astm, NAN, NAN, "x = nan\ny = 0.05\n"), 2, "impactor.x");
  rig("rig_circular_off_the_disk", rig_deck(disk, 0.05, 0.0), 2, "lies outside the mesh");
  rig("rig_unknown_preset", rig_deck("preset = \"astm\"", NAN, NAN), 2, "astm-d7136");
  rig("rig_circular_without_diameter", rig_deck("preset = \"circular\"", NAN, NAN), 2, "diameter");
  rig("rig_circular_zero_diameter", rig_deck("preset = \"circular\"\ndiameter = 0", NAN, NAN), 2, "diameter");
  rig("rig_circular_negative_diameter", rig_deck("preset = \"circular\"\ndiameter = -0.1", NAN, NAN), 2,
      "diameter");
  rig("rig_circular_nan_diameter", rig_deck("preset = \"circular\"\ndiameter = nan", NAN, NAN), 2,
      "diameter");
  rig("rig_circular_1km", rig_deck("preset = \"circular\"\ndiameter = 1000.0", NAN, NAN), 1, "rig.diameter");
  rig("rig_circular_1um", rig_deck("preset = \"circular\"\ndiameter = 1e-6", NAN, NAN), 0, "rig.diameter");
  // 1 um elements ran (17 s for 4 steps), 0.1 um ones factored for ever: below 10 um they are refused (issue
  // 77)
  rig("rig_tiny_elements", rig_deck(astm, NAN, NAN, "[mesh]\nsize_at_impact = 1e-6\n"), 2,
      "mesh.size_at_impact = 1e-06 m is below");
  rig("rig_smallest_elements", rig_deck(astm, NAN, NAN, "[mesh]\nsize_at_impact = 1e-5\n"), 0,
      "rig: ASTM D7136");
  rig("rig_endless_elements", rig_deck(astm, NAN, NAN, "[mesh]\nsize_at_impact = 1e-5\ngrowth = 1.0\n"), 2,
      "before meshing");
  // meshed for 341 s before its assembly was refused for 126 GB: now refused before gmsh starts (issue 77)
  rig("rig_uniform_fine_mesh_beyond_memory",
      rig_deck(astm, NAN, NAN, "[mesh]\nsize_at_impact = 2e-4\ngrowth = 1.0\n"), 2, "before meshing");
  rig("rig_huge_elements", rig_deck(astm, NAN, NAN, "[mesh]\nsize_at_impact = 10.0\n"), 0,
      "mesh.size_at_impact");
  rig("rig_and_plate", rig_deck(astm, NAN, NAN, "[plate]\na = 0.15\nb = 0.1\n"), 2, "[plate]");
  rig("rig_and_boundary", rig_deck(astm, NAN, NAN, "[boundary]\nx0 = \"clamped\"\n"), 2, "[boundary]");
  rig("rig_and_mesh_file", rig_deck(astm, NAN, NAN, "[mesh]\nfile = \"plate.msh\"\n"), 2,
      "[rig] meshes its plate");
  rig("rig_and_mesh_geo", rig_deck(astm, NAN, NAN, "[mesh]\ngeo = \"plate.geo\"\n"), 2,
      "[rig] meshes its plate");
  rig("rig_and_uniform_mesh", rig_deck(astm, NAN, NAN, "[mesh]\nnx = 10\nny = 10\n"), 2, "rig");
  rig("rig_preset_number", rig_deck("preset = 7", NAN, NAN), 2, "rig.preset");
  rig("rig_unknown_key", rig_deck(astm + "\nwindow = 0.1", NAN, NAN), 2, "window");
  rig("rig_thick_coupon_on_small_disk",
      replace_all(rig_deck("preset = \"circular\"\ndiameter = 0.012", NAN, NAN), "[45/0/-45/90]2s",
                  "[45/0/-45/90]4s"),
      0, "fifth");
  for (auto& k : c)
    k.env = "PLYIMPACT_GMSH_TIME_LIMIT_S=30";
  return c;
}

/// Impactor noses with values out of their domain.
std::vector<HostileCase> nose_cases() {
  std::vector<HostileCase> c;
  const auto nose = [&](const std::string& name, const std::string& keys, int exit, const std::string& says,
                        const std::string& extra = "") {
    std::string deck = plate_deck(extra);
    deck = replace_all(deck, "radius = 12.7e-3\n", keys);
    c.push_back({name, impact(), {{"deck.toml", deck}}, exit, says});
  };
  nose("nose_flat", "nose = \"flat\"\nradius = 2e-3\n", 0, "peak force");
  nose("nose_cone", "nose = \"cone\"\nhalf_angle = 60\n", 0, "peak force");
  nose("nose_unknown", "nose = \"ogive\"\nradius = 2e-3\n", 2, "impactor.nose");
  nose("nose_flat_zero_radius", "nose = \"flat\"\nradius = 0\n", 2, "impactor.radius");
  nose("nose_flat_negative_radius", "nose = \"flat\"\nradius = -2e-3\n", 2, "impactor.radius");
  nose("nose_flat_nan_radius", "nose = \"flat\"\nradius = nan\n", 2, "impactor.radius");
  nose("nose_flat_wider_than_plate", "nose = \"flat\"\nradius = 0.5\n", 0, "impactor.radius");
  nose("nose_flat_tan_sun", "nose = \"flat\"\nradius = 2e-3\n", 2, "tan-sun",
       "[contact]\nunloading = \"tan-sun\"\n");
  nose("nose_cone_zero_angle", "nose = \"cone\"\nhalf_angle = 0\n", 2, "half_angle");
  nose("nose_cone_right_angle", "nose = \"cone\"\nhalf_angle = 90\n", 2, "half_angle");
  nose("nose_cone_obtuse", "nose = \"cone\"\nhalf_angle = 120\n", 2, "half_angle");
  nose("nose_cone_nan_angle", "nose = \"cone\"\nhalf_angle = nan\n", 2, "half_angle");
  nose("nose_cone_radians", "nose = \"cone\"\nhalf_angle = 1.0\n", 0, "half_angle");
  nose("nose_cone_without_angle", "nose = \"cone\"\n", 2, "half_angle");
  nose("nose_hemisphere_without_radius", "", 2, "impactor.radius");
  nose("nose_hemisphere_10m", "radius = 10.0\n", 0, "impactor.radius");
  nose("nose_hemisphere_1nm", "radius = 1e-9\n", 0, "impactor.radius");
  nose("nose_hemisphere_inf", "radius = inf\n", 2, "impactor.radius");
  nose("nose_array", "nose = [\"flat\"]\nradius = 2e-3\n", 2, "impactor.nose");
  return c;
}

/// Ply damage: missing, out-of-domain and absurd values of the progressive model and the criteria.
std::vector<HostileCase> damage_cases() {
  std::vector<HostileCase> c;
  const std::string base = replace_all(plate_deck("[damage]\nmodel = \"progressive\"\n"), "rho = 1389.2\n",
                                       std::string("rho = 1389.2\n") + t300_damage);
  const auto damage = [&](const std::string& name, const std::string& deck, int exit,
                          const std::string& says) {
    c.push_back({name, impact(), {{"deck.toml", deck}}, exit, says});
  };
  damage("damage_control", base, 0, "peak force");
  // Out of the domain: refused, naming the key.
  for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{{"G_mt", "-1"},
                                                                                   {"G_mt", "0"},
                                                                                   {"G_ft", "nan"},
                                                                                   {"Yt", "-55e6"},
                                                                                   {"S12", "inf"},
                                                                                   {"Xc", "\"high\""}}) {
    damage("damage_" + key + "_" +
               (value == "\"high\"" ? "text"
                : value == "-55e6"  ? "negative"
                : value == "-1"     ? "minus1"
                                    : value),
           set_key(base, "materials.T300_976", key, value), 2, key);
  }
  for (const auto& [key, value] :
       std::vector<std::pair<std::string, std::string>>{{"viscosity", "-1"},
                                                        {"viscosity", "nan"},
                                                        {"refactor_tolerance", "0"},
                                                        {"refactor_tolerance", "-0.1"},
                                                        {"area_threshold", "0"},
                                                        {"area_threshold", "1.5"},
                                                        {"oversize", "\"ignore\""},
                                                        {"integration", "\"magic\""},
                                                        {"model", "\"progresive\""},
                                                        {"every", "0"},
                                                        {"criteria", "[\"hashinn\"]"},
                                                        {"alpha", "-1"}}) {
    damage("damage_" + key + "_" + name_part(value), set_key(base, "damage", key, value), 2, "damage." + key);
  }
  damage("damage_missing_toughness", replace_all(base, "G_mt = 277.0\n", ""), 2, "G_mt");
  damage("damage_missing_strength", replace_all(base, "S23 = 32.94e6\n", ""), 2, "S23");
  damage("damage_q9_element", set_key(base, "mesh", "element", "\"q9\""), 2, "MITC9");
  damage("damage_poisson_free", set_key(base, "laminate", "reduced_stiffness", "\"poisson-free\""), 2,
         "reduced_stiffness");
  // Absurd but well formed: the run goes on, and says what looks wrong.
  damage("damage_huge_toughness", set_key(base, "materials.T300_976", "G_mt", "1e300"), 0, "G_mt");
  damage("damage_tiny_toughness", set_key(base, "materials.T300_976", "G_mt", "1e-300"), 0, "G_mt");
  damage("damage_huge_fibre_toughness", set_key(base, "materials.T300_976", "G_ft", "1e12"), 0, "G_ft");
  damage("damage_toughness_in_kJ", set_key(base, "materials.T300_976", "G_mc", "0.788"), 0, "G_mc");
  damage("damage_tiny_strength", set_key(base, "materials.T300_976", "Yt", "1e-300"), 0, "Yt");
  damage("damage_huge_viscosity", set_key(base, "damage", "viscosity", "1e300"), 0, "damage.viscosity");
  damage("damage_strength_in_MPa", set_key(base, "materials.T300_976", "Xt", "1500"), 0, "Xt");
  damage("damage_onset_no_strengths",
         small_deck("impact",
                    steel_ball_impactor("dt = 1e-6\nend = 5e-6\n") + "[damage]\ncriteria = [\"hashin\"]\n"),
         2, "hashin");
  damage("damage_nonlinear_explicit",
         set_key(set_key(base, "damage", "integration", "\"explicit\""), "time", "dt", "\"auto\""), 0,
         "peak force");
  return c;
}

/// Delamination: cohesive values out of their domain, absurd, and interfaces that do not exist.
std::vector<HostileCase> delamination_cases() {
  std::vector<HostileCase> c;
  const std::string base = plate_deck(R"([delamination]
interfaces = "orientation-changes"
G_Ic = 969.0
G_IIc = 1719.0
bk_exponent = 2.284
normal_strength = 73.7e6
shear_strength = 98.2e6
)",
                                      "")
                               .append("[contact]\nload = \"point\"\n");
  const auto delam = [&](const std::string& name, const std::string& deck, int exit,
                         const std::string& says) {
    c.push_back({name, impact(), {{"deck.toml", deck}}, exit, says});
  };
  const auto with = [&](const std::string& key, const std::string& value) {
    return set_key(base, "delamination", key, value);
  };
  delam("delamination_control", base, 0, "peak force");
  // issue 77: a seed larger than the plate cracked every interface everywhere, 15 s a step, silently
  delam("delamination_seed_radius_huge", with("seed_radius", "1e300"), 0, "delamination.seed_radius");
  // G_Ic = 1e300 cancelled in the B-K blend to a toughness of 0, and the message blamed the penalty stiffness
  delam("delamination_G_Ic_1e300", with("G_Ic", "1e300"), 2, "check G_Ic and G_IIc");
  delam("delamination_penalty_1e300", with("penalty_stiffness", "1e300"), 1,
        "delamination.penalty_stiffness");
  // explicit with dt = "auto": the run said "reduce time.dt", which is automatic
  delam("delamination_penalty_1e300_explicit",
        replace_all(with("penalty_stiffness", "1e300"), "dt = 1e-6\n",
                    "integration = \"explicit\"\ndt = \"auto\"\n"),
        1, "far out of scale");
  for (const auto& [key, value] :
       std::vector<std::pair<std::string, std::string>>{{"G_Ic", "-969"},
                                                        {"G_Ic", "0"},
                                                        {"G_IIc", "nan"},
                                                        {"bk_exponent", "-1"},
                                                        {"bk_exponent", "inf"},
                                                        {"normal_strength", "0"},
                                                        {"shear_strength", "-1e6"},
                                                        {"penalty_stiffness", "-1e15"},
                                                        {"penalty_stiffness", "\"huge\""},
                                                        {"interfaces", "[0]"},
                                                        {"interfaces", "[99]"},
                                                        {"interfaces", "[3, 2]"},
                                                        {"interfaces", "[2, 2]"},
                                                        {"interfaces", "\"everywhere\""},
                                                        {"onset", "\"tsai\""},
                                                        {"points", "\"lobatto\""},
                                                        {"supports", "\"top\""},
                                                        {"integration", "\"rk4\""}}) {
    delam("delamination_" + key + "_" + name_part(value), with(key, value), 2, "delamination." + key);
  }
  delam("delamination_missing_toughness", replace_all(base, "G_IIc = 1719.0\n", ""), 2, "G_IIc");
  delam("delamination_single_orientation", replace_all(base, "[0_2/90_4/0_2]", "[0_8]"), 2, "interface");
  c.push_back({"delamination_static",
               "static deck.toml -o out",
               {{"deck.toml", replace_all(base, "analysis = \"impact\"", "analysis = \"static\"") +
                                  "[load]\npressure = 1e3\n"}},
               2,
               "delamination"});
  // Absurd but well formed: warned, and the run goes on.
  delam("delamination_huge_bk_exponent", with("bk_exponent", "1e300"), 0, "delamination.bk_exponent");
  delam("delamination_tiny_strength", with("normal_strength", "1e-300"), 0, "delamination.normal_strength");
  delam("delamination_huge_toughness", with("G_Ic", "1e6"), 0, "delamination.G_Ic");
  delam("delamination_absurd_toughness", with("G_Ic", "1e300"), 2, "cohesive law");
  delam("delamination_toughness_in_kJ", with("G_IIc", "1.719"), 2, "G_IIc");
  delam("delamination_strength_in_MPa", with("shear_strength", "98.2"), 0, "shear_strength");
  delam("delamination_huge_penalty", with("penalty_stiffness", "1e20"), 1, "delamination.penalty_stiffness");
  delam("delamination_tiny_penalty", with("penalty_stiffness", "1e3"), 2, "penalty_stiffness");
  return c;
}

/// Sweeps: broken specifications, cases that fail among good ones, and what a sweep folder holds.
std::vector<HostileCase> sweep_cases() {
  std::vector<HostileCase> c;
  // whole events (a case cut short by time.end is a failed case): the small plate, a few thousand steps
  const std::string deck = small_deck("impact", steel_ball_impactor("dt = 2e-6\n"));
  const auto sweep = [&](const std::string& name, const std::string& options, int exit,
                         const std::string& says, const std::string& with = "") {
    c.push_back(
        {name, "sweep deck.toml -o out " + options, {{"deck.toml", with.empty() ? deck : with}}, exit, says});
  };
  sweep("sweep_control", "--set impactor.velocity=1,2", 0, "2 cases");
  sweep("sweep_unknown_key", "--set impactor.speed=1,2", 2, "impactor.speed");
  sweep("sweep_empty_values", "--set impactor.velocity=", 2, "impactor.velocity");
  sweep("sweep_bad_range", "--set impactor.velocity=1:2:1", 2, "count");
  sweep("sweep_range_text", "--set impactor.velocity=a:b:3", 2, "impactor.velocity");
  sweep("sweep_huge_range", "--set impactor.velocity=1:2:1000000000", 2, "count");
  sweep("sweep_mode_unknown", "--set impactor.velocity=1,2 --mode diagonal", 2, "--mode");
  sweep("sweep_zip_unequal", "--set impactor.velocity=1,2 --set impactor.mass=0.1,0.2,0.3 --mode zip", 2,
        "zip");
  sweep("sweep_jobs_zero", "--set impactor.velocity=1,2 --jobs 0", 2, "--jobs");
  sweep("sweep_jobs_negative", "--set impactor.velocity=1,2 --jobs -3", 2, "--jobs");
  sweep("sweep_jobs_huge", "--set impactor.velocity=1,2 --jobs 100000", 2, "--jobs");
  sweep("sweep_jobs_text", "--set impactor.velocity=1,2 --jobs many", 2, "--jobs");
  sweep("sweep_one_case_fails", "--set impactor.velocity=1,-2,2", 0, "1 of 3 cases did not complete");
  sweep("sweep_every_case_fails", "--set impactor.velocity=-1,-2", 1, "impactor.velocity");
  sweep("sweep_mesh_nx_text", "--set mesh.nx=a,b", 1, "mesh.nx");
  sweep("sweep_layup_broken", "--set laminate.layup=[0/90,[0/90]s", 0, "1 of 2 cases did not complete");
  sweep("sweep_resume_nothing", "--set impactor.velocity=1,2 --resume", 0, "2 cases");
  sweep("sweep_random_bad_distribution", "", 2, "sweep.random",
        deck + "[sweep.random]\nsamples = 2\nseed = 1\n\"impactor.velocity\" = { lognormal = [1, 2] }\n");
  sweep("sweep_random_negative_samples", "", 2, "samples",
        deck + "[sweep.random]\nsamples = -2\nseed = 1\n\"impactor.velocity\" = { uniform = [1, 2] }\n");
  sweep(
      "sweep_random_huge_samples", "", 2, "samples",
      deck +
          "[sweep.random]\nsamples = 100000000000\nseed = 1\n\"impactor.velocity\" = { uniform = [1, 2] }\n");
  sweep(
      "sweep_random_negative_modulus", "", 1, "none of the 3 cases completed",
      deck +
          "[sweep.random]\nsamples = 3\nseed = 7\n\"materials.T300_976.E2\" = { uniform = [-2e9, -1e9] }\n");
  sweep("sweep_values_table", "", 2, "sweep.values",
        deck + "[sweep.values]\n\"impactor.velocity\" = { a = 1 }\n");
  sweep("sweep_analysis_unknown", "", 2, "sweep.analysis",
        deck + "[sweep]\nanalysis = \"modal\"\n[sweep.values]\n\"impactor.velocity\" = [1, 2]\n");
  sweep("sweep_nothing_to_sweep", "", 2, "sweep", deck);
  // the audit's rig points (one aborted the whole sweep), as whole events of a light striker
  const std::string light_rig = replace_all(
      rig_deck("preset = \"astm-d7136\"", NAN, NAN, "energy = 0.5\n[time]\n"), "mass = 5.5", "mass = 0.05");
  sweep("sweep_rig_points", "--set impactor.x=0.075,0.03 --set impactor.y=0.00625", 0, "2 cases", light_rig);
  sweep("sweep_rig_point_off_coupon", "--set impactor.x=0.075,0.3 --set impactor.y=0.05", 0,
        "1 of 2 cases did not complete", light_rig);
  c.push_back({"sweep_into_a_file",
               "sweep deck.toml -o out.txt --set impactor.velocity=1,2",
               {{"deck.toml", deck}, {"out.txt", "a file, not a folder\n"}},
               1,
               "out.txt"});
  for (auto& k : c)
    k.env = "PLYIMPACT_GMSH_TIME_LIMIT_S=30";
  return c;
}

/// Command lines: options out of range, files that are not decks, output folders that cannot be written.
std::vector<HostileCase> command_line_cases() {
  std::vector<HostileCase> c;
  const std::string deck =
      plate_deck("[damage]\ncriteria = [\"max-stress\"]\n[threshold]\ntolerance = 0.5\n").insert(0, "");
  const std::string onset =
      replace_all(deck, "rho = 1389.2\n",
                  "rho = 1389.2\nXt = 1.5e9\nXc = 1.2e9\nYt = 55.2e6\nYc = 294.0e6\nS12 = 101.1e6\n");
  const auto cli = [&](const std::string& name, const std::string& args, int exit, const std::string& says,
                       std::vector<CaseFile> files = {}) {
    if (files.empty()) files = {{"deck.toml", onset}};
    c.push_back({name, args, std::move(files), exit, says});
  };
  for (const std::string t : {"-1", "0", "nan", "inf", "abc", "1e400"})
    cli("threshold_tolerance_" + std::string(t == "-1"      ? "minus1"
                                             : t == "1e400" ? "overflow"
                                                            : t),
        "threshold deck.toml -o out --tolerance " + t, 2, "--tolerance");
  for (const std::string t : {"0", "-1", "100000", "x"})
    cli("threads_" + std::string(t == "-1" ? "minus1" : t), "impact deck.toml -o out --threads " + t, 2,
        "--threads");
  cli("unknown_option", "impact deck.toml -o out --fast", 2, "--fast");
  cli("unknown_command", "impakt deck.toml", 2, "impact");
  cli("no_deck", "impact", 2, "deck");
  cli("deck_missing", "impact nothing.toml -o out", 2, "nothing.toml");
  cli("deck_is_a_folder", "impact sub -o out", 2, "sub", {{"sub", "<dir>"}});
  cli("deck_is_a_fifo", "impact pipe.toml -o out", 2, "pipe.toml", {{"pipe.toml", "<fifo>"}});
  cli("deck_is_dev_zero", "impact /dev/zero -o out", 2, "/dev/zero");
  cli("deck_empty", "impact deck.toml -o out", 2, "deck.toml", {{"deck.toml", ""}});
  cli("deck_binary", "impact deck.toml -o out", 2, "deck.toml",
      {{"deck.toml", std::string("\0\x01\x02\xff\xfe binary", 12)}});
  cli("deck_not_utf8", "impact deck.toml -o out", 2, "deck.toml", {{"deck.toml", "title = \"\xc3\x28\"\n"}});
  cli("deck_huge_number", "impact deck.toml -o out", 2, "1e999",
      {{"deck.toml", set_key(onset, "impactor", "velocity", "1e999")}});
  cli("deck_deep_arrays", "impact deck.toml -o out", 2, "deck.toml",
      {{"deck.toml", onset + "x = " + std::string(5000, '[') + std::string(5000, ']') + "\n"}});
  cli("output_is_a_file", "impact deck.toml -o out.txt", 1, "out.txt",
      {{"deck.toml", onset}, {"out.txt", "a file\n"}});
  cli("output_in_proc", "impact deck.toml -o /proc/plyimpact-out", 1, "/proc/plyimpact-out");
  cli("static_on_impact_deck_without_load", "static deck.toml -o out", 2, "[load]");
  cli("modal_zero_modes", "modal deck.toml -o out", 2, "modal.count",
      {{"deck.toml", onset + "[modal]\ncount = 0\n"}});
  cli("buckling_no_load", "buckling deck.toml -o out", 2, "buckling",
      {{"deck.toml", onset + "[buckling]\ncount = 2\n"}});
  cli("max_steps_reached", "impact deck.toml -o out", 3, "step limit",
      {{"deck.toml", set_key(onset, "time", "max_steps", "2")}});
  cli("memory_limit_malformed", "impact deck.toml -o out", 2, "PLYIMPACT_MEMORY_LIMIT_BYTES");
  c.back().env = "PLYIMPACT_MEMORY_LIMIT_BYTES=lots";
  cli("gmsh_time_limit_malformed", "impact deck.toml -o out", 2, "PLYIMPACT_GMSH_TIME_LIMIT_S",
      {{"deck.toml", mesh_deck("geo = \"plate.geo\"")}, {"plate.geo", rectangle_geo()}});
  c.back().env = "PLYIMPACT_GMSH_TIME_LIMIT_S=-5";
  return c;
}

/// The re-audit of issue 77: a crash, hangs, silent wrong answers and raw messages, each reproduced.
std::vector<HostileCase> audit_cases() {
  std::vector<HostileCase> c;
  const std::string deck =
      plate_deck("[damage]\ncriteria = [\"max-stress\"]\n[threshold]\ntolerance = 0.5\n");
  const std::string onset =
      replace_all(deck, "rho = 1389.2\n",
                  "rho = 1389.2\nXt = 1.5e9\nXc = 1.2e9\nYt = 55.2e6\nYc = 294.0e6\nS12 = 101.1e6\n");
  const auto add = [&](const std::string& name, const std::string& args, int exit, const std::string& says,
                       std::vector<CaseFile> files = {}, const std::string& env = {}) {
    if (files.empty()) files = {{"deck.toml", onset}};
    c.push_back({name, args, std::move(files), exit, says, env});
  };
  // OMP_NUM_THREADS=100000 crashed in libgomp (exit 139): capped to the machine, and checked
  add("omp_threads_huge_impact", "impact deck.toml -o out", 0, "more threads than the machine", {},
      "OMP_NUM_THREADS=100000");
  add("omp_threads_huge_threshold", "threshold deck.toml -o out", 0, "more threads than the machine", {},
      "OMP_NUM_THREADS=100000");
  add("omp_threads_list", "impact deck.toml -o out", 0, "peak force", {}, "OMP_NUM_THREADS=1,1");
  for (const std::string v : {"abc", "0", "-4", "2x", "1,,2"})
    add("omp_threads_malformed_" + name_part(v), "impact deck.toml -o out", 2, "OMP_NUM_THREADS", {},
        "OMP_NUM_THREADS=" + v);
  // --progress-every nan was accepted
  for (const std::string v : {"nan", "inf", "-1", "1e300", "x"})
    add("progress_every_" + name_part(v), "impact deck.toml -o out --progress-every " + v, 2,
        "--progress-every");
  add("progress_every_zero", "impact deck.toml -o out --progress-every 0", 0, "peak force");
  // threshold finding no failure exited 4, the internal-error code: it is a result
  add("threshold_no_failure", "threshold deck.toml -o out", 0, "no failure up to the velocity limit",
      {{"deck.toml", set_key(onset, "threshold", "max_velocity", "0.01")}});
  // a rig whose element sizes are absurdly small factored for ever, deaf to Ctrl-C
  for (const std::string size : {"1e-9", "1e-7", "5e-6"})
    add("rig_size_at_impact_" + name_part(size), "impact deck.toml -o out", 2, "is below",
        {{"deck.toml",
          rig_deck("preset = \"astm-d7136\"", NAN, NAN, "[mesh]\nsize_at_impact = " + size + "\n")}});
  // nodal mass scaling far beyond the mesh's step: a heavier plate, silently (now suspect); and a target
  // so far that Lanczos failed with Spectra's raw message as an internal error
  const auto explicit_deck = [&](const std::string& target) {
    return replace_all(set_key(plate_deck(), "mesh", "mass", "\"lumped\""), "dt = 1e-6\nend = 5e-6\n",
                       "integration = \"explicit\"\ndt = \"auto\"\nmass_scaling = \"nodal\"\ntarget_dt = " +
                           target + "\nend = 2e-4\n");
  };
  add("mass_scaling_far_beyond_the_step", "impact deck.toml -o out", 0, "SUSPECT",
      {{"deck.toml", explicit_deck("1e-5")}});
  add("mass_scaling_target_dt_1e300", "impact deck.toml -o out", 1, "could not be computed",
      {{"deck.toml", explicit_deck("1e300")}});
  // plot: a results folder is input; it blocked on a FIFO, never ended on /dev/zero, took a cut or nan row
  const std::string header = "t_s,force_N,impactor_w_m,impactor_v_m_per_s,plate_w_m,indentation_m,"
                             "plate_kinetic_J,plate_strain_J,impactor_energy_J,contact_work_J\n";
  const std::string rows = "0,0,0,1,0,0,0,0,1,0\n1e-6,12,1e-6,1,1e-6,0,0,0,1,0\n";
  const auto plot_case = [&](const std::string& name, const std::string& history, const std::string& says) {
    add("plot_history_" + name, "plot res -o pics", 2, says, {{"res/history.csv", history}});
  };
  plot_case("fifo", "<fifo>", "not a regular file");
  plot_case("dev_zero", "<link>/dev/zero", "not a regular file");
  plot_case("folder", "<dir>", "not a regular file");
  plot_case("empty", "", "no header line");
  plot_case("cut_mid_row", header + rows + "2e-6,12", "cut mid-row");
  plot_case("nan_row", header + rows + "2e-6,nan,0,1,0,0,0,0,1,0\n", "not a finite number");
  plot_case("inf_row", header + rows + "2e-6,inf,0,1,0,0,0,0,1,0\n", "not a finite number");
  plot_case("garbage_row", header + rows + "hello world\n", "cells where the header has 10");
  plot_case("garbage_cell", header + rows + "2e-6,12abc,0,1,0,0,0,0,1,0\n", "not a finite number");
  plot_case("not_a_history", "a,b\n1,2\n", "not t_s");
  add("plot_summary_with_a_string", "plot res -o pics", 0, "force_time",
      {{"res/history.csv", header + rows},
       {"res/summary.json", "{\"impact_velocity\": \"fast\", \"impactor_mass\": [1]}"}});
  add("plot_summary_not_an_object", "plot res -o pics", 0, "force_time",
      {{"res/history.csv", header + rows}, {"res/summary.json", "[1, 2]"}});
  // a deck whose name is not UTF-8 threw json's type_error.316 when summary.json was written
  add("deck_name_not_utf8", "impact \xff.toml -o out", 0, "peak force", {{"\xff.toml", onset}});
  plot_case("binary",
            std::string("\x7f"
                        "ELF\0\x01\x02",
                        7),
            "error");
  return c;
}

std::vector<HostileCase> all_cases() {
  std::vector<HostileCase> all;
  for (const auto& family :
       {geo_cases(), sandbox_cases(), audit_cases(), msh_cases(), rig_cases(), nose_cases(), damage_cases(),
        delamination_cases(), sweep_cases(), command_line_cases()})
    all.insert(all.end(), family.begin(), family.end());
  return all;
}

// ---------------------------------------------------------------------------------------------------

/// How long one case may take before it counts as a hang (the sanitizers' build included).
constexpr int case_time_limit_s = 300;

void write_case_files(const fs::path& dir, const HostileCase& k) {
  for (const CaseFile& f : k.files) {
    const fs::path p = dir / f.name;
    fs::create_directories(p.parent_path());
    if (f.text == "<fifo>") {
      ASSERT_EQ(::mkfifo(p.c_str(), 0600), 0) << p;
    } else if (f.text == "<dir>") {
      fs::create_directories(p);
    } else if (f.text.starts_with("<link>")) {
      fs::create_symlink(f.text.substr(6), p);
    } else {
      std::ofstream(p, std::ios::binary) << replace_all(f.text, "{dir}", dir.string());
    }
  }
}

class HostileInputs : public ::testing::TestWithParam<HostileCase> {};

TEST_P(HostileInputs, Survives) {
  const HostileCase& k = GetParam();
  const fs::path dir = scratch("hostile-" + k.name);
  write_case_files(dir, k);
  const CommandResult r =
      shell(fmt::format("cd '{}' && env {} timeout -s KILL {} {} {} < /dev/null", dir.string(), k.env,
                        case_time_limit_s, PLYIMPACT_EXE, replace_all(k.args, "{dir}", dir.string())));
  const std::string shown =
      r.out.size() > 4000 ? r.out.substr(0, 2000) + "\n[…]\n" + r.out.substr(r.out.size() - 2000) : r.out;
  // never a crash, an abort, an internal error or a hang
  EXPECT_NE(r.status, 4) << "internal error\n" << shown;
  EXPECT_NE(r.status, 137) << "killed after " << case_time_limit_s << " s: a hang\n" << shown;
  EXPECT_NE(r.status, -1) << "ended by a signal\n" << shown;
  EXPECT_EQ(r.status, k.exit) << shown;
  EXPECT_NE(r.out.find(k.says), std::string::npos) << "expected \"" << k.says << "\" in\n" << shown;
  // a run that says it succeeded has written its results; one that failed says why
  if (r.status == 0 || r.status == 3) {
    if (k.args.find("-o out ") != std::string::npos || k.args.ends_with("-o out")) {
      EXPECT_TRUE(fs::exists(dir / "out" / "summary.json") || fs::exists(dir / "out" / "sweep.csv") ||
                  fs::exists(dir / "out" / "cases.csv"))
          << "exit " << r.status << " but no results in " << (dir / "out") << "\n"
          << shown;
    }
  } else {
    EXPECT_NE(r.out.find("error"), std::string::npos) << shown;
  }
  // no shell command ran from the deck, and no file was written by it
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_FALSE(entry.path().filename().string().starts_with("pwned")) << "a deck wrote " << entry.path();
  EXPECT_TRUE(fs::exists(dir / "deck.toml") || k.files.empty() || k.files.front().name != "deck.toml")
      << "a deck deleted a file";
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Case, HostileInputs, ::testing::ValuesIn(all_cases()),
                         [](const ::testing::TestParamInfo<HostileCase>& param) { return param.param.name; });

TEST(HostileInputSuite, HoldsAtLeastFourHundredCasesWithUniqueNames) {
  const std::vector<HostileCase> all = all_cases();
  std::vector<std::string> names;
  for (const HostileCase& k : all)
    names.push_back(k.name);
  std::sort(names.begin(), names.end());
  EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end());
  EXPECT_GE(all.size(), 400U); // issue 77 asked for at least 400
  std::printf("  %zu hostile cases\n", all.size());
}

} // namespace
} // namespace plyimpact::test::hostile_inputs_tests
