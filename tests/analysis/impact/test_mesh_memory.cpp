// The memory estimate made before assembly (analysis/impact/mesh_memory.hpp): the formula's numbers for one
// mesh, that it errs on the large side of the exact symbolic analysis of the assembled K̄ on structured meshes
// of several sizes and aspect ratios, that the graded mesh it sizes is the one the case builds, and that the
// case refuses a graded mesh beyond the memory available before building anything.
#include "plyimpact/analysis/impact/guards.hpp"
#include "plyimpact/analysis/impact/mesh_memory.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "support/cli.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace plyimpact::mesh_memory_tests {
namespace {

TEST(MemoryEstimate, FormulaOfA15By11Mesh) {
  const MeshMemoryEstimate e = estimate_mesh_memory(15, 11);
  EXPECT_EQ(e.nodes, 31.0 * 23.0);
  EXPECT_EQ(e.equations, 5.0 * 713.0);
  EXPECT_EQ(e.matrix_nonzeros, 400.0 * 713.0);
  EXPECT_DOUBLE_EQ(e.factor_nonzeros, factor_fill_constant * 3565.0 * std::pow(std::log2(3565.0), 2));
  EXPECT_DOUBLE_EQ(e.bytes, 12.0 * (e.factor_nonzeros + e.equations + 3.0 * e.matrix_nonzeros));
}

TEST(MemoryEstimate, ExceedsTheSymbolicAnalysisOfStructuredMeshes) {
  for (const auto& [nx, ny] : {std::pair{4, 4}, {8, 8}, {16, 12}, {24, 24}, {40, 6}, {32, 32}, {48, 48}}) {
    const std::string text = test::small_deck("static", "") + "";
    Deck deck = parse_deck(text, "deck.toml");
    deck.mesh->nx = nx;
    deck.mesh->ny = ny;
    const DiscretePlate model = plate_model(deck);
    const SparseMatrix Kbar = model.stiffness() + 1e6 * model.mass();
    const FactorMemoryEstimate exact = estimate_factor_memory(Kbar);
    const MeshMemoryEstimate e = estimate_mesh_memory(nx, ny);
    std::printf("%d x %d: equations %ld (estimate %.0f), nnz(A) %ld (estimate %.0f), nnz(L) %ld, ratio to "
                "n log2 n %.3f\n",
                nx, ny, exact.equations, e.equations, exact.matrix_nonzeros, e.matrix_nonzeros,
                exact.factor_nonzeros,
                static_cast<double>(exact.factor_nonzeros) /
                    (static_cast<double>(exact.equations) *
                     std::pow(std::log2(static_cast<double>(exact.equations)), 2)));
    EXPECT_GE(e.equations, static_cast<double>(exact.equations)) << nx << " x " << ny;
    EXPECT_GE(e.matrix_nonzeros, static_cast<double>(exact.matrix_nonzeros)) << nx << " x " << ny;
    EXPECT_GE(e.factor_nonzeros, static_cast<double>(exact.factor_nonzeros)) << nx << " x " << ny;
    EXPECT_GE(e.bytes, exact.bytes) << nx << " x " << ny;
  }
}

/// small_deck's plate struck by the tests' steel ball (with `impactor_keys`), its [mesh] nx, ny replaced by
/// the graded mesh's keys.
ImpactCaseDescription graded_case(const std::string& mesh_keys, const std::string& impactor_keys = "") {
  std::string text = test::small_deck("impact", R"(
[impactor]
mass = 0.314
radius = 12.7e-3
E = 207e9
velocity = 2.92
)" + impactor_keys);
  text.replace(text.find("nx = 6\nny = 4"), 13, mesh_keys);
  return impact_case_description(parse_deck(text, "deck.toml"));
}

TEST(MemoryEstimate, GradedMeshSizeIsTheMeshTheImpactCaseBuilds) {
  const ImpactCaseDescription d = graded_case("size_at_impact = 1e-3\ngrowth = 1.2", "x = 0.05\n");
  ASSERT_TRUE(d.mesh.grading);
  const auto [nx, ny] = graded_mesh_size(d);
  const Mesh mesh = impact_mesh(d);
  EXPECT_EQ(nx * ny, mesh.element_count());
  EXPECT_EQ((2 * nx + 1) * (2 * ny + 1), mesh.node_count());
  EXPECT_GT(nx, 6);
}

TEST(MemoryEstimate, TheImpactCaseRefusesAGradedMeshBeyondTheMemoryBeforeBuildingIt) {
  // 10 µm elements at the impact point (the smallest a deck may ask for) growing by 1 %: more than a
  // thousand element lines each way, hundreds of gigabytes; building the mesh alone would take minutes.
  ImpactCaseDescription d = graded_case("size_at_impact = 1e-5\ngrowth = 1.01");
  d.memory_limit_bytes = 16e9;
  const auto [nx, ny] = graded_mesh_size(d);
  EXPECT_GT(estimate_mesh_memory(nx, ny).bytes, 16e9);
  try {
    const ImpactCase impact(d);
    ADD_FAILURE() << "a graded mesh of " << nx << " x " << ny << " elements was built";
  } catch (const InsufficientMemory& e) {
    EXPECT_NE(std::string(e.what()).find(
                  fmt::format("a mesh graded toward the impact point of {} x {} elements", nx, ny)),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("give a larger mesh.size_at_impact"), std::string::npos);
  }
}

// Issue 77: a graded mesh whose max_size is below the size at the impact point chosen from the contact
// radius ignored it (0.5 mm asked, 1 to 2.5 mm given): max_size caps every element, that one too.
TEST(MemoryEstimate, AGradedMeshHonoursMaxSizeBelowTheAutomaticSizeAtTheImpact) {
  const ImpactCaseDescription d = graded_case("max_size = 0.5e-3");
  ASSERT_TRUE(d.mesh.grading);
  const Mesh mesh = impact_mesh(d);
  // every element is at most max_size on a side, but those of the last row and column at the plate's
  // edges, which take the remainder of the side: up to 2.5 max_size (fem/structured_mesh.cpp, graded_lines:
  // the last line is moved onto the edge, so the last element is the last step and the remainder)
  const BoundingBox box = mesh.bounds();
  double inner = 0.0, edge = 0.0;
  for (int e = 0; e < mesh.element_count(); ++e) {
    const Eigen::Vector2d c = mesh.map(e, 0.0, 0.0);
    const bool at_edge =
        std::min({c.x() - box.x_min, box.x_max - c.x(), c.y() - box.y_min, box.y_max - c.y()}) < 0.7e-3;
    double& largest = at_edge ? edge : inner;
    for (int k = 0; k < 2; ++k) { // the element's sides along x and y
      const Eigen::Vector2d side =
          mesh.map(e, k == 0 ? 1.0 : -1.0, k == 0 ? -1.0 : 1.0) - mesh.map(e, -1.0, -1.0);
      largest = std::max(largest, side.norm());
    }
  }
  EXPECT_LE(inner, 0.5e-3 * (1.0 + 1e-9));
  EXPECT_GT(inner, 0.4e-3); // the plate is not meshed finer than asked either
  EXPECT_LE(edge, 1.25e-3 * (1.0 + 1e-9));
}

} // namespace
} // namespace plyimpact::mesh_memory_tests
