// A chord_points vein whose consecutive points are both on the leading edge (xi = 0) or both
// on the trailing edge (xi = 1) runs along that edge through the outline's own vertices
// (wings/loader/wing_file.cpp): the straight chords between points on a curved edge left it.
#include <gtest/gtest.h>

#include <string>

#include "wings/loader/planform_geometry.hpp"
#include "wings/loader/toml_reader.hpp"
#include "wings/loader/wing_file.hpp"

namespace w = flapsim::wings;

TEST(VeinAlongEdge, TheOutlinesEdgeVerticesBetweenTwoStationsInTheirOrder) {
  // A hexagon: leading edge through (3, 10), trailing edge through (−3, 10).
  const w::Polygon hexagon = {{2, 0}, {3, 10}, {2, 20}, {-2, 20}, {-3, 10}, {-2, 0}};
  const auto le = w::edge_vertices_between(hexagon, 5.0, 15.0, true);
  ASSERT_EQ(le.size(), 1u);
  EXPECT_EQ(le[0], Eigen::Vector2d(3, 10));
  const auto te = w::edge_vertices_between(hexagon, 5.0, 15.0, false);
  ASSERT_EQ(te.size(), 1u);
  EXPECT_EQ(te[0], Eigen::Vector2d(-3, 10));
  // Strictly between: a station at a vertex's y does not repeat it.
  EXPECT_TRUE(w::edge_vertices_between(hexagon, 10.0, 15.0, true).empty());
  // From the tip down: in that order. The tip's corners (y = 20) are excluded as stations.
  const w::Polygon octagon = {{2, 0}, {3, 5}, {3.5, 10}, {3, 15}, {2, 20}, {-2, 20}, {-3, 10}, {-2, 0}};
  const auto down = w::edge_vertices_between(octagon, 18.0, 2.0, true);
  ASSERT_EQ(down.size(), 3u);
  EXPECT_EQ(down[0], Eigen::Vector2d(3, 15));
  EXPECT_EQ(down[2], Eigen::Vector2d(3, 5));
}

TEST(VeinAlongEdge, ACostaAtXiZeroLiesOnTheLeadingEdgeOfAnEllipse) {
  // An elliptic wing (40 mm, chord 12 mm, 96 outline points) with a costa written at xi = 0
  // from y/R 0.05 to 0.95, subdivide 10: its points were the leading edge's at 11 stations,
  // the chords between them inside the convex edge by up to 0.13 mm (gmsh: 1.03° triangles
  // in the gap). Now every point lies on the outline, the outline's vertices among them.
  const std::string text =
      "name = \"ell\"\nlength_unit = \"mm\"\n[planform]\nshape = \"ellipse\"\nspan = 40.0\nchord = 12.0\n"
      "clamp_y = 2.0\n[materials.c]\nyoungs_modulus = 6e9\npoisson_ratio = 0.3\ndensity = 1200.0\n"
      "[membrane]\nthickness = 0.01\nmaterial = \"c\"\n"
      "[[veins]]\nname = \"costa\"\nchord_points = [[0.05, 0.0], [0.95, 0.0]]\nsubdivide = 10\n"
      "outer_diameter = 0.2\nwall = 0.05\nmaterial = \"c\"\n"
      "[[veins]]\nname = \"cross\"\nchord_points = [[0.5, 0.0], [0.5, 1.0]]\nsubdivide = 10\n"
      "outer_diameter = 0.2\nwall = 0.05\nmaterial = \"c\"\n";
  const w::Wing wing = w::read_wing(w::parse_toml_string(text, "ell.toml"));
  const auto& costa = wing.veins[0].points;
  int outline_vertices = 0;
  for (const auto& p : costa) {
    EXPECT_LT(w::distance_to_boundary(wing.outline, p), 1e-12 * wing.span);
    for (const auto& v : wing.outline) outline_vertices += (p == v);
  }
  // The leading edge between y = 2 and 38 mm: about 0.9 · 96 / 2 of the ellipse's vertices.
  EXPECT_GT(outline_vertices, 30);
  EXPECT_EQ(outline_vertices + 2, static_cast<int>(costa.size()));
  EXPECT_NEAR(costa.front().y(), 0.05 * 40e-3, 1e-15);
  EXPECT_NEAR(costa.back().y(), 0.95 * 40e-3, 1e-15);
  // A vein across the chord (xi from 0 to 1) is subdivided as before: 11 points, straight.
  EXPECT_EQ(wing.veins[1].points.size(), 11u);
}
