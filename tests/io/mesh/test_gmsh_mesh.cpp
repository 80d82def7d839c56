// Plate meshes from gmsh files ([mesh] file, io/mesh/gmsh_mesh.hpp): meshes made with the gmsh library as a
// user makes them, then static and modal analyses against closed forms — the clamped circular plate
// under uniform pressure (Mindlin: Kirchhoff plus the shear term) and under a central point load, its
// fundamental frequency (λ² = 10.2158), the annular plate simply supported outside and free inside
// (Kirchhoff's axisymmetric solution) —, the thesis rectangle meshed by gmsh against the structured
// factory (static and the thesis impact), the §3.6 impact on an unstructured mesh refined at the impact
// point against the graded structured mesh, and every kind of mesh file that must be refused with a
// message that says why.
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/io/mesh/gmsh_mesh.hpp"
#include "plyimpact/io/run/plate_analyses.hpp"
#include "support/decks.hpp"
#include "support/gmsh_meshes.hpp"
#include "support/navier.hpp"
#include "support/navier_plies.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

namespace plyimpact::gmsh_mesh_tests {
namespace {

namespace fs = std::filesystem;
using test::GmshMeshOptions;

constexpr double E = 70e9, nu = 0.3, rho = 2700.0, kappa = 5.0 / 6.0;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("plyimpact-gmsh-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// An isotropic plate ([0] of one ply of thickness h) on the mesh file, with `rest` appended.
Deck isotropic_deck(const std::string& analysis, const fs::path& mesh, double h, const std::string& rest) {
  const double G = E / (2.0 * (1.0 + nu));
  return parse_deck(fmt::format(R"(analysis = "{}"
[materials.alu]
E1 = {}
E2 = {}
G12 = {}
G13 = {}
G23 = {}
nu12 = {}
rho = {}
[laminate]
material = "alu"
layup = "[0]"
ply_thickness = {}
[mesh]
file = "{}"
)",
                                analysis, E, E, G, G, G, nu, rho, h, mesh.string()) +
                        rest,
                    "deck.toml");
}

double bending_stiffness(double h) {
  return E * h * h * h / (12.0 * (1.0 - nu * nu));
}

double static_value(const Deck& deck, const char* key) {
  return run_static_analysis(deck, false, std::nullopt).summary.at(key).get<double>();
}

TEST(GmshMesh, ReadsQuad9ElementsAndNamedSets) {
  const fs::path file = scratch("read") / "disk.msh";
  test::write_disk_mesh(file, 0.1, 0.02);
  const Mesh mesh = read_gmsh_mesh(file);
  EXPECT_GT(mesh.element_count(), 20);
  EXPECT_TRUE(mesh.has_edge_set("rim"));
  EXPECT_TRUE(mesh.has_node_set("centre"));
  ASSERT_EQ(mesh.node_set("centre").size(), 1U);
  EXPECT_LT(mesh.node(mesh.node_set("centre").front()).norm(), 1e-12);
  // Every rim node lies on the circle (gmsh puts the mid-side nodes on the arc), and the elements tile
  // the disk: their areas add up to π R² within the chordal error of the arcs.
  for (const int n : mesh.node_set("rim"))
    EXPECT_NEAR(mesh.node(n).norm(), 0.1, 1e-12);
  double area = 0.0;
  for (int e = 0; e < mesh.element_count(); ++e)
    area += mesh.element_area(e);
  EXPECT_NEAR(area / (M_PI * 0.01), 1.0, 1e-4);
}

TEST(GmshMesh, ClampedCircularPlateUnderPressureHasMindlinsCentreDeflection) {
  // w0 = q a⁴/(64 D) + q a²/(4 κ G h) (Kirchhoff plus the shear term of the Mindlin plate; Reddy,
  // Theory and Analysis of Elastic Plates, §12.2). At h/a = 0.1 the shear term is 4.6 % of the whole.
  const double a = 0.1, h = 0.01, q = 1e5, G = E / (2.0 * (1.0 + nu));
  const fs::path file = scratch("clamped-pressure") / "disk.msh";
  test::write_disk_mesh(file, a, a / 6.0);
  const Deck deck =
      isotropic_deck("static", file, h, "[boundary]\nrim = \"clamped\"\n[load]\npressure = 1e5\n");
  const double bending = q * std::pow(a, 4) / (64.0 * bending_stiffness(h)),
               shear = q * a * a / (4.0 * kappa * G * h);
  const double w = static_value(deck, "center_deflection");
  std::printf("  w0 = %.6e m, Mindlin %.6e m (Kirchhoff alone %.6e m)\n", w, bending + shear, bending);
  EXPECT_NEAR(std::abs(w) / (bending + shear), 1.0, 0.01);
  EXPECT_GT(std::abs(w) / bending, 1.03) << "the shear term is there";
}

TEST(GmshMesh, ClampedOrthotropicCircularPlateUnderPressureHasLekhnitskiisCentreDeflection) {
  // A plate with rectilinear orthotropy (D16 = D26 = 0) clamped on an ellipse deflects exactly as
  // w = w0 (1 − x²/a² − y²/b²)² under uniform q (Lekhnitskii, Anisotropic Plates, 1968: the clamped
  // elliptical plate; Kirchhoff); on a circle w0 = q a⁴ / (8 (3 D11 + 2 (D12 + 2 D66) + 3 D22)) (64 D when
  // isotropic). T300/976 [0/90]s, h/a = 0.005 so that the transverse shear adds little; D from the
  // plies' textbook formulas (tests/support/navier_plies.hpp), not from src/.
  const double a = 0.1, t = 0.125e-3, q = 100.0;
  const fs::path file = scratch("clamped-orthotropic") / "disk.msh";
  test::write_disk_mesh(file, a, a / 8.0);
  const Material m = test::t300_976();
  const Eigen::Matrix3d D =
      test::navier::plate_from_plies(1.0, 1.0, test::navier_cross_ply(m, {0, 90, 90, 0}, t)).D;
  const Deck deck =
      parse_deck(fmt::format(R"(analysis = "static"
[materials.T300_976]
E1 = {}
E2 = {}
G12 = {}
G13 = {}
G23 = {}
nu12 = {}
rho = {}
[laminate]
material = "T300_976"
layup = "[0/90]s"
ply_thickness = {}
[mesh]
file = "{}"
[boundary]
rim = "clamped"
[load]
pressure = {}
)",
                             m.E1, m.E2, m.G12, m.G13, m.G23, m.nu12, m.rho, t, file.string(), q),
                 "deck.toml");
  const double expected =
      q * std::pow(a, 4) / (8.0 * (3.0 * D(0, 0) + 2.0 * (D(0, 1) + 2.0 * D(2, 2)) + 3.0 * D(1, 1)));
  const double w = static_value(deck, "center_deflection");
  std::printf("  orthotropic w0 = %.6e m, Lekhnitskii %.6e m\n", w, expected);
  EXPECT_NEAR(w / expected, 1.0, 0.01);
}

TEST(GmshMesh, ClampedCircularPlateUnderCentralLoadHasTheClosedFormDeflection) {
  // w0 = P a²/(16 π D) (Timoshenko & Woinowsky-Krieger §19). The Mindlin shear part of a point load is
  // singular at the load; at h/a = 0.01 it adds (4/(3(1 − ν)κ)) (h/a)² ln(a/r) ≈ 0.1 % for element-sized r.
  const double a = 0.1, h = 0.001, P = 10.0;
  const fs::path file = scratch("clamped-point") / "disk.msh";
  test::write_disk_mesh(file, a, a / 6.0);
  const Deck deck = isotropic_deck(
      "static", file, h, "[boundary]\nrim = \"clamped\"\n[load.point]\nx = 0.0\ny = 0.0\nforce = 10.0\n");
  const double expected = P * a * a / (16.0 * M_PI * bending_stiffness(h));
  const double w = static_value(deck, "load_point_deflection");
  std::printf("  w0 = %.6e m, closed form %.6e m\n", w, expected);
  EXPECT_NEAR(std::abs(w) / expected, 1.0, 0.01);
}

TEST(GmshMesh, ClampedCircularPlateHasTheFundamentalFrequencyOfTheThinPlate) {
  // f1 = λ²/(2π a²) √(D/(ρ h)) with λ² = 10.2158 (Leissa, Vibration of Plates, NASA SP-160, Table 2.1).
  const double a = 0.1, h = 0.001;
  const fs::path file = scratch("clamped-modal") / "disk.msh";
  test::write_disk_mesh(file, a, a / 6.0);
  const Deck deck = isotropic_deck("modal", file, h, "[boundary]\nrim = \"clamped\"\n[modal]\ncount = 1\n");
  const double expected = 10.2158 / (2.0 * M_PI * a * a) * std::sqrt(bending_stiffness(h) / (rho * h));
  const double f = run_modal_analysis(deck, std::nullopt).summary.at("frequencies_hz").at(0).get<double>();
  std::printf("  f1 = %.4f Hz, closed form %.4f Hz\n", f, expected);
  EXPECT_NEAR(f / expected, 1.0, 0.01);
}

/// Kirchhoff's annular plate of radii b < a under uniform q, simply supported at r = a and free at
/// r = b: w = q r⁴/(64 D) + C1 + C2 r² + C3 ln r + C4 r² ln r, with C4 = −q b²/(8 D) from Q_r(b) = 0 and
/// w(a) = 0, M_r(a) = 0, M_r(b) = 0 (M_r ∝ w'' + ν w'/r) for the others. Returns w(b) − w(a).
double annulus_inner_edge_deflection(double a, double b, double q, double D) {
  const double C4 = -q * b * b / (8.0 * D); // Q_r ∝ (∇²w)' = q r/(2D) + 4 C4/r vanishes at r = b
  const auto slope = [&](double r) { return q * r * r * r / (16.0 * D) + C4 * (2.0 * r * std::log(r) + r); };
  const auto curvature = [&](double r) {
    return 3.0 * q * r * r / (16.0 * D) + C4 * (2.0 * std::log(r) + 3.0);
  };
  // Unknowns (C1, C2, C3): the slope and curvature parts of C2 r², C3 ln r are 2 C2 r, C3/r and 2 C2, −C3/r².
  Eigen::Matrix3d A;
  Eigen::Vector3d rhs;
  A << 1.0, a * a, std::log(a), 0.0, 2.0 + 2.0 * nu, (nu - 1.0) / (a * a), 0.0, 2.0 + 2.0 * nu,
      (nu - 1.0) / (b * b);
  rhs << -(q * std::pow(a, 4) / (64.0 * D) + C4 * a * a * std::log(a)), -(curvature(a) + nu * slope(a) / a),
      -(curvature(b) + nu * slope(b) / b);
  const Eigen::Vector3d C = A.fullPivLu().solve(rhs);
  const auto w = [&](double r) {
    return q * std::pow(r, 4) / (64.0 * D) + C(0) + C(1) * r * r + C(2) * std::log(r) +
           C4 * r * r * std::log(r);
  };
  return w(b) - w(a);
}

TEST(GmshMesh, AnnularPlateSimplySupportedOutsideMatchesKirchhoffsSolution) {
  // Outer edge: w = 0 with the in-plane displacements held ("11100"; hard ss would fix the tangential
  // rotation, which is not a nodal DOF on a curved edge; u, v do not bend a one-ply plate), inner edge
  // free, h/a = 0.01: the largest deflection, at the hole, against the axisymmetric closed form.
  const double a = 0.1, b = 0.03, h = 0.001, q = 100.0;
  const fs::path file = scratch("annulus") / "annulus.msh";
  test::write_annulus_mesh(file, a, b, 0.01);
  const Deck deck =
      isotropic_deck("static", file, h, "[boundary]\nouter = \"11100\"\n[load]\npressure = 100.0\n");
  const double expected = std::abs(annulus_inner_edge_deflection(a, b, q, bending_stiffness(h)));
  double area = 0.0;
  for (int e = 0; e < deck.file_mesh->element_count(); ++e)
    area += deck.file_mesh->element_area(e);
  EXPECT_NEAR(area / (M_PI * (a * a - b * b)), 1.0, 1e-3) << "the hole is there";
  const nlohmann::json s = run_static_analysis(deck, false, std::nullopt).summary;
  std::printf("  w(b) = %.6e m, Kirchhoff %.6e m\n", s.at("max_abs_deflection").get<double>(), expected);
  EXPECT_NEAR(s.at("max_abs_deflection").get<double>() / expected, 1.0, 0.01);
  EXPECT_TRUE(s.at("center_deflection").is_null()) << "the centre is in the hole";
}

/// The thesis §3.6 material and laminate (Table 3.1; examples/thesis-3.6-v268.toml).
const std::string thesis_3_6_laminate = R"([materials.thesis_3_6]
E1 = 129.0e9
E2 = 7.5e9
G12 = 3.5e9
G13 = 3.5e9
G23 = 3.5e9
nu12 = 0.33
rho = 1540.0
[laminate]
material = "thesis_3_6"
layup = "[45/90/-45/0]3s"
ply_thickness = 0.19375e-3
)";

