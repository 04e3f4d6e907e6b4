// Lattice grid from planform outlines.
#include "uvlm/planform_grid.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

using namespace flapsim::uvlm;

namespace {

// A shipped outline (wings/outlines/*.csv: '#' comment lines, an "x,y" header, then
// one "x,y" pair per line, in units of R) scaled by `scale`. Read here rather than
// with the wings library, which uvlm does not use (docs/architecture.md).
std::vector<Eigen::Vector2d> read_outline(const std::string& name, double scale) {
  std::ifstream in(std::string(FLAPSIM_SOURCE_DIR) + "/wings/outlines/" + name);
  std::vector<Eigen::Vector2d> pts;
  double x = 0.0, y = 0.0;
  for (std::string line; std::getline(in, line);)
    if (std::sscanf(line.c_str(), "%lf,%lf", &x, &y) == 2) pts.emplace_back(scale * x, scale * y);
  return pts;
}

}  // namespace

TEST(PlanformGrid, RectangleNodesAndArea) {
  PlanformGridOptions o;
  o.chordwise = 4;
  o.spanwise = 5;
  const PlanformGrid g = make_rectangular_grid(0.2, 1.0, o);
  ASSERT_EQ(g.nodes.cols(), 5 * 6);
  EXPECT_NEAR(g.lattice_area, 0.2, 1e-14);
  // Node (i, j) at i + (nc+1) j: leading edge x = 0, trailing edge x = −c, root y = 0.
  EXPECT_NEAR(g.nodes(0, 0 + 5 * 3), 0.0, 1e-15);
  EXPECT_NEAR(g.nodes(0, 4 + 5 * 3), -0.2, 1e-15);
  EXPECT_NEAR(g.nodes(1, 2 + 5 * 5), 1.0, 1e-15);
}

// A root edge square only to round-off (a drawing rotated by 90°, a corner off by 1e-12 of
// the span): before, the root station went to where the slant's chord passes 0.1 of the
// largest, 1e-13 in, and the root strip started from that chord (a lattice 2.7 % smaller,
// CL 1.8 % lower in a hover). Now its grid is the square root's to the slant's size.
TEST(PlanformGrid, ARootSquareOnlyToRoundOffGivesTheSquareRootsGrid) {
  PlanformGridOptions o;
  const std::vector<Eigen::Vector2d> square = {
      {0.0025, 0.0}, {0.0025, 0.04}, {-0.0075, 0.04}, {-0.0075, 0.0}};
  const PlanformGrid g = make_planform_grid(square, o);
  for (const double slant : {1e-15, -1e-15, 1e-9}) {
    std::vector<Eigen::Vector2d> off = square;
    off[3].y() += slant;  // the root's trailing corner [m]
    const PlanformGrid h = make_planform_grid(off, o);
    EXPECT_NEAR(h.lattice_area, g.lattice_area, 1e-5 * g.lattice_area) << slant;
    EXPECT_NEAR(h.y_root, g.y_root, 1e-6 * 0.04 + std::abs(slant)) << slant;
    // The root station's chord is the full 10 mm.
    EXPECT_NEAR(h.nodes(0, 0) - h.nodes(0, o.chordwise), 0.01, 1e-6) << slant;
  }
}

TEST(PlanformGrid, CosineSpacingClustersAtBothEdges) {
  PlanformGridOptions o;
  o.chordwise = 4;
  o.spanwise = 2;
  o.chordwise_spacing = Spacing::Cosine;
  const PlanformGrid g = make_rectangular_grid(1.0, 1.0, o);
  // ξ_i = (1 − cos(π i/4))/2 = 0, 0.1464, 0.5, 0.8536, 1
  EXPECT_NEAR(-g.nodes(0, 1), 0.5 * (1 - std::cos(M_PI / 4)), 1e-14);
  EXPECT_NEAR(-g.nodes(0, 2), 0.5, 1e-14);
}

TEST(PlanformGrid, ChordExtentOfATriangle) {
  // Triangle with leading edge x = 1 − y and trailing edge x = 0, tip at y = 1.
  const std::vector<Eigen::Vector2d> tri = {{0, 0}, {1, 0}, {0, 1}};
  const Eigen::Vector2d e = chord_extent(tri, 0.25);
  EXPECT_NEAR(e(0), 0.75, 1e-14);
  EXPECT_NEAR(e(1), 0.0, 1e-14);
  EXPECT_NEAR(polygon_area(tri), 0.5, 1e-14);
}

TEST(PlanformGrid, HawkmothOutlineHasNoDegeneratePanels) {
  // hawkmoth1: polygon area 0.3092 R² (stated in the file header).
  const double R = 0.0483;
  const auto outline = read_outline("hawkmoth1_outline.csv", R);
  ASSERT_GT(outline.size(), 100u);
  PlanformGridOptions o;  // 6 × 10
  const PlanformGrid g = make_planform_grid(outline, o);
  EXPECT_NEAR(g.outline_area / (R * R), 0.3092, 5e-4);
  // The rounded tip and root are trimmed where the chord falls below 10 % of the largest.
  EXPECT_GT(g.lattice_area, 0.97 * g.outline_area);
  EXPECT_LT(g.lattice_area, g.outline_area);
  double smallest = 1e9;
  for (int j = 0; j < o.spanwise; ++j)
    for (int i = 0; i < o.chordwise; ++i) {
      const int n1 = o.chordwise + 1;
      const Eigen::Vector3d d1 = g.nodes.col(i + 1 + n1 * (j + 1)) - g.nodes.col(i + n1 * j);
      const Eigen::Vector3d d2 = g.nodes.col(i + n1 * (j + 1)) - g.nodes.col(i + 1 + n1 * j);
      smallest = std::min(smallest, 0.5 * d1.cross(d2).norm());
    }
  EXPECT_GT(smallest, 0.01 * g.lattice_area / 60.0);
  // Leading edge toward +x: every leading-edge node lies ahead of its trailing-edge node.
  for (int j = 0; j <= o.spanwise; ++j) EXPECT_GT(g.nodes(0, 7 * j), g.nodes(0, 6 + 7 * j));
}

TEST(PlanformGrid, RejectsBadInput) {
  PlanformGridOptions o;
  EXPECT_THROW(make_planform_grid({{0, 0}, {1, 0}}, o), std::invalid_argument);
  EXPECT_THROW(make_planform_grid({{0, 0}, {1, 0}, {2, 0}}, o), std::invalid_argument);
  o.spanwise = 0;
  EXPECT_THROW(make_rectangular_grid(1, 1, o), std::invalid_argument);
}
