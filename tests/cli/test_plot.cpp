// Pictures and reports from an impact run: `plyimpact plot` makes non-blank PNGs of the stated size and
// SVGs that parse as XML; ParaView frames are listed in plate.pvd; report.txt echoes the run.
#include "plyimpact/io/results/plots.hpp"

#include "support/cli.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPointData.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include <cmath>
#include <sstream>

namespace plot_tests {

namespace {

using namespace plyimpact::test;

/// A short impact on the 6 × 4 Annex 2 plate with Choi–Chang damage, ParaView frames and a report.
std::string impact_deck(double velocity) {
  std::string deck = small_deck("impact", R"(
[impactor]
mass = 0.00844
radius = 6.35e-3
E = 207e9
velocity = )" + std::to_string(velocity) + R"(
[time]
dt = 0.5e-6
end = 40e-6
[damage]
criteria = ["choi-chang-matrix", "choi-chang-delamination"]
[output]
vtk_every = 20
report_displacements_at = 20e-6
)");
  const std::string rho = "rho = 1389.2\n"; // T300/976 strengths (Table 4.2) for the criteria
  deck.insert(deck.find(rho) + rho.size(),
              "Yt = 55.2e6\nYc = 294.0e6\nS12 = 101.1e6\nS23 = 32.94e6\nDa = 1.8\n");
  return deck;
}

struct Picture {
  int width = 0, height = 0;
  double variance = 0.0; ///< of all pixel channel values
};

Picture read_png(const fs::path& file) {
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  Picture p;
  int dims[3];
  image->GetDimensions(dims);
  p.width = dims[0];
  p.height = dims[1];
  vtkDataArray* pixels = image->GetPointData()->GetScalars();
  if (pixels == nullptr) return p;
  double sum = 0.0, sum2 = 0.0;
  const vtkIdType n = pixels->GetNumberOfTuples() * pixels->GetNumberOfComponents();
  for (vtkIdType i = 0; i < pixels->GetNumberOfTuples(); ++i)
    for (int c = 0; c < pixels->GetNumberOfComponents(); ++c) {
      const double v = pixels->GetComponent(i, c);
      sum += v;
      sum2 += v * v;
    }
  p.variance = sum2 / double(n) - (sum / double(n)) * (sum / double(n));
  return p;
}

bool svg_parses(const fs::path& file) {
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(file.string().c_str());
  return parser->Parse() == 1 && std::string(parser->GetRootElement()->GetName()) == "svg";
}

TEST(CliPlot, EveryPlotIsANonBlankPngOfTheStatedSizeAndAParsableSvg) {
  const fs::path dir = scratch("plot");
  // 20 m/s: the Hertz pressure (the default load) fails plies on this coarse mesh, so damage_area has rows.
  const CommandResult r =
      run("impact " + write(dir, impact_deck(20.0)).string() + " -o " + (dir / "out").string());
  ASSERT_EQ(r.status, 0) << r.out;
  const CommandResult p = run("plot " + (dir / "out").string());
  ASSERT_EQ(p.status, 0) << p.out;
  const auto specs = plyimpact::impact_plots({{dir / "out", "run", dir / "out" / "history.csv"}});
  ASSERT_EQ(specs.size(), 8U);
  for (const plyimpact::PlotSpec& spec : specs) {
    const std::string& name = spec.name;
    const fs::path png = dir / "out" / "plots" / (std::string(name) + ".png");
    ASSERT_TRUE(fs::exists(png)) << name;
    const Picture pic = read_png(png);
    const auto [width, height] = plyimpact::picture_size(spec);
    EXPECT_EQ(pic.width, width) << name;
    EXPECT_EQ(pic.height, height) << name;
    EXPECT_GT(pic.variance, 100.0) << name; // a white page has variance 0
    EXPECT_TRUE(svg_parses(dir / "out" / "plots" / (std::string(name) + ".svg"))) << name;
    EXPECT_TRUE(fs::exists(dir / "out" / "plots" / (std::string(name) + ".gp"))) << name;
  }
  // No temporary file is left behind.
  for (const auto& entry : fs::directory_iterator(dir / "out" / "plots"))
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
}

TEST(CliPlot, SeveralResultsFoldersAreOverlaidWithOneLabelledCurveEach) {
  const fs::path dir = scratch("overlay");
  std::string dirs;
  for (const double v : {4.0, 8.0, 12.0}) {
    const fs::path sub = dir / fmt::format("v{}", v);
    fs::create_directories(sub);
    ASSERT_EQ(run("impact " + write(sub, impact_deck(v)).string() + " -o " + (sub / "out").string()).status,
              0);
    dirs.append(" ").append((sub / "out").string());
  }
  const CommandResult p = run(fmt::format("plot{} -o {}", dirs, (dir / "overlay").string()));
  ASSERT_EQ(p.status, 0) << p.out;
  const std::string script = read_text(dir / "overlay" / "force_time.gp");
  for (const char* label : {"v0 = 4 m/s", "v0 = 8 m/s", "v0 = 12 m/s"})
    EXPECT_NE(script.find(label), std::string::npos) << label;
  EXPECT_GT(read_png(dir / "overlay" / "force_time.png").variance, 100.0);
}

TEST(CliPlot, AProgressiveRunGetsADamageMapPerPlyAndTheProjectedMapBesideTheForcePlots) {
  // examples/damage-progressive.toml: [0/90]s, 4 plies; the maps are drawn from damage_elements.csv.
  const fs::path dir = scratch("plot-progressive");
  const std::string deck = std::string(PLYIMPACT_SOURCE_DIR) + "/examples/damage-progressive.toml";
  const CommandResult r = run("impact " + deck + " -o " + (dir / "out").string());
  ASSERT_EQ(r.status, 0) << r.out;
  ASSERT_TRUE(fs::exists(dir / "out" / "damage_elements.csv"));
  const CommandResult p = run("plot " + (dir / "out").string());
  ASSERT_EQ(p.status, 0) << p.out;
  const auto specs = plyimpact::impact_plots({{dir / "out", "run", dir / "out" / "history.csv"}});
  std::vector<std::string> maps;
  for (const plyimpact::PlotSpec& spec : specs)
    if (spec.name.starts_with("damage_map_")) maps.push_back(spec.name);
  EXPECT_EQ(maps, (std::vector<std::string>{"damage_map_ply01", "damage_map_ply02", "damage_map_ply03",
                                            "damage_map_ply04", "damage_map_projected"}));
  for (const std::string name :
       {"damage_map_ply01", "damage_map_ply04", "damage_map_projected", "force_time", "force_displacement"}) {
    const fs::path png = dir / "out" / "plots" / (name + ".png");
    ASSERT_TRUE(fs::exists(png)) << name;
    const Picture pic = read_png(png);
    EXPECT_EQ(pic.width, plyimpact::plot_width_px) << name;
    EXPECT_EQ(pic.height, plyimpact::plot_height_px) << name;
    EXPECT_GT(pic.variance, 100.0) << name;
    EXPECT_TRUE(svg_parses(dir / "out" / "plots" / (name + ".svg"))) << name;
  }
  // The impact point of the folder's deck.toml (plate centre, 6 mm, 6 mm) is marked on the maps.
  EXPECT_NE(read_text(dir / "out" / "plots" / "damage_map_projected.gp").find("impact point"),
            std::string::npos);
  EXPECT_NE(read_text(dir / "out" / "plots" / "damage_map_projected.gp").find("6.000000,6.000000"),
            std::string::npos);
}

TEST(CliPlot, PlotOfAFolderWithoutHistoryIsAClearError) {
  const fs::path dir = scratch("plot-bad");
  const CommandResult p = run("plot " + dir.string());
  EXPECT_EQ(p.status, 2); // a results folder given to plot is input: a bad one is exit 2, as a bad deck
  EXPECT_NE(p.out.find("not an impact results folder"), std::string::npos) << p.out;
}

TEST(CliOutput, ImpactWritesParaViewFramesAndAnAnnexTwoStyleReport) {
  const fs::path dir = scratch("vtk-report");
  const CommandResult r =
      run("impact " + write(dir, impact_deck(12.0)).string() + " -o " + (dir / "out").string());
  ASSERT_EQ(r.status, 0) << r.out;
  const auto summary = read_json(dir / "out" / "summary.json");
  const long steps = summary["steps"].get<long>();
  // A frame every 20 steps: 80 steps of 0.5 µs to 40 µs → frames at steps 20, 40, 60, 80, and the
  // undeformed plate at t = 0 (the last step, 80, is already a frame).
  ASSERT_EQ(steps % 20, 0);
  EXPECT_EQ(summary["vtk_frames"].get<long>(), steps / 20 + 1);
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName((dir / "out" / "plate.pvd").string().c_str());
  ASSERT_EQ(parser->Parse(), 1);
  vtkXMLDataElement* collection = parser->GetRootElement()->FindNestedElementWithName("Collection");
  ASSERT_NE(collection, nullptr);
  ASSERT_EQ(collection->GetNumberOfNestedElements(), steps / 20 + 1);
  EXPECT_STREQ(collection->GetNestedElement(0)->GetAttribute("timestep"), "0");
  EXPECT_TRUE(fs::exists(dir / "out" / "layers.pvd"));

  const std::string report = read_text(dir / "out" / "report.txt");
  for (const char* section :
       {"MATERIALS AND LAMINATE", "PLATE AND MESH", "IMPACTOR AND CONTACT", "TIME STEPPING", "RESULTS",
        "FIRST FAILURES", "DISPLACEMENTS AT t = 20.0000 us"})
    EXPECT_NE(report.find(section), std::string::npos) << section;
  char peak[64];
  std::snprintf(peak, sizeof peak, "%.2f N", summary["peak_force"].get<double>());
  EXPECT_NE(report.find(peak), std::string::npos) << peak;
  // One displacement row per node of the 6 × 4 Q9 mesh: 13 × 9 = 117.
  const std::string table = report.substr(report.find("DISPLACEMENTS AT"));
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 3 + 117);
}

TEST(CliOutput, ParaViewFramesIncludeTheFirstAndTheLastStepWhateverTheInterval) {
  const fs::path dir = scratch("vtk-ends");
  std::string deck = impact_deck(12.0);
  deck.replace(deck.find("vtk_every = 20"), 14, "vtk_every = 30"); // 80 steps: 30, 60 and not 80
  const CommandResult r = run("impact " + write(dir, deck).string() + " -o " + (dir / "out").string());
  ASSERT_EQ(r.status, 0) << r.out;
  const std::string pvd = read_text(dir / "out" / "plate.pvd");
  for (const char* frame :
       {"plate_0000000.vtu", "plate_0000030.vtu", "plate_0000060.vtu", "plate_0000080.vtu"})
    EXPECT_NE(pvd.find(frame), std::string::npos) << frame;
  EXPECT_EQ(read_json(dir / "out" / "summary.json")["vtk_frames"].get<long>(), 4);
}

TEST(CliOutput, StaticAndModalWriteParaViewFilesWithVtkTrue) {
  const fs::path dir = scratch("vtk-static-modal");
  const std::string source(PLYIMPACT_SOURCE_DIR);
  for (const char* name : {"static-annex2-loads", "modal-annex2"}) {
    std::string deck = read_text(source + "/examples/" + name + ".toml");
    deck += "\n[output]\nvtk = true\n";
    const fs::path sub = dir / name;
    fs::create_directories(sub);
    const std::string command = std::string(name).starts_with("static") ? "static " : "modal ";
    const CommandResult r = run(command + write(sub, deck).string() + " -o " + (sub / "out").string());
    ASSERT_EQ(r.status, 0) << r.out;
    vtkNew<vtkXMLDataParser> parser;
    parser->SetFileName((sub / "out" / "plate.pvd").string().c_str());
    ASSERT_EQ(parser->Parse(), 1) << name;
    const int frames =
        parser->GetRootElement()->FindNestedElementWithName("Collection")->GetNumberOfNestedElements();
    if (std::string(name).starts_with("static")) {
      EXPECT_EQ(frames, 1);
    } else {
      // One frame per mode, its "time" the mode number.
      EXPECT_EQ(frames, static_cast<int>(read_json(sub / "out" / "summary.json")["frequencies_hz"].size()));
    }
    EXPECT_TRUE(fs::exists(sub / "out" / "layers.pvd")) << name;
  }
}

} // namespace

} // namespace plot_tests
