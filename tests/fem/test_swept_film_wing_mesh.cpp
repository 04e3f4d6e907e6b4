// A user's swept film wing whose root spar was written to start on the leading edge but lies
// 1.1 µm inside it (tests/data/swept_film_50um_wing.toml): gmsh meshed the gap into a
// triangle with an angle of 0.028°, and its FEM's Newton stalled on it (docs/wing_file.md,
// "Checks"). The spar's end is now moved onto the edge (wings/wing_file.cpp):
// measured smallest angle 8.09°.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fem/wing_fem.hpp"
#include "wings/wing_file.hpp"

namespace flapsim::fem {
namespace {

TEST(SweptFilmWingMesh, NoSliverWhereTheSparMeetsTheLeadingEdge) {
  const WingFem f = build_wing_fem(
      wings::load_wing_file(std::string(FLAPSIM_SOURCE_DIR) + "/tests/data/swept_film_50um_wing.toml"));
  double smallest = 180.0;  // [deg]
  const Mesh& mesh = f.model.mesh;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d u = mesh.nodes[t[(k + 1) % 3]] - mesh.nodes[t[k]];
      const Eigen::Vector3d v = mesh.nodes[t[(k + 2) % 3]] - mesh.nodes[t[k]];
      smallest = std::min(smallest, std::acos(std::clamp(u.dot(v) / (u.norm() * v.norm()), -1.0, 1.0)) *
                                        180.0 / std::numbers::pi);
    }
  // Frontal-Delaunay's triangles next to a vein of finer elements: measured 8.09°; the sliver
  // was 0.028°.
  EXPECT_GT(smallest, 5.0);
}

}  // namespace
}  // namespace flapsim::fem
