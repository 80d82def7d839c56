// ParaView output: the .vtu/.pvd files are read back with VTK's own readers and their arrays are
// checked against the solver's displacements and against hand calculations from those nodal values
// (ply stress from the centre curvature, parabolic interface shear in a homogeneous plate).
#include "plyimpact/analysis/fields/element_fields.hpp"
#include "plyimpact/analysis/plate_analyses/static_analysis.hpp"
#include "plyimpact/io/results/vtk_output.hpp"
#include "support/decks.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <filesystem>
#include <string>

namespace plyimpact::vtk_output_tests {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("plyimpact-vtk-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

vtkSmartPointer<vtkUnstructuredGrid> read_vtu(const fs::path& file) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  return reader->GetOutput();
}

/// A simply supported plate under uniform pressure: a smooth bending field with B = 0.
struct PressurePlate {
  double a = 0.2, b = 0.15, q = 2.0e4;
  Laminate lam;
  DiscretePlate model;
  Eigen::VectorXd u;
  PressurePlate(const Material& m, const std::string& layup, double t)
      : lam(test::laminate_of(m, layup, t)),
        model(lam, {a, b}, {4, 3, MassMatrix::lumped, ElementFormulation::q9}, test::all_edges("ss")) {
    StaticLoad load;
    load.pressure = q;
    u = solve_static(model, load).u;
  }
};

TEST(VtkOutput, PlateFileReadBackByVtkHasTheMeshQ9CellsAndTheSolverDisplacements) {
  const PressurePlate p(test::t300_976(), "[0/90]s", 0.25e-3);
  const fs::path file = scratch("plate") / "plate.vtu";
  write_plate_vtu(file, p.model, p.u, {}, 1.5e-5, VtkOptions{});
  const auto grid = read_vtu(file);
  const Mesh& mesh = p.model.mesh();
  ASSERT_EQ(grid->GetNumberOfPoints(), mesh.node_count()); // 9 × 7 = 63 nodes
  ASSERT_EQ(grid->GetNumberOfCells(), mesh.element_count());
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
    ASSERT_EQ(grid->GetCellType(c), VTK_BIQUADRATIC_QUAD);
  // The written connectivity is the mesh's (Q9 local order = VTK's biquadratic quad order).
  for (int e = 0; e < mesh.element_count(); ++e)
    for (int a = 0; a < 9; ++a)
      EXPECT_EQ(grid->GetCell(e)->GetPointId(a), vtkIdType{mesh.element_nodes(e)[std::size_t(a)]});
  const Eigen::VectorXd nodal = p.model.to_nodal(p.u);
  vtkDataArray* w = grid->GetPointData()->GetArray("w_m");
  vtkDataArray* disp = grid->GetPointData()->GetVectors();
  ASSERT_NE(w, nullptr);
  ASSERT_NE(disp, nullptr);
  EXPECT_STREQ(disp->GetName(), "displacement_m");
  double w_max = 0.0;
  for (int n = 0; n < mesh.node_count(); ++n) {
    EXPECT_EQ(w->GetTuple1(n), nodal(5 * n + 2)); // float64 written and read: bit for bit
    EXPECT_EQ(disp->GetComponent(n, 2), nodal(5 * n + 2));
    EXPECT_EQ(disp->GetComponent(n, 0), nodal(5 * n + 0));
    w_max = std::max(w_max, std::abs(nodal(5 * n + 2)));
  }
  EXPECT_GT(w_max, 1e-6); // a real deflection, not an array of zeros
}

TEST(VtkOutput, PlyStressCellDataEqualsTheHandCalculationFromNodalRotations) {
  // [0/90]s in pure bending (B = 0, ε0 = 0): ply 1 (0°) σ̄11 = z̄ (Q11 κx + Q12 κy) with κ at the element
  // centre from the Q9's middle-row nodes, κx = (θx(5) − θx(7))/Δx, κy = (θy(6) − θy(4))/Δy (the
  // quadratic shape functions' derivative at ξ = η = 0); ply 4 (0°, z̄ mirrored) carries −σ̄11.
  const Material m = test::t300_976();
  const double t = 0.25e-3;
  const PressurePlate p(m, "[0/90]s", t);
  const fs::path file = scratch("hand") / "plate.vtu";
  write_plate_vtu(file, p.model, p.u, {}, 0.0, VtkOptions{});
  const auto grid = read_vtu(file);
  vtkDataArray* s1 = grid->GetCellData()->GetArray("ply1_s11_Pa");
  vtkDataArray* s4 = grid->GetCellData()->GetArray("ply4_s11_Pa");
  vtkDataArray* tx = grid->GetPointData()->GetArray("theta_x_rad");
  vtkDataArray* ty = grid->GetPointData()->GetArray("theta_y_rad");
  ASSERT_TRUE(s1 && s4 && tx && ty);
  const double d = 1.0 - m.nu12 * m.nu21(), Q11 = m.E1 / d, Q12 = m.nu12 * m.E2 / d;
  const double z1 = -1.5 * t, dx = p.a / 4, dy = p.b / 3;
  const Mesh& mesh = p.model.mesh();
  double peak = 0.0;
  for (int e = 0; e < mesh.element_count(); ++e) {
    const auto& n = mesh.element_nodes(e);
    const double kx = (tx->GetTuple1(n[5]) - tx->GetTuple1(n[7])) / dx;
    const double ky = (ty->GetTuple1(n[6]) - ty->GetTuple1(n[4])) / dy;
    const double hand = z1 * (Q11 * kx + Q12 * ky);
    EXPECT_NEAR(s1->GetTuple1(e), hand, 1e-9 * std::abs(hand) + 1e-3) << "element " << e;
    EXPECT_NEAR(s4->GetTuple1(e), -hand, 1e-9 * std::abs(hand) + 1e-3) << "element " << e;
    peak = std::max(peak, std::abs(hand));
  }
  EXPECT_GT(peak, 1e6); // MPa-level bending stress under 20 kPa
}

TEST(VtkOutput, InterfaceShearAtTheMidPlaneOfAHomogeneousPlateIsOneAndAHalfTimesTheMean) {
  // Two equal isotropic plies: the equilibrium shear is parabolic, so at the mid-plane interface
  // τxz = 1.5 Qx/h with Qx = K G h γxz and γxz = θx + w,x at the centre (θx(8), (w(5) − w(7))/Δx).
  const double E = 70e9, nu = 0.3, h = 2e-3;
  const Material m = test::isotropic(E, nu, 2700.0);
  const PressurePlate p(m, "[0/0]", h / 2);
  const fs::path file = scratch("shear") / "plate.vtu";
  write_plate_vtu(file, p.model, p.u, {}, 0.0, VtkOptions{});
  const auto grid = read_vtu(file);
  vtkDataArray* txz = grid->GetCellData()->GetArray("interface1_txz_Pa");
  vtkDataArray* w = grid->GetPointData()->GetArray("w_m");
  vtkDataArray* tx = grid->GetPointData()->GetArray("theta_x_rad");
  ASSERT_TRUE(txz && w && tx);
  const double G = E / (2 * (1 + nu)), K = 5.0 / 6.0, dx = p.a / 4;
  const Mesh& mesh = p.model.mesh();
  int checked = 0;
  for (int e = 0; e < mesh.element_count(); ++e) {
    const auto& n = mesh.element_nodes(e);
    const double gamma_xz = tx->GetTuple1(n[8]) + (w->GetTuple1(n[5]) - w->GetTuple1(n[7])) / dx;
    const double hand = 1.5 * K * G * gamma_xz;
    if (std::abs(hand) < 1e3) continue; // on the symmetry line x = a/2 the shear vanishes
    EXPECT_NEAR(txz->GetTuple1(e), hand, 1e-8 * std::abs(hand)) << "element " << e;
    ++checked;
  }
  EXPECT_GE(checked, 6);
}

TEST(VtkOutput, LayeredViewStacksOneHexahedronLayerPerPlyWithThroughThicknessDisplacement) {
  const double t = 0.25e-3, scale = 20.0;
  const PressurePlate p(test::t300_976(), "[0/90]s", t);
  const fs::path file = scratch("layers") / "layers.vtu";
  VtkOptions options;
  options.thickness_scale = scale;
  write_layers_vtu(file, p.model, p.u, {}, 0.0, options);
  const auto grid = read_vtu(file);
  const Mesh& mesh = p.model.mesh();
  const vtkIdType nodes = mesh.node_count();
  ASSERT_EQ(grid->GetNumberOfPoints(), 5 * nodes);                   // 4 plies → 5 surfaces
  ASSERT_EQ(grid->GetNumberOfCells(), 4 * 4 * mesh.element_count()); // 2×2 node cells per Q9, 4 plies
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
    ASSERT_EQ(grid->GetCellType(c), VTK_HEXAHEDRON);
  const Eigen::VectorXd nodal = p.model.to_nodal(p.u);
  vtkDataArray* disp = grid->GetPointData()->GetVectors();
  ASSERT_NE(disp, nullptr);
  for (int s = 0; s <= 4; ++s) {
    const double z = -2 * t + s * t; // surfaces from the impacted face z = −h/2
    for (int n = 0; n < nodes; n += 7) {
      const vtkIdType q = s * nodes + n;
      EXPECT_NEAR(grid->GetPoint(q)[2], scale * z, 1e-15);
      // (1.1): u = u0 + z θx, w = w0
      EXPECT_NEAR(disp->GetComponent(q, 0), nodal(5 * n) + z * nodal(5 * n + 3), 1e-18);
      EXPECT_EQ(disp->GetComponent(q, 2), nodal(5 * n + 2));
    }
  }
  vtkDataArray* ply = grid->GetCellData()->GetArray("ply");
  vtkDataArray* angle = grid->GetCellData()->GetArray("angle_deg");
  ASSERT_TRUE(ply && angle);
  const vtkIdType per_ply = 4 * mesh.element_count();
  EXPECT_EQ(ply->GetTuple1(0), 1);
  EXPECT_EQ(ply->GetTuple1(3 * per_ply), 4);
  EXPECT_EQ(angle->GetTuple1(per_ply), 90); // ply 2 of [0/90]s
}

TEST(VtkOutput, DamageFractionCountsEachFailedGaussPointOnceUpToTheFrameTime) {
  auto onset = [](Criterion c, int ply, int interface, int element, int i, int j, double t) {
    DamageOnset o;
    o.criterion = c;
    o.ply = ply;
    o.interface = interface;
    o.element = element;
    o.ipgs = i;
    o.jpgs = j;
    o.time = t;
    return o;
  };
  const std::vector<DamageOnset> onsets{
      onset(Criterion::choi_chang_matrix, 2, 0, 1, 1, 1, 1e-6),
      onset(Criterion::hashin, 2, 0, 1, 1, 1, 2e-6), // same point, second criterion: counted once
      onset(Criterion::choi_chang_matrix, 2, 0, 1, 3, 2, 3e-6),
      onset(Criterion::choi_chang_delamination, 0, 1, 3, 2, 2, 3e-6),
      onset(Criterion::choi_chang_matrix, 2, 0, 1, 2, 2, 9e-6), // after the frame time
  };
  const DamageFractions d = damage_fractions(onsets, 4, 3, 5e-6);
  EXPECT_DOUBLE_EQ(d.ply[1 * 4 + 0], 2.0 / 9.0);       // ply 2, element 1
  EXPECT_DOUBLE_EQ(d.interface[0 * 4 + 2], 1.0 / 9.0); // interface 1, element 3
  double total = 0.0;
  for (const double f : d.ply)
    total += f;
  EXPECT_DOUBLE_EQ(total, 2.0 / 9.0);
}

TEST(VtkOutput, AWhollyFailedElementIsExactlyOne) {
  // Nine additions of 1/9 give 1.0000000000000002; the fraction is counted, then divided, at most 1.
  std::vector<DamageOnset> onsets;
  for (int i = 1; i <= 3; ++i)
    for (int j = 1; j <= 3; ++j) {
      DamageOnset o;
      o.criterion = Criterion::choi_chang_matrix;
      o.ply = 1;
      o.element = 2;
      o.ipgs = i;
      o.jpgs = j;
      onsets.push_back(o);
    }
  const DamageFractions d = damage_fractions(onsets, 2, 1, 1.0);
  EXPECT_EQ(d.ply[1], 1.0);
  EXPECT_EQ(d.ply[0], 0.0);
}

TEST(VtkOutput, SeriesKeepsAValidPvdListingEveryFrameWithItsTime) {
  const PressurePlate p(test::t300_976(), "[0/90]s", 0.25e-3);
  const fs::path dir = scratch("series");
  VtkSeries series(dir, p.model, VtkOptions{});
  series.write(10, 1.0e-5, p.u, {});
  series.write(20, 2.0e-5, 2.0 * p.u, {});
  for (const char* name : {"plate.pvd", "layers.pvd"}) {
    vtkNew<vtkXMLDataParser> parser;
    parser->SetFileName((dir / name).string().c_str());
    ASSERT_EQ(parser->Parse(), 1) << name;
    vtkXMLDataElement* root = parser->GetRootElement();
    ASSERT_STREQ(root->GetName(), "VTKFile");
    EXPECT_STREQ(root->GetAttribute("type"), "Collection");
    vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
    ASSERT_NE(collection, nullptr);
    ASSERT_EQ(collection->GetNumberOfNestedElements(), 2);
    for (int i = 0; i < 2; ++i) {
      vtkXMLDataElement* ds = collection->GetNestedElement(i);
      double t = 0.0;
      ASSERT_TRUE(ds->GetScalarAttribute("timestep", t));
      EXPECT_DOUBLE_EQ(t, (i + 1) * 1.0e-5);
      const auto grid = read_vtu(dir / ds->GetAttribute("file"));
      EXPECT_GT(grid->GetNumberOfPoints(), 0);
    }
  }
  // The second frame holds the second state: w doubled.
  const auto second = read_vtu(dir / "paraview" / "plate_0000020.vtu");
  const Eigen::VectorXd nodal = p.model.to_nodal(p.u);
  const int centre = 3 * 9 + 4; // grid node (4, 3) of the 4 × 3 structured mesh: 9 nodes a row
  EXPECT_EQ(second->GetPointData()->GetArray("w_m")->GetTuple1(centre), 2.0 * nodal(5 * centre + 2));
}

/// Damage of three element-ply pairs of the 4 × 3 plate (0-based element and ply), as the run lists
/// them; every other element and ply is undamaged.
std::vector<ElementPlyDamage> three_damaged() {
  return {{2, 3, {{0.1, 0.2, 0.7, 0.0}}}, {5, 0, {{0.9, 0.0, 0.0, 0.3}}}, {2, 1, {{0.0, 0.4, 0.0, 0.0}}}};
}

TEST(VtkOutput, ProgressiveDamageCellDataReadBackEqualsTheListedDamageAndZeroElsewhere) {
  const PressurePlate p(test::t300_976(), "[0/90]s", 0.25e-3);
  const fs::path dir = scratch("progressive");
  const PlyDamageTable table(p.model, three_damaged());
  write_plate_vtu(dir / "plate.vtu", p.model, p.u, {}, 0.0, VtkOptions{}, &table);
  const auto grid = read_vtu(dir / "plate.vtu");
  vtkCellData& cells = *grid->GetCellData();
  // Expected values by hand from three_damaged(): (ply 1-based, mode name, element) → d.
  auto expected = [](int ply, const std::string& mode, int e) {
    if (ply == 4 && e == 2) return mode == "d_ft" ? 0.1 : mode == "d_fc" ? 0.2 : mode == "d_mt" ? 0.7 : 0.0;
    if (ply == 1 && e == 5) return mode == "d_ft" ? 0.9 : mode == "d_mc" ? 0.3 : 0.0;
    if (ply == 2 && e == 2) return mode == "d_fc" ? 0.4 : 0.0;
    return 0.0;
  };
  for (int ply = 1; ply <= 4; ++ply)
    for (const std::string mode : {"d_ft", "d_fc", "d_mt", "d_mc"}) {
      vtkDataArray* a = cells.GetArray(fmt::format("ply{}_{}", ply, mode).c_str());
      ASSERT_NE(a, nullptr) << ply << mode;
      for (int e = 0; e < 12; ++e)
        EXPECT_EQ(a->GetTuple1(e), expected(ply, mode, e))
            << "ply " << ply << " " << mode << " element " << e;
    }
  // Ply 3 has no damage: every value of its largest-variable array is zero.
  vtkDataArray* ply3 = cells.GetArray("ply3_d_max");
  ASSERT_NE(ply3, nullptr);
  for (int e = 0; e < 12; ++e)
    EXPECT_EQ(ply3->GetTuple1(e), 0.0);
  EXPECT_EQ(cells.GetArray("ply4_d_max")->GetTuple1(2), 0.7);
  // damage_max: the largest over plies and modes (element 2: 0.7 of ply 4 over 0.4 of ply 2; element 5: 0.9).
  vtkDataArray* projected = cells.GetArray("damage_max");
  ASSERT_NE(projected, nullptr);
  for (int e = 0; e < 12; ++e)
    EXPECT_EQ(projected->GetTuple1(e), e == 2 ? 0.7 : e == 5 ? 0.9 : 0.0) << "element " << e;

  // The layered view: cells ply by ply, element by element, four hexahedra per element.
  write_layers_vtu(dir / "layers.vtu", p.model, p.u, {}, 0.0, VtkOptions{}, &table);
  const auto layers = read_vtu(dir / "layers.vtu");
  vtkDataArray* d_mt = layers->GetCellData()->GetArray("d_mt");
  vtkDataArray* d_max = layers->GetCellData()->GetArray("d_max");
  ASSERT_TRUE(d_mt && d_max);
  for (int k = 0; k < 4; ++k)
    for (int e = 0; e < 12; ++e)
      for (int q = 0; q < 4; ++q) {
        const vtkIdType cell = (k * 12 + e) * 4 + q;
        EXPECT_EQ(d_mt->GetTuple1(cell), expected(k + 1, "d_mt", e));
        EXPECT_EQ(d_max->GetTuple1(cell), table.largest(k, e));
      }
  EXPECT_EQ(d_max->GetTuple1((0 * 12 + 5) * 4), 0.9); // ply 1, element 5
}

TEST(VtkOutput, OnsetFramesHaveNoProgressiveDamageArrays) {
  const PressurePlate p(test::t300_976(), "[0/90]s", 0.25e-3);
  const fs::path dir = scratch("onset");
  write_plate_vtu(dir / "plate.vtu", p.model, p.u, {}, 0.0, VtkOptions{});
  write_layers_vtu(dir / "layers.vtu", p.model, p.u, {}, 0.0, VtkOptions{});
  for (const char* file : {"plate.vtu", "layers.vtu"}) {
    const auto grid = read_vtu(dir / file);
    vtkCellData& cells = *grid->GetCellData();
    ASSERT_GT(cells.GetNumberOfArrays(), 0);
    for (int i = 0; i < cells.GetNumberOfArrays(); ++i) {
      const std::string name = cells.GetArrayName(i);
      for (const std::string suffix : {"d_ft", "d_fc", "d_mt", "d_mc", "d_max"}) // the name or a plyN_ prefix
        EXPECT_FALSE(name == suffix || name.ends_with("_" + suffix)) << file << ": " << name;
      EXPECT_NE(name, "damage_max") << file;
    }
  }
}

TEST(VtkOutput, ADamageEntryOutsideTheModelIsRefused) {
  EXPECT_THROW(PlyDamageTable(12, 4, {{12, 0, {}}}), std::invalid_argument);
  EXPECT_THROW(PlyDamageTable(12, 4, {{0, 4, {}}}), std::invalid_argument);
}

} // namespace
} // namespace plyimpact::vtk_output_tests
