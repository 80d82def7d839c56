// The plots' contents, read from the specs `impact_plots` builds (no gnuplot needed): the damage-area
// plot of a 24-ply laminate is drawn as small multiples of at most ten distinguishable curves, layers in
// stacking order; the drop-weight energy plot starts from the impact energy of the history's first row;
// the force-indentation and force-displacement plots keep only the contact part.
#include "plyimpact/io/results/plots.hpp"

#include "support/cli.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>

namespace plots_tests {

namespace {

using namespace plyimpact;
namespace fs = std::filesystem;
using plyimpact::test::scratch;

/// A results folder with a two-row history (E0 = 22.05 J) and a damage_area.csv holding one row per
/// layer: `plies` plies with matrix cracks and `interfaces` delaminated interfaces, written in the
/// lexical order of their numbers (1, 10, 11, ..., 2, ...) as a file sorted as text would be.
fs::path results_with_damage(const std::string& name, int plies, int interfaces) {
  const fs::path dir = scratch(name);
  std::ofstream(dir / "history.csv")
      << "t_s,force_N,impactor_w_m,impactor_v_m_per_s,plate_w_m,indentation_m,plate_kinetic_J,"
         "plate_strain_J,impactor_energy_J,contact_work_J\n"
      << "0,0,0,2.68,0,0,0,0,22.05,0\n"
      << "1e-3,100,1e-3,2.5,1e-3,0,0,0,19.2,0\n";
  std::vector<std::string> rows;
  for (int k = 1; k <= plies; ++k)
    rows.push_back(fmt::format("5e-4,choi-chang-matrix,{},,{}e-6", k, k));
  for (int k = 1; k <= interfaces; ++k)
    rows.push_back(fmt::format("5e-4,choi-chang-delamination,,{},{}e-6", k, k));
  std::sort(rows.begin(), rows.end());
  std::ofstream csv(dir / "damage_area.csv");
  csv << "time_s,criterion,ply,interface,failed_area_m2\n";
  for (const std::string& r : rows)
    csv << r << "\n";
  return dir;
}

const PlotSpec& find(const std::vector<PlotSpec>& specs, const std::string& name) {
  const auto it = std::find_if(specs.begin(), specs.end(), [&](const PlotSpec& s) { return s.name == name; });
  if (it == specs.end()) throw std::runtime_error("no plot " + name);
  return *it;
}

TEST(Plots, FortySevenDamagedLayersAreSmallMultiplesOfAtMostTenCurvesInStackingOrder) {
  const fs::path dir = results_with_damage("plots-47", 24, 23);
  const auto specs = impact_plots({{dir, "run", dir / "history.csv"}});
  const PlotSpec& damage = find(specs, "damage_area");
  ASSERT_TRUE(damage.curves.empty());
  // 23 interfaces -> 8, 8, 7; 24 plies -> 8, 8, 8 (three panels each, as even as possible).
  ASSERT_EQ(damage.panels.size(), 6U);
  const std::vector<std::string> titles = {"choi-chang-delamination: interfaces 1-8",
                                           "choi-chang-delamination: interfaces 9-16",
                                           "choi-chang-delamination: interfaces 17-23",
                                           "choi-chang-matrix: plies 1-8",
                                           "choi-chang-matrix: plies 9-16",
                                           "choi-chang-matrix: plies 17-24"};
  std::size_t layers = 0;
  for (std::size_t k = 0; k < damage.panels.size(); ++k) {
    const PlotPanel& panel = damage.panels[k];
    EXPECT_EQ(panel.title, titles[k]);
    EXPECT_LE(panel.curves.size(), max_curves_per_panel);
    std::set<std::string> colours;
    for (const PlotCurve& c : panel.curves)
      colours.insert(c.colour);
    EXPECT_EQ(colours.size(), panel.curves.size()) << "every curve of a panel has its own colour";
    layers += panel.curves.size();
  }
  EXPECT_EQ(layers, 47U);
  // Stacking order, not the text order of the file: the third ply panel is plies 17..24.
  EXPECT_EQ(damage.panels[5].curves.front().title, "ply 17");
  EXPECT_EQ(damage.panels[5].curves.back().title, "ply 24");
  EXPECT_EQ(damage.panels[3].curves[1].title, "ply 2");
  // The area of ply 24 (24e-6 m^2 = 24 mm^2) is held to the end of the run (1 ms = 1000 us).
  EXPECT_NE(damage.panels[5].curves.back().data.find("500,24\n1000,24\n"), std::string::npos)
      << damage.panels[5].curves.back().data;
  EXPECT_EQ(picture_size(damage), std::make_pair(1400, 1200));
}

TEST(Plots, TenOrFewerDamagedLayersStayOnePlot) {
  const fs::path dir = results_with_damage("plots-8", 5, 4);
  const auto specs = impact_plots({{dir, "run", dir / "history.csv"}});
  const PlotSpec& damage = find(specs, "damage_area");
  EXPECT_TRUE(damage.panels.empty());
  ASSERT_EQ(damage.curves.size(), 9U);
  EXPECT_EQ(damage.curves.front().title, "choi-chang-delamination interface 1");
  EXPECT_EQ(damage.curves.back().title, "choi-chang-matrix ply 5");
  EXPECT_EQ(picture_size(damage), std::make_pair(plot_width_px, plot_height_px));
}

TEST(Plots, ImpactorEnergyPlotStartsFromTheImpactEnergyOfTheFirstHistoryRow) {
  const fs::path dir = results_with_damage("plots-energy", 1, 0);
  const auto specs = impact_plots({{dir, "run", dir / "history.csv"}});
  const PlotSpec& energy = find(specs, "impactor_energy");
  ASSERT_EQ(energy.curves.size(), 3U);
  EXPECT_NE(energy.curves[0].using_expr.find(":(22.05"), std::string::npos) << energy.curves[0].using_expr;
  EXPECT_NE(energy.curves[2].using_expr.find("(22.05"), std::string::npos) << energy.curves[2].using_expr;
  EXPECT_NE(energy.curves[2].using_expr.find("-column('impactor_energy_J')"), std::string::npos);
}

TEST(Plots, ForceIndentationAndForceDisplacementKeepOnlyTheContactPart) {
  const fs::path dir = results_with_damage("plots-contact", 1, 0);
  const auto specs = impact_plots({{dir, "run", dir / "history.csv"}});
  for (const char* name : {"force_indentation", "force_displacement"}) {
    const PlotSpec& spec = find(specs, name);
    ASSERT_EQ(spec.curves.size(), 1U);
    EXPECT_NE(spec.curves[0].using_expr.find("column('indentation_m') >= 0 ?"), std::string::npos) << name;
  }
}

} // namespace

} // namespace plots_tests
