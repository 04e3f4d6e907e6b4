// A vein's end written next to another vein is moved onto it when the gap would be meshed
// into slivers (wings/loader/vein_junctions.hpp, applied by the mesher for the mesh's vein size):
// the ends only, within tan(0.5°) of the vein element size and at most 0.1 % of the span.
#include <gtest/gtest.h>

#include <vector>

#include "wings/loader/vein_junctions.hpp"

namespace w = flapsim::wings;

namespace {

// A spar along x = 1 mm from y = 0 to 30 mm, and a second vein through `cross` [m].
std::vector<w::Vein> spar_and(std::vector<Eigen::Vector2d> cross) {
  std::vector<w::Vein> veins(2);
  veins[0].points = {{1e-3, 0.0}, {1e-3, 30e-3}};
  veins[1].points = std::move(cross);
  return veins;
}

// The tolerance of a 40 mm wing meshed at vein size `h` [m]; round-off as the mesher's.
int snap(std::vector<w::Vein>& veins, double h) {
  return w::snap_vein_ends_onto_other_veins(veins, w::vein_junction_tolerance(40e-3, h), 1e-12 * 40e-3);
}

}  // namespace

TEST(VeinJunctions, TheToleranceIsTheSliverAngleTimesTheVeinElementSizeAtMostATenthOfAPercentOfTheSpan) {
  // tan(0.5°) = 8.72687e-3 (0.5° = 8.72665e-3 rad; tan x = x + x³/3 + …).
  EXPECT_NEAR(w::vein_junction_tolerance(0.04, 0.8e-3), 0.8e-3 * 8.72686779e-3, 1e-15);
  EXPECT_EQ(w::vein_junction_tolerance(0.04, 10e-3), 0.04e-3);  // capped: 87 µm > 40 µm
}

TEST(VeinJunctions, AnEndAMicrometreOffAnotherVeinIsMovedOntoIt) {
  // 0.8 mm elements: tolerance 6.98 µm. The cross vein's first point 1 µm right of the spar
  // lands on it, x = 1 mm exactly; its other end, far from any vein, stays.
  auto veins = spar_and({{1.001e-3, 10e-3}, {-4e-3, 20e-3}});
  EXPECT_EQ(snap(veins, 0.8e-3), 1);
  EXPECT_EQ(veins[1].points.front().x(), 1e-3);
  EXPECT_NEAR(veins[1].points.front().y(), 10e-3, 1e-17);
  EXPECT_EQ(veins[1].points.back(), Eigen::Vector2d(-4e-3, 20e-3));
  EXPECT_EQ(veins[0].points.back(), Eigen::Vector2d(1e-3, 30e-3));  // the spar unchanged
  // Its last point 1 µm past the spar's end: onto that end, exactly. (The spar's end lies
  // 0.2 µm from the cross vein's line as written: each moved onto the other's line, as a T,
  // the two ends would have landed beside each other.)
  auto past = spar_and({{-4e-3, 20e-3}, {1e-3, 30.001e-3}});
  EXPECT_EQ(snap(past, 0.8e-3), 1);
  EXPECT_EQ(past[1].points.back(), Eigen::Vector2d(1e-3, 30e-3));
  EXPECT_EQ(past[0].points.back(), Eigen::Vector2d(1e-3, 30e-3));
}

TEST(VeinJunctions, AGapWiderThanTheToleranceAndAnInnerPointStayAsWritten) {
  // 20 µm off at 0.8 mm elements (tolerance 6.98 µm): meshed as written (about 1.4°, no sliver).
  auto wide = spar_and({{1.02e-3, 10e-3}, {-4e-3, 20e-3}});
  EXPECT_EQ(snap(wide, 0.8e-3), 0);
  // The same 20 µm at 10 mm elements (tolerance min(87 µm, 40 µm)): moved; 50 µm: not.
  EXPECT_EQ(snap(wide, 10e-3), 1);
  EXPECT_EQ(wide[1].points.front().x(), 1e-3);
  auto wider = spar_and({{1.05e-3, 10e-3}, {-4e-3, 20e-3}});
  EXPECT_EQ(snap(wider, 10e-3), 0);
  // An inner point 1 µm off the spar is where a vein runs past another: left alone.
  auto inner = spar_and({{-4e-3, 5e-3}, {0.999e-3, 10e-3}, {-4e-3, 15e-3}});
  EXPECT_EQ(snap(inner, 0.8e-3), 0);
}

TEST(VeinJunctions, EndsMeetEndsFirstThenLinesAndAnEndOnAVeinIsNotMoved) {
  std::vector<w::Vein> veins(3);
  veins[0].points = {{0.0, 0.0}, {0.0, 1.0}};    // x = 0
  veins[1].points = {{3e-6, 0.0}, {3e-6, 1.0}};  // x = 3 µm
  veins[2].points = {{2e-6, 0.5}, {-1.0, 0.5}};  // starts 2 µm from the first, 1 µm from the second
  EXPECT_EQ(w::snap_vein_ends_onto_other_veins(veins, 5e-6, 1e-12), 3);
  // The second vein's ends are 3 µm from the first's: onto them (ends first, onto the
  // earlier vein); then the third's start is 2 µm from both lines, now one: onto x = 0.
  EXPECT_EQ(veins[1].points[0], Eigen::Vector2d(0.0, 0.0));
  EXPECT_EQ(veins[1].points[1], Eigen::Vector2d(0.0, 1.0));
  EXPECT_EQ(veins[2].points[0], Eigen::Vector2d(0.0, 0.5));
  // Nothing is moved a second time: every end now lies on another vein.
  EXPECT_EQ(w::snap_vein_ends_onto_other_veins(veins, 5e-6, 1e-12), 0);
}
