// The outputs of an impact run on the stacked plate (issue 19): history.csv follows the delaminated areas
// and the interfaces' dissipation step by step — the areas never shrink (the law is irreversible), the
// last row is the summary's, and with the dissipation the energies add up to the impact energy on every
// row; delamination_points.csv gives each interface point the part of the plate it stands for (the cells
// tile the plate, and the delaminated cells add up to the summary's areas); the maps' titles quote those
// areas; the ParaView frames carry each interface's damage as delamination_elements.csv has it.
//
// The case: examples/impact-delamination.toml (30 g at 3 m/s on a clamped 13.2 mm [0_2/90_2]s AS4/PEEK
// plate) on 5 × 5 elements to 0.25 ms, where both interfaces delaminate over 3.1 mm² (2 s).
#include "plyimpact/analysis/thresholds/delamination_shape.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/io/results/ply_damage_maps.hpp"
#include "plyimpact/io/run/impact_run.hpp"
#include "support/cli.hpp"
#include "test_paths.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace plyimpact::delamination_outputs_tests {
namespace {

namespace fs = std::filesystem;

/// A CSV file as its header's names and its rows of numbers.
struct Table {
  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;
  [[nodiscard]] std::size_t column(const std::string& name) const {
    const auto it = std::find(names.begin(), names.end(), name);
    EXPECT_NE(it, names.end()) << "no column " << name;
    return static_cast<std::size_t>(it - names.begin());
  }
};

Table read_table(const fs::path& csv) {
  std::ifstream in(csv);
  Table t;
  std::string line, cell;
  std::getline(in, line);
  std::istringstream header(line);
  while (std::getline(header, cell, ','))
    t.names.push_back(cell);
  while (std::getline(in, line)) {
    std::istringstream cells(line);
    std::vector<double>& row = t.rows.emplace_back();
    while (std::getline(cells, cell, ','))
      row.push_back(std::stod(cell));
  }
  return t;
}

/// The shipped example on 5 × 5 elements to 0.25 ms, with ParaView frames every 500 steps.
Deck small_delamination_deck() {
  std::string text = test::read_text(fs::path(PLYIMPACT_SOURCE_DIR) / "examples/impact-delamination.toml");
  text = test::with_line(text, "nx = 11", "nx = 5");
  text = test::with_line(text, "ny = 11", "ny = 5");
  text = test::with_line(text, "end = 0.35e-3", "end = 0.25e-3");
  return parse_deck(text + "[output]\nvtk_every = 500\n", "impact-delamination.toml");
}

/// The run, once per test process (ctest runs each test in its own process, so each its own folder).
struct DelaminationRun {
  fs::path out;
  nlohmann::json summary;
};

const DelaminationRun& the_run() {
  static const DelaminationRun run = [] {
    DelaminationRun r{test::scratch(fmt::format("delamination-outputs-{}", ::getpid())) / "out", {}};
    const Deck deck = small_delamination_deck();
    const ImpactCase impact(impact_case_description(deck));
    ImpactRunOptions options;
    options.output_dir = r.out;
    options.pictures = false;
    r.summary = run_impact(deck, impact, options).summary;
    return r;
  }();
  return run;
}

class DelaminationOutputs : public ::testing::Test {
protected:
  static const fs::path& out() { return the_run().out; }
  static const nlohmann::json& summary() { return the_run().summary; }
  static const nlohmann::json& delamination() { return summary()["delamination"]; }
};

TEST_F(DelaminationOutputs, HistoryFollowsTheAreasAndTheEnergyTheInterfacesDissipate) {
  const Table h = read_table(out() / "history.csv");
  const std::vector<int> plies = delamination()["interfaces_after_ply"];
  ASSERT_EQ(plies, (std::vector<int>{2, 6}));
  std::vector<std::size_t> interface;
  for (const int p : plies)
    interface.push_back(h.column(fmt::format("delamination_area_after_ply{}_m2", p)));
  const std::size_t projected = h.column("delamination_area_m2");
  const std::size_t dissipated = h.column("delamination_dissipation_J");
  ASSERT_EQ(h.names.size(), 10U + 2U + plies.size());
  // Irreversible: no area and no dissipation ever decreases; the projected area is the union.
  for (std::size_t r = 1; r < h.rows.size(); ++r) {
    for (const std::size_t c : interface)
      EXPECT_GE(h.rows[r][c], h.rows[r - 1][c]) << "row " << r;
    EXPECT_GE(h.rows[r][dissipated], h.rows[r - 1][dissipated]) << "row " << r;
    double largest = 0.0, sum = 0.0;
    for (const std::size_t c : interface) {
      largest = std::max(largest, h.rows[r][c]);
      sum += h.rows[r][c];
    }
    EXPECT_GE(h.rows[r][projected], largest);
    EXPECT_LE(h.rows[r][projected], sum * (1.0 + 1e-12));
  }
  // It starts intact and ends with the summary's areas (3.1 mm² at both interfaces); the summary's first
  // growth is the first row with an area (every step's row: the run has fewer than 4 096 steps).
  EXPECT_EQ(h.rows.front()[projected], 0.0);
  const auto grown = std::find_if(h.rows.begin(), h.rows.end(),
                                  [&](const std::vector<double>& row) { return row[projected] > 0.0; });
  ASSERT_NE(grown, h.rows.end());
  EXPECT_EQ(delamination()["first_growth"]["time_s"].get<double>(), (*grown)[0]);
  EXPECT_EQ(delamination()["first_growth"]["force_N"].get<double>(), (*grown)[h.column("force_N")]);
  const std::vector<double>& last = h.rows.back();
  for (std::size_t i = 0; i < interface.size(); ++i)
    EXPECT_EQ(last[interface[i]], delamination()["delaminated_area_m2"][i].get<double>());
  EXPECT_GT(last[projected], 1e-6);
  EXPECT_EQ(last[projected], delamination()["projected_delaminated_area_m2"].get<double>());
  EXPECT_EQ(last[dissipated], delamination()["dissipated_energy_J"].get<double>());
  // Energy (SPEC §4): impactor + plate kinetic + stored + contact work + dissipated = ½ m v0² = 0.135 J on
  // every row, within the summary's balance error (0.52 %); without the dissipation the last row would
  // miss it by 0.0144 J, 10.7 %.
  const double e0 = 0.5 * 0.03 * 3.0 * 3.0;
  const double tolerance = summary()["energy_balance_error"].get<double>() * 1.01 + 1e-9;
  EXPECT_LT(tolerance, 0.01);
  for (const std::vector<double>& row : h.rows) {
    const double total = row[h.column("impactor_energy_J")] + row[h.column("plate_kinetic_J")] +
                         row[h.column("plate_strain_J")] + row[h.column("contact_work_J")] + row[dissipated];
    EXPECT_NEAR(total, e0, tolerance * e0) << "t = " << row[0];
  }
  EXPECT_GT(last[dissipated], 5.0 * tolerance * e0);
}

TEST_F(DelaminationOutputs, EachInterfacePointStandsForACellAndTheCellsAddUpToTheAreas) {
  const Table points = read_table(out() / delamination_points_file);
  ASSERT_EQ(points.rows.size(), 25U * 9U); // 5 × 5 elements, 3 × 3 nodal points each
  const std::size_t area = points.column("area_m2");
  double plate = 0.0;
  std::map<int, double> delaminated;
  for (const std::vector<double>& p : points.rows) {
    // The cell is a rectangle here (a rectangular mesh): its shoelace area is the point's area w detJ.
    double shoelace = 0.0;
    for (std::size_t a = 0; a < 4; ++a) {
      const std::size_t b = (a + 1) % 4;
      const double xa = p[points.column(fmt::format("x{}_m", a + 1))];
      const double ya = p[points.column(fmt::format("y{}_m", a + 1))];
      const double xb = p[points.column(fmt::format("x{}_m", b + 1))];
      const double yb = p[points.column(fmt::format("y{}_m", b + 1))];
      shoelace += 0.5 * (xa * yb - xb * ya);
    }
    EXPECT_NEAR(shoelace, p[area], 1e-12 * 0.0132 * 0.0132) << "point " << p[0];
    plate += p[area];
    for (const int ply : {2, 6})
      if (p[points.column(fmt::format("d_after_ply_{}", ply))] >= 1.0) delaminated[ply] += p[area];
  }
  EXPECT_NEAR(plate, 0.0132 * 0.0132, 1e-15); // the cells tile the plate
  EXPECT_NEAR(delaminated[2], delamination()["delaminated_area_m2"][0].get<double>(), 1e-15);
  EXPECT_NEAR(delaminated[6], delamination()["delaminated_area_m2"][1].get<double>(), 1e-15);

  // The maps: one per interface, the projected one and the C-scan, their titles quoting those areas in
  // mm².
  const std::vector<PlotSpec> maps = delamination_map_plots(out());
  ASSERT_EQ(maps.size(), 4U);
  EXPECT_EQ(maps[0].name, "delamination_map_after_ply02");
  EXPECT_EQ(maps[1].name, "delamination_map_after_ply06");
  EXPECT_EQ(maps[2].name, "delamination_map_projected");
  EXPECT_EQ(maps[3].name, "delamination_cscan");
  // Its colour box is labelled "after ply 2" … beside the box, with the box's label right of them: the
  // script reserves a right margin for both, which gnuplot's own (with `size ratio -1`) did not leave.
  EXPECT_NE(maps[3].extra.find("set rmargin 21\n"), std::string::npos) << maps[3].extra.substr(0, 400);
  EXPECT_NE(maps[1].title.find(fmt::format("delaminated {:.3g} mm^2", delaminated[6] * 1e6)),
            std::string::npos)
      << maps[1].title;
}

TEST_F(DelaminationOutputs, TheReportsCscanGivesEachInterfaceTheAreaItShowsAndTheyAddUpToTheProjection) {
  // A C-scan from the impacted face sees the interface after ply 2 wherever it has delaminated, the one
  // after ply 6 only where ply 2's has not: the two shares, summed from delamination_points.csv, add up to
  // the summary's projected area, and report.html quotes them.
  const Table points = read_table(out() / delamination_points_file);
  double upper = 0.0, lower_seen = 0.0;
  for (const std::vector<double>& p : points.rows) {
    const bool d2 = p[points.column("d_after_ply_2")] >= 1.0, d6 = p[points.column("d_after_ply_6")] >= 1.0;
    upper += d2 ? p[points.column("area_m2")] : 0.0;
    lower_seen += !d2 && d6 ? p[points.column("area_m2")] : 0.0;
  }
  EXPECT_NEAR(upper + lower_seen, delamination()["projected_delaminated_area_m2"].get<double>(), 1e-15);
  // The shallower interface shows whole, the deeper one at most its own area (here none of it: at
  // 0.25 ms its delamination lies under the upper one's).
  EXPECT_NEAR(upper, delamination()["delaminated_area_m2"][0].get<double>(), 1e-15);
  EXPECT_GT(upper, 0.0);
  EXPECT_LE(lower_seen, delamination()["delaminated_area_m2"][1].get<double>() + 1e-15);
  std::ifstream in(out() / "report.html");
  std::stringstream html;
  html << in.rdbuf();
  EXPECT_NE(html.str().find("<h2>Delaminations (C-scan)</h2>"), std::string::npos);
  EXPECT_NE(html.str().find(fmt::format("interface after ply 2: {:.4g} mm² seen", upper * 1e6)),
            std::string::npos);
  EXPECT_NE(html.str().find(fmt::format("interface after ply 6: {:.4g} mm² seen", lower_seen * 1e6)),
            std::string::npos);
}

TEST_F(DelaminationOutputs, EachInterfacesShapeIsGivenWithTheFibresOfThePlyBelow) {
  // [0_2/90_2]s: the ply below the interface after ply 2 is at 90°, below the one after ply 6 at 0°; each
  // shape's area is the interface's delaminated area, its axis and ratio given where it has one.
  const nlohmann::json& shapes = delamination()["shapes"];
  ASSERT_EQ(shapes.size(), 2U);
  EXPECT_EQ(shapes[0]["after_ply"], 2);
  EXPECT_EQ(shapes[0]["ply_below_angle_deg"].get<double>(), 90.0);
  EXPECT_EQ(shapes[1]["ply_below_angle_deg"].get<double>(), 0.0);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(shapes[i]["area_m2"].get<double>(), delamination()["delaminated_area_m2"][i].get<double>(),
                1e-15);
    ASSERT_TRUE(shapes[i]["axis_deg"].is_number()) << shapes.dump(1);
    EXPECT_GE(shapes[i]["aspect_ratio"].get<double>(), 1.0);
    EXPECT_NEAR(shapes[i]["axis_to_fibre_deg"].get<double>(),
                angle_between_lines_deg(shapes[i]["axis_deg"].get<double>(),
                                        shapes[i]["ply_below_angle_deg"].get<double>()),
                1e-12);
  }
}

