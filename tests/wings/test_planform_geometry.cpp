// Planform geometry: areas, centroids, span moments, simplicity, containment, chords.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "wings/loader/outline_csv.hpp"
#include "wings/loader/planform_geometry.hpp"

using flapsim::wings::Polygon;
namespace w = flapsim::wings;

namespace {
Polygon unit_square() { return {{0, 0}, {1, 0}, {1, 1}, {0, 1}}; }
Polygon right_triangle() { return {{0, 0}, {1, 0}, {0, 1}}; }
}  // namespace

TEST(PlanformGeometry, UnitSquareAreaAndCentroid) {
  // Exact: area 1, centroid (1/2, 1/2).
  EXPECT_DOUBLE_EQ(w::polygon_area(unit_square()), 1.0);
  const auto c = w::polygon_centroid(unit_square());
  EXPECT_DOUBLE_EQ(c.x(), 0.5);
  EXPECT_DOUBLE_EQ(c.y(), 0.5);
}

TEST(PlanformGeometry, RightTriangleAreaAndCentroid) {
  // Exact: area 1/2, centroid at the mean of the vertices (1/3, 1/3).
  EXPECT_DOUBLE_EQ(w::polygon_area(right_triangle()), 0.5);
  const auto c = w::polygon_centroid(right_triangle());
  EXPECT_NEAR(c.x(), 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(c.y(), 1.0 / 3.0, 1e-15);
}

TEST(PlanformGeometry, SignedAreaFollowsOrientation) {
  Polygon cw = unit_square();
  std::reverse(cw.begin(), cw.end());
  EXPECT_DOUBLE_EQ(w::polygon_signed_area(unit_square()), 1.0);
  EXPECT_DOUBLE_EQ(w::polygon_signed_area(cw), -1.0);
  EXPECT_DOUBLE_EQ(w::polygon_area(cw), 1.0);
}

TEST(PlanformGeometry, SecondMomentOfRectangleAndTriangle) {
  // ∫∫ y² dA: unit square 1/3; triangle (0,0),(1,0),(0,1): ∫_0^1 y²(1−y) dy = 1/12.
  EXPECT_NEAR(w::polygon_second_moment_y(unit_square()), 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(w::polygon_second_moment_y(right_triangle()), 1.0 / 12.0, 1e-15);
}

TEST(PlanformGeometry, AreaMomentsOfATriangleInEitherOrientation) {
  // Triangle (0,0),(1,0),(0,1): ∫∫ x dA = ∫∫ y dA = 1/6, ∫∫ x² dA = ∫∫ y² dA = 1/12,
  // ∫∫ x y dA = ∫_0^1 x (1−x)²/2 dx = 1/24.
  Polygon cw = right_triangle();
  std::reverse(cw.begin(), cw.end());
  for (const Polygon& t : {right_triangle(), cw}) {
    const w::PolygonMoments m = w::polygon_moments(t);
    EXPECT_NEAR(m.area, 0.5, 1e-15);
    EXPECT_NEAR(m.first.x(), 1.0 / 6.0, 1e-15);
    EXPECT_NEAR(m.first.y(), 1.0 / 6.0, 1e-15);
    EXPECT_NEAR(m.xx, 1.0 / 12.0, 1e-15);
    EXPECT_NEAR(m.yy, 1.0 / 12.0, 1e-15);
    EXPECT_NEAR(m.xy, 1.0 / 24.0, 1e-15);
  }
  // Unit square shifted by (2, 3): ∫∫ x y dA = 2.5 · 3.5.
  const Polygon shifted{{2, 3}, {3, 3}, {3, 4}, {2, 4}};
  EXPECT_NEAR(w::polygon_moments(shifted).xy, 8.75, 1e-13);
}

TEST(PlanformGeometry, RectangleFromPivotHasAspectRatioAndR2) {
  // Rectangle chord c, span R from the pivot: S = cR, c̄ = c, AR = R/c, r2 = 1/√3.
  const Polygon rect{{0.0025, 0.0}, {0.0025, 0.04}, {-0.0075, 0.04}, {-0.0075, 0.0}};
  const auto p = w::planform_properties(rect);
  EXPECT_NEAR(p.span, 0.04, 1e-15);
  EXPECT_NEAR(p.area, 4e-4, 1e-18);
  EXPECT_NEAR(p.mean_chord, 0.01, 1e-15);
  EXPECT_NEAR(p.aspect_ratio, 4.0, 1e-12);
  EXPECT_NEAR(p.r2, 1.0 / std::sqrt(3.0), 1e-12);
}

TEST(PlanformGeometry, DetectsSelfIntersection) {
  EXPECT_FALSE(w::find_self_intersection(unit_square()));
  const Polygon bow_tie{{0, 0}, {1, 1}, {1, 0}, {0, 1}};  // edges 0 and 2 cross at (0.5, 0.5)
  const auto hit = w::find_self_intersection(bow_tie);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->first, 0);
  EXPECT_EQ(hit->second, 2);
  const Polygon repeated{{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_TRUE(w::find_self_intersection(repeated));
  // A vertex touching a non-adjacent edge is not simple either.
  const Polygon touching{{0, 0}, {2, 0}, {2, 2}, {1, 0}, {0, 2}};
  EXPECT_TRUE(w::find_self_intersection(touching));
}

TEST(PlanformGeometry, ContainsPointWithTolerance) {
  const Polygon sq = unit_square();
  EXPECT_TRUE(w::contains_point(sq, {0.5, 0.5}, 0.0));
  EXPECT_FALSE(w::contains_point(sq, {1.5, 0.5}, 0.0));
  EXPECT_TRUE(w::contains_point(sq, {1.0, 0.5}, 1e-12));        // on an edge
  EXPECT_TRUE(w::contains_point(sq, {1.0 + 1e-4, 0.5}, 1e-3));  // just outside, within tol
  EXPECT_FALSE(w::contains_point(sq, {1.0 + 1e-2, 0.5}, 1e-3));
  // Non-convex: an L shape, the notch is outside.
  const Polygon ell{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  EXPECT_TRUE(w::contains_point(ell, {0.5, 1.5}, 0.0));
  EXPECT_FALSE(w::contains_point(ell, {1.5, 1.5}, 0.0));
}

TEST(PlanformGeometry, ChordAtStation) {
  const Polygon tri{{0, 0}, {2, 0}, {0, 2}};  // leading edge x = 2 − y, trailing edge x = 0
  const auto c = w::chord_at(tri, 0.5);
  ASSERT_TRUE(c);
  EXPECT_DOUBLE_EQ(c->leading_x, 1.5);
  EXPECT_DOUBLE_EQ(c->trailing_x, 0.0);
  EXPECT_FALSE(w::chord_at(tri, 2.5));
  EXPECT_FALSE(w::chord_at(tri, -0.1));
}

TEST(PlanformGeometry, Hawkmoth1OutlineArea) {
  // Source: header of wings/outlines/hawkmoth1_outline.csv, "Polygon area = 0.3092 R^2".
  const Polygon p = w::read_outline_csv(
      std::string(FLAPSIM_SOURCE_DIR) + "/wings/outlines/hawkmoth1_outline.csv", "outline_file");
  EXPECT_EQ(p.size(), 200u);
  EXPECT_NEAR(w::polygon_area(p), 0.3092, 0.00005);
  EXPECT_FALSE(w::find_self_intersection(p));
  // Robofly: header "Polygon area = 0.2531 R^2".
  const Polygon r = w::read_outline_csv(
      std::string(FLAPSIM_SOURCE_DIR) + "/wings/outlines/robofly_dickinson_outline.csv", "o");
  EXPECT_NEAR(w::polygon_area(r), 0.2531, 0.00005);
}

TEST(PlanformGeometry, NearestPointOfAnOpenAndAClosedPolyline) {
  // Three sides of the unit square, (0,0) → (1,0) → (1,1) → (0,1). From (−0.5, 0.5) the
  // open polyline's nearest point is its first corner, (0, 0) and (0, 1) being equally near
  // (the first is taken); closed, the fourth side x = 0 is there: (0, 0.5).
  const Polygon square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const Eigen::Vector2d p(-0.5, 0.5);
  EXPECT_EQ(w::nearest_point_on_polyline(square, p), Eigen::Vector2d(0, 0));
  EXPECT_EQ(w::nearest_point_on_polyline(square, p, true), Eigen::Vector2d(0, 0.5));
  EXPECT_EQ(w::nearest_boundary_point(square, p), Eigen::Vector2d(0, 0.5));
  // Inside a segment: the foot of the perpendicular; a polyline of one point: that point.
  EXPECT_EQ(w::nearest_point_on_polyline(square, Eigen::Vector2d(1.5, 0.25)), Eigen::Vector2d(1, 0.25));
  EXPECT_EQ(w::nearest_point_on_polyline({{2, 3}}, p), Eigen::Vector2d(2, 3));
}