TEST(GmshMesh, TheThesisPlateMeshedByGmshGivesTheStructuredMeshsAnswer) {
  // §3.6 plate, 15 × 11 elements by transfinite lines, Annex 2's restraint codes on the named edges:
  // the same static deflections as the structured factory, up to the order of the operations.
  const fs::path dir = scratch("thesis");
  test::write_rectangle_mesh(dir / "thesis.msh", 0.127, 0.0762, 15, 11);
  // The same sets on both meshes: the structured factory's edges and corners, gmsh's physical groups.
  const std::string plate = "analysis = \"static\"\n" + thesis_3_6_laminate + R"([load]
pressure = 1e5
[boundary]
x0 = "10101"
xa = "10101"
y0 = "10101"
yb = "10101"
corners = "11111"
)";
  const Deck structured =
      parse_deck(plate + "[plate]\na = 0.127\nb = 0.0762\n[mesh]\nnx = 15\nny = 11\n", "structured.toml");
  const Deck meshed =
      parse_deck(plate + fmt::format("[mesh]\nfile = \"{}\"\n", (dir / "thesis.msh").string()), "gmsh.toml");
  const nlohmann::json a = run_static_analysis(structured, false, std::nullopt).summary;
  const nlohmann::json b = run_static_analysis(meshed, false, std::nullopt).summary;
  for (const char* key : {"center_deflection", "max_abs_deflection"}) {
    std::printf("  %s: structured %.17g m, gmsh %.17g m\n", key, a.at(key).get<double>(),
                b.at(key).get<double>());
    EXPECT_NEAR(b.at(key).get<double>() / a.at(key).get<double>(), 1.0, 1e-10) << key;
  }
  EXPECT_EQ(a.at("dofs"), b.at("dofs"));
}

