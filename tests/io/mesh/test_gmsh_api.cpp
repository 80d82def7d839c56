// The gmsh library opened at run time (io/mesh/gmsh_api): the calls reach gmsh, and gmsh's error codes
// come back as GmshError carrying gmsh's own message.
#include "plyimpact/io/mesh/gmsh_api.hpp"

#include <gtest/gtest.h>

#include <string>

namespace plyimpact::gmsh_api_tests {
namespace {

/// gmsh initialised for one test, finalised after it.
class GmshApiTest : public ::testing::Test {
protected:
  void SetUp() override {
    gmsh.initialize(false);
    gmsh.set_option("General.Terminal", 0);
  }
  void TearDown() override { gmsh.finalize(); }
  const GmshApi& gmsh = gmsh_api();
};

TEST_F(GmshApiTest, BuildsAndMeshesASquareThroughTheCApi) {
  // A unit square of 2 × 2 transfinite quadrilaterals has 9 nodes and 4 elements; its
  // bounding box is the square.
  gmsh.add_model("square");
  const int p0 = gmsh.add_point(0, 0, 0), p1 = gmsh.add_point(1, 0, 0), p2 = gmsh.add_point(1, 1, 0),
            p3 = gmsh.add_point(0, 1, 0);
  const int loop = gmsh.add_curve_loop(
      {gmsh.add_line(p0, p1), gmsh.add_line(p1, p2), gmsh.add_line(p2, p3), gmsh.add_line(p3, p0)});
  const int surface = gmsh.add_plane_surface({loop});
  gmsh.synchronize();
  gmsh.set_physical_name(2, gmsh.add_physical_group(2, {surface}), "plate");
  gmsh.set_option("Mesh.RecombineAll", 1);
  gmsh.set_option("Mesh.MeshSizeMin", 0.5);
  gmsh.set_option("Mesh.MeshSizeMax", 0.5);
  gmsh.generate(2);

  const std::vector<double> box = gmsh.bounding_box();
  EXPECT_DOUBLE_EQ(box[0], 0.0);
  EXPECT_DOUBLE_EQ(box[3], 1.0);
  EXPECT_DOUBLE_EQ(box[4], 1.0);
  const auto groups = gmsh.physical_groups();
  ASSERT_EQ(groups.size(), 1U);
  EXPECT_EQ(gmsh.physical_name(groups[0].first, groups[0].second), "plate");
  EXPECT_EQ(gmsh.entities_for_physical_group(2, groups[0].second), std::vector<int>{surface});
  const GmshApi::Nodes nodes = gmsh.nodes();
  EXPECT_EQ(nodes.coords.size(), 3 * nodes.tags.size());
  const GmshApi::Elements quads = gmsh.elements_by_type(3); // 4-node quadrilaterals
  EXPECT_EQ(quads.node_tags.size(), 4 * quads.tags.size());
  EXPECT_GE(quads.tags.size(), 4U);
  EXPECT_EQ(gmsh.nodes_for_physical_group(2, groups[0].second).tags.size(), nodes.tags.size());
}

TEST_F(GmshApiTest, GmshsErrorCodeBecomesGmshErrorWithGmshsMessage) {
  // A line between points that do not exist is an error in gmsh; its message names the point.
  gmsh.add_model("broken");
  try {
    static_cast<void>(gmsh.add_line(100, 101));
    FAIL() << "gmsh drew a line between points that do not exist";
  } catch (const GmshError& e) {
    EXPECT_NE(std::string(e.what()).find("point 100"), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace plyimpact::gmsh_api_tests
