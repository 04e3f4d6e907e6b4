// A root clamp that holds only film (fem/root_clamp_warning.hpp). A user's film wing whose
// spar was drawn from 0.4 mm above the clamp line had a first mode of 5.7 Hz against 36.6 Hz
// with the spar clamped, and a plate with a pointed root (one node clamped) 3.3 Hz against
// 43.5 Hz with a 4 mm root held: `check` and `modes` said nothing.
#include <gtest/gtest.h>

#include <string>

#include "fem/root_clamp_warning.hpp"

namespace flapsim::fem {
namespace {

// A 10 mm x 40 mm rectangle (mean chord 10 mm) with nodes on its root edge y = 0 at the given
// x [mm], one node above them, and a vein of two elements from (0, y0) up the span.
struct Case {
  Mesh mesh;
  wings::Wing wing;
};

Case rectangle(const std::vector<double>& root_x_mm, double vein_start_y_mm, bool with_vein) {
  Case c;
  c.wing.source_file = "w.toml";
  c.wing.outline = {{2.5e-3, 0.0}, {2.5e-3, 40e-3}, {-7.5e-3, 40e-3}, {-7.5e-3, 0.0}};
  c.wing.clamp_y = 0.0;
  for (double x : root_x_mm) c.mesh.nodes.emplace_back(x * 1e-3, 0.0, 0.0);
  c.mesh.nodes.emplace_back(0.0, 20e-3, 0.0);
  if (with_vein) {
    c.wing.veins.resize(1);
    const int a = static_cast<int>(c.mesh.nodes.size());
    c.mesh.nodes.emplace_back(0.0, vein_start_y_mm * 1e-3, 0.0);
    c.mesh.nodes.emplace_back(0.0, 30e-3, 0.0);
    c.mesh.beams.push_back({{a, a + 1}, 0});
    c.mesh.beams.push_back({{a + 1, a - 1}, 0});
  }
  return c;
}

TEST(RootClampWarning, AVeinStartingAboveTheClampLineIsWarned) {
  const Case held = rectangle({-7.5, -5.0, -2.5, 0.0, 2.5}, 0.0, true);  // the spar's first node at y = 0
  EXPECT_EQ(root_clamp_warning(held.mesh, held.wing), "");
  const Case above = rectangle({-7.5, -5.0, -2.5, 0.0, 2.5}, 0.4, true);  // 0.4 mm above the clamp line
  const std::string w = root_clamp_warning(above.mesh, above.wing);
  EXPECT_NE(w.find("holds 5 nodes over 10 mm of chord (the mean chord 10 mm) and no vein"), std::string::npos)
      << w;
  EXPECT_NE(w.find("w.toml: "), std::string::npos) << w;
}

TEST(RootClampWarning, APointedRootWithoutVeinsIsWarnedAFullOneNot) {
  const Case full = rectangle({-7.5, -2.5, 2.5}, 0.0, false);
  EXPECT_EQ(root_clamp_warning(full.mesh, full.wing), "");
  const Case point = rectangle({0.0}, 0.0, false);
  EXPECT_NE(root_clamp_warning(point.mesh, point.wing).find("holds 1 node over 0 mm"), std::string::npos);
  // Just under a quarter of the mean chord is narrow, just over it not (kNarrowClampChordShare).
  const Case narrow = rectangle({0.0, 2.49}, 0.0, false);
  EXPECT_NE(root_clamp_warning(narrow.mesh, narrow.wing), "");
  const Case wide = rectangle({0.0, 2.51}, 0.0, false);
  EXPECT_EQ(root_clamp_warning(wide.mesh, wide.wing), "");
}

}  // namespace
}  // namespace flapsim::fem
