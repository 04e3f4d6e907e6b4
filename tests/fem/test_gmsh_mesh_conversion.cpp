// gmsh's mesh turned into the FEM's Mesh (fem/gmsh_mesh_conversion.hpp): gmsh returns the
// same triangles in an order that changes from run to run (six meshings of
// wings/hawkmoth.toml on one machine gave three element orders), and the Mesh, hence the
// FEM's node numbering, summation order and every result downstream, must not depend on it.
#include "fem/gmsh_mesh_conversion.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

using namespace flapsim;

namespace {

/// A unit square (nodes 1–4 at the corners, 5 at the centre, 6 unused) in four triangles
/// around the centre, and one vein along the diagonal 1 → 5 → 3 in two line elements.
struct SquareMesh {
  wings::Wing wing;
  fem::GmshWingMesh gmsh;
  SquareMesh() {
    wing.outline = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    wings::Vein v;
    v.name = "diagonal";
    v.points = {{0, 0}, {1, 1}};
    wing.veins.push_back(v);
    gmsh.status = fem::GmshWingMesh::Status::ok;
    gmsh.node_tags = {1, 2, 3, 4, 5, 6};
    gmsh.coordinates = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 0, 2, 2, 0};
    gmsh.triangle_nodes = {1, 2, 5, 2, 3, 5, 3, 4, 5, 4, 1, 5};
    gmsh.vein_curves = {{0, {1, 5, 5, 3}}};
  }
};

}  // namespace

TEST(GmshMeshConversion, TheOrderOfGmshsTrianglesDoesNotChangeTheMesh) {
  SquareMesh a;
  const fem::Mesh ma = fem::mesh_from_gmsh(a.wing, a.gmsh);
  // The same triangles in reverse order, each listed from another node and clockwise.
  SquareMesh b;
  b.gmsh.triangle_nodes = {5, 1, 4, 5, 4, 3, 5, 3, 2, 5, 2, 1};
  const fem::Mesh mb = fem::mesh_from_gmsh(b.wing, b.gmsh);
  ASSERT_EQ(ma.nodes.size(), 5u);  // node 6 is used by no element: dropped
  ASSERT_EQ(mb.nodes.size(), ma.nodes.size());
  for (std::size_t i = 0; i < ma.nodes.size(); ++i) EXPECT_EQ(ma.nodes[i], mb.nodes[i]) << "node " << i;
  EXPECT_EQ(ma.triangles, mb.triangles);
  ASSERT_EQ(ma.beams.size(), 2u);
  ASSERT_EQ(mb.beams.size(), 2u);
  for (std::size_t e = 0; e < ma.beams.size(); ++e) EXPECT_EQ(ma.beams[e].nodes, mb.beams[e].nodes) << "beam " << e;
  // Every triangle counter-clockwise seen from +z (positive area), starting at its lowest node.
  for (const auto& t : ma.triangles) {
    const Eigen::Vector3d n = (ma.nodes[t[1]] - ma.nodes[t[0]]).cross(ma.nodes[t[2]] - ma.nodes[t[0]]);
    EXPECT_NEAR(n.z(), 0.5, 1e-15);  // twice the area of a quarter of the unit square
    EXPECT_EQ(t[0], *std::min_element(t.begin(), t.end()));
  }
  EXPECT_TRUE(std::is_sorted(ma.triangles.begin(), ma.triangles.end()));
  // Beams along the vein's direction (from (0, 0) towards (1, 1)).
  for (const auto& b : ma.beams) EXPECT_GT((ma.nodes[b.nodes[1]] - ma.nodes[b.nodes[0]]).sum(), 0.0);
}