/// The message of the DeckError that parsing `deck` throws ("(no error)" when it parses).
std::string deck_error(const std::function<Deck()>& deck) {
  try {
    (void)deck();
  } catch (const DeckError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string mesh_error(const GmshMeshOptions& o, const std::string& name) {
  const fs::path file = scratch(name) / "disk.msh";
  test::write_disk_mesh(file, 0.1, 0.03, o);
  return deck_error([&] { return isotropic_deck("static", file, 0.001, "[boundary]\nrim = \"clamped\"\n"); });
}

TEST(GmshMesh, OtherElementTypesAreRefusedWithTheGmshOptionsThatMakeQuad9) {
  GmshMeshOptions linear;
  linear.order = 1;
  const std::string quad4 = mesh_error(linear, "quad4");
  EXPECT_NE(quad4.find("deck.toml:15:"), std::string::npos) << quad4;
  EXPECT_NE(quad4.find("4-node quadrilaterals (gmsh type 3)"), std::string::npos) << quad4;
  EXPECT_NE(quad4.find("Mesh.SecondOrderIncomplete = 0"), std::string::npos) << quad4;
  GmshMeshOptions triangles;
  triangles.recombine = false;
  EXPECT_NE(mesh_error(triangles, "tri6").find("6-node triangles (gmsh type 9)"), std::string::npos);
  GmshMeshOptions incomplete;
  incomplete.incomplete = true;
  EXPECT_NE(mesh_error(incomplete, "quad8").find("8-node quadrilaterals (gmsh type 16)"), std::string::npos);
}

TEST(GmshMesh, BadMeshesAreRefusedWithWhatIsWrong) {
  GmshMeshOptions unnamed;
  unnamed.physical_groups = false;
  EXPECT_NE(mesh_error(unnamed, "unnamed").find("the mesh has no physical groups"), std::string::npos);
  GmshMeshOptions lifted;
  lifted.z = 0.01;
  EXPECT_NE(mesh_error(lifted, "lifted").find("off the plate's mid-plane z = 0"), std::string::npos);
  GmshMeshOptions clockwise;
  clockwise.clockwise = true;
  const std::string inverted = mesh_error(clockwise, "inverted");
  EXPECT_NE(inverted.find("is inverted (its nodes run clockwise"), std::string::npos) << inverted;
  GmshMeshOptions nan_node;
  nan_node.not_a_number = true; // before: "element is inverted or degenerate", naming no node
  const std::string not_finite = mesh_error(nan_node, "nan");
  EXPECT_NE(not_finite.find("has the coordinates (nan, "), std::string::npos) << not_finite;
  EXPECT_NE(not_finite.find("every node of a mesh needs finite coordinates"), std::string::npos)
      << not_finite;
  GmshMeshOptions folded;
  folded.degenerate = true;
  const std::string degenerate = mesh_error(folded, "degenerate");
  EXPECT_NE(degenerate.find("is degenerate or folded (its Jacobian changes sign or vanishes)"),
            std::string::npos)
      << degenerate;
  // A set the mesh does not have, with the groups it has.
  const fs::path file = scratch("no-set") / "disk.msh";
  test::write_disk_mesh(file, 0.1, 0.03);
  const std::string no_set =
      deck_error([&] { return isotropic_deck("static", file, 0.001, "[boundary]\nrimm = \"clamped\"\n"); });
  EXPECT_NE(no_set.find("deck.toml:17:"), std::string::npos) << no_set;
  EXPECT_NE(
      no_set.find(
          "the mesh has no physical group \"rimm\" (did you mean \"rim\"?) (its groups: centre, plate, rim)"),
      std::string::npos)
      << no_set;
  // Hard simple support on a curved edge would need rotated DOFs.
  EXPECT_NE(deck_error([&] {
              return isotropic_deck("static", file, 0.001, "[boundary]\nrim = \"ss\"\n");
            }).find("boundary.rim = \"ss\""),
            std::string::npos);
}

TEST(GmshMesh, FilesThatAreNotGmshMeshesAreRefused) {
  const fs::path dir = scratch("not-gmsh");
  std::ofstream(dir / "notes.msh") << "Point(1) = {0, 0, 0};\n";
  const std::string script =
      deck_error([&] { return isotropic_deck("static", dir / "notes.msh", 0.001, ""); });
  EXPECT_NE(script.find("not a gmsh mesh file (a .msh file starts with $MeshFormat)"), std::string::npos)
      << script;
  const std::string geo = deck_error([&] { return isotropic_deck("static", dir / "plate.geo", 0.001, ""); });
  EXPECT_NE(geo.find("mesh.file must be a gmsh mesh (.msh)"), std::string::npos) << geo;
  const std::string missing =
      deck_error([&] { return isotropic_deck("static", dir / "missing.msh", 0.001, ""); });
  EXPECT_NE(missing.find("cannot open the mesh file"), std::string::npos) << missing;
  // A mesh file stands for [plate] and the structured mesh's keys.
  test::write_disk_mesh(dir / "disk.msh", 0.1, 0.03);
  EXPECT_NE(deck_error([&] {
              return isotropic_deck("static", dir / "disk.msh", 0.001, "[plate]\na = 0.1\nb = 0.1\n");
            }).find("leave out [plate]"),
            std::string::npos);
  EXPECT_NE(deck_error([&] {
              return parse_deck(
                  std::string("[mesh]\nfile = \"") + (dir / "disk.msh").string() + "\"\nnx = 4\n", "d.toml");
            }).find("mesh.nx shapes the structured rectangle"),
            std::string::npos);
}

/// The thesis §3.6 impact (examples/thesis-3.6-v268.toml) without its [plate], [mesh], [contact] and
/// [time], which each test adds.
const std::string thesis_3_6_impact = "analysis = \"impact\"\n" + thesis_3_6_laminate + R"([boundary]
x0 = "ss"
xa = "ss"
y0 = "ss"
yb = "ss"
[impactor]
mass = 6.14
radius = 12.7e-3
E = 207e9
nu = 0.3
velocity = 2.68
)";

ImpactResult impact_of(const std::string& text) {
  return ImpactCase(impact_case_description(parse_deck(text, "deck.toml"))).run();
}

TEST(GmshMesh, TheThesisImpactOnTheGmshRectangleIsTheStructuredMeshs) {
  // The thesis configuration (15 × 11 q9, lumped mass, point load, Δt = 1 µs): the same event on the
  // rectangle meshed by gmsh with transfinite lines as on the structured factory's.
  const fs::path dir = scratch("thesis-impact");
  test::write_rectangle_mesh(dir / "thesis.msh", 0.127, 0.0762, 15, 11);
  const std::string thesis = "[contact]\nk = 0.6e9\nload = \"point\"\n[time]\ndt = 1.0e-6\n";
  const ImpactResult structured = impact_of(
      thesis_3_6_impact + thesis +
      "[plate]\na = 0.127\nb = 0.0762\n[mesh]\nnx = 15\nny = 11\nmass = \"lumped\"\nelement = \"q9\"\n");
  const ImpactResult meshed =
      impact_of(thesis_3_6_impact + thesis +
                fmt::format("[mesh]\nfile = \"{}\"\nmass = \"lumped\"\nelement = \"q9\"\n",
                            (dir / "thesis.msh").string()));
  std::printf("  peak force: structured %.17g N, gmsh %.17g N\n", structured.peak_force, meshed.peak_force);
  EXPECT_NEAR(meshed.peak_force / structured.peak_force, 1.0, 1e-10);
  EXPECT_NEAR(meshed.peak_contact_deflection / structured.peak_contact_deflection, 1.0, 1e-10);
  EXPECT_EQ(meshed.time_of_peak_force, structured.time_of_peak_force);
  EXPECT_EQ(meshed.contact_duration, structured.contact_duration);
  EXPECT_NEAR(structured.peak_force, 12661.70, 0.01) << "README's number for the thesis configuration";
}

TEST(GmshMesh, TheThesisImpactOnAnUnstructuredMeshRefinedAtTheImpactPointIsWithinOnePercent) {
  // The default settings (MITC9, the Hertz pressure over the contact circle, automatic Δt) on an
  // unstructured gmsh mesh, 10 mm elements at the corners and 2 mm at the impact point, against the
  // structured mesh graded toward the impact point (12859.68 N; converged 12878.0 N, docs/validation.md §19).
  const fs::path dir = scratch("thesis-unstructured");
  test::write_refined_rectangle_mesh(dir / "refined.msh", 0.127, 0.0762, 0.010, 0.002);
  const std::string contact = "[contact]\nk = 0.6e9\n"; // the thesis's contact stiffness, as the example
  const ImpactResult graded = impact_of(thesis_3_6_impact + contact + "[plate]\na = 0.127\nb = 0.0762\n");
  const Deck deck = parse_deck(thesis_3_6_impact + contact +
                                   fmt::format("[mesh]\nfile = \"{}\"\n", (dir / "refined.msh").string()),
                               "deck.toml");
  const ImpactResult meshed = ImpactCase(impact_case_description(deck)).run();
  std::printf("  peak force: graded structured %.2f N, unstructured gmsh (%d elements) %.2f N (%+.3f %%)\n",
              graded.peak_force, deck.file_mesh->element_count(), meshed.peak_force,
              100.0 * (meshed.peak_force / graded.peak_force - 1.0));
  EXPECT_NEAR(meshed.peak_force / graded.peak_force, 1.0, 0.01);
  EXPECT_NEAR(meshed.peak_force / 12878.0, 1.0, 0.01);
}

TEST(GmshMesh, AnImpactPointOffTheMeshIsRefused) {
  const fs::path file = scratch("impact-off") / "annulus.msh";
  test::write_annulus_mesh(file, 0.1, 0.03, 0.02);
  const std::string impactor = "[impactor]\nmass = 1.0\nradius = 0.01\nE = 207e9\nvelocity = 1.0\n";
  const std::string in_hole = deck_error(
      [&] { return isotropic_deck("impact", file, 0.002, "[boundary]\nouter = \"clamped\"\n" + impactor); });
  EXPECT_NE(in_hole.find("which is not on the plate: give impactor.x and impactor.y"), std::string::npos)
      << in_hole;
  const std::string outside = deck_error([&] {
    return isotropic_deck("impact", file, 0.002,
                          "[boundary]\nouter = \"clamped\"\n" + impactor + "x = 0.2\ny = 0.0\n");
  });
  EXPECT_NE(outside.find("impact point (0.2, 0) m lies outside the mesh"), std::string::npos) << outside;
}

} // namespace
} // namespace plyimpact::gmsh_mesh_tests