TEST_F(DelaminationOutputs, ParaViewFramesCarryEachInterfacesDamage) {
  const Table elements = read_table(out() / delamination_elements_file);
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  const fs::path last = out() / "paraview" / fmt::format("plate_{:07d}.vtu", summary()["steps"].get<long>());
  ASSERT_TRUE(fs::exists(last)) << last;
  reader->SetFileName(last.string().c_str());
  reader->Update();
  vtkCellData& cells = *reader->GetOutput()->GetCellData();
  vtkDataArray* after2 = cells.GetArray("cohesive_d_after_ply2");
  vtkDataArray* after6 = cells.GetArray("cohesive_d_after_ply6");
  vtkDataArray* largest = cells.GetArray("cohesive_d_max");
  ASSERT_TRUE(after2 != nullptr && after6 != nullptr && largest != nullptr);
  ASSERT_EQ(after2->GetNumberOfTuples(), static_cast<vtkIdType>(elements.rows.size()));
  int delaminated = 0;
  for (std::size_t e = 0; e < elements.rows.size(); ++e) {
    const auto id = static_cast<vtkIdType>(e);
    const double d2 = elements.rows[e][elements.column("d_after_ply_2")];
    const double d6 = elements.rows[e][elements.column("d_after_ply_6")];
    EXPECT_EQ(after2->GetTuple1(id), d2) << "element " << e + 1;
    EXPECT_EQ(after6->GetTuple1(id), d6) << "element " << e + 1;
    EXPECT_EQ(largest->GetTuple1(id), std::max(d2, d6)) << "element " << e + 1;
    delaminated += d6 >= 1.0 ? 1 : 0;
  }
  EXPECT_GT(delaminated, 0);
}

} // namespace
} // namespace plyimpact::delamination_outputs_tests
