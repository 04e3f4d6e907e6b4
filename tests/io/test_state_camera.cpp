// The ParaView state's colour range and camera rules (pipeline/io/pvsm_state.hpp,
// state_camera.hpp), each against a hand-worked case.
#include <gtest/gtest.h>

#include <vector>

#include "pipeline/io/pvsm_state.hpp"
#include "pipeline/io/state_camera.hpp"

namespace io = flapsim::io;

// Nearest-rank percentiles of {15, 20, 35, 40, 50} (the worked example of the nearest-rank
// method, e.g. Wikipedia "Percentile"): 5th -> 15, 30th -> 20, 40th -> 20, 50th -> 35,
// 100th -> 50; signs do not count (|x|).
TEST(StateColourRange, NearestRankPercentileOfMagnitudes) {
  for (const auto& [p, expected] : std::vector<std::pair<double, double>>{
           {5.0, 15.0}, {30.0, 20.0}, {40.0, 20.0}, {50.0, 35.0}, {100.0, 50.0}}) {
    std::vector<double> v = {-40.0, 15.0, 50.0, -20.0, 35.0};
    EXPECT_EQ(io::magnitude_percentile(v, p), expected) << p;
  }
  std::vector<double> none;
  EXPECT_EQ(io::magnitude_percentile(none, 98.0), 0.0);
}

// A unit cube seen along -z (up y) in a square picture: half height 1.05 max(0.5,
// 0.5 / 0.84) = 0.625 (the cube's width takes kFramedWidth = 0.84 of the picture), the
// focal point (1 - 0.84) / 2 of the picture's width (0.1) right of the cube's centre, on +x.
TEST(StateCamera, FramesABoxInTheLeftPartOfThePicture) {
  const io::FramingCamera c = io::frame_box({0, 1, 0, 1, 0, 1}, {{0, 0, 1}, {0, 1, 0}}, 1.0);
  EXPECT_NEAR(c.parallel_scale, 1.05 * 0.5 / 0.84, 1e-12);
  EXPECT_NEAR(c.focal_point[0], 0.5 + 0.08 * 2.0 * c.parallel_scale, 1e-12);
  EXPECT_NEAR(c.focal_point[1], 0.5, 1e-12);
  EXPECT_NEAR(c.focal_point[2], 0.5, 1e-12);
  EXPECT_GT(c.position[2], 1.0);  // in front of the cube, beyond its face
  EXPECT_NEAR(c.up[1], 1.0, 1e-12);
}

// A flat unit square in the x-y plane (normal z) is seen whole from above and edge-on from
// any level direction: the chooser picks the highest elevation it has, 60°, where its
// projected area is sin 60° of its area.
TEST(StateCamera, PicksTheDirectionThatSeesTheWingsFace) {
  io::PolyDataMesh square;
  square.points.resize(3, 4);
  square.points << 0, 1, 1, 0, 0, 0, 1, 1, 0, 0, 0, 0;
  square.polygons = {{0, 1, 2, 3}};
  io::StateCameraChooser chooser;
  chooser.add_frame(square);
  const io::ViewDirection d = chooser.best(*chooser.bounds(), 1.0);
  EXPECT_NEAR(d.toward[2], std::sqrt(3.0) / 2.0, 1e-12);
}
