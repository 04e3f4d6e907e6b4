// From a drawing to lift (docs/wing_file.md, "A wing from a drawing"): a case whose wing is
// an SVG drawing runs, and gives the lift of the same wing written as points, bit for bit;
// the shipped test drawing meshes with both of its veins.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "rigid_wingbeat_case.hpp"

namespace {

namespace fs = std::filesystem;
using flapsim::test::json_number;
using flapsim::test::read_text;
using flapsim::test::run_flapsim;
using flapsim::test::write_film_wing;
using flapsim::test::write_rigid_wingbeat_case;

// The trapezoid of wings.WingFromDrawing.* (tip right, leading edge up; outline (0, 0), (5, 50),
// (−10, 50), (−15, 0) mm by hand) flapped rigidly for a wingbeat: the same mean lift as the
// inline outline, to the last bit (the same points, up to the outline's starting point, which
// the lattice does not see).
TEST(WingFromDrawingRun, ADrawnWingFliesAsTheSameWingWrittenAsPoints) {
  const flapsim::test::ScratchDir dir("drawn_wing_run");
  std::ofstream(dir / "w.svg") << "<svg xmlns=\"http://www.w3.org/2000/svg\">\n"
                                  "<polygon id=\"outline\" points=\"10,20 110,10 110,40 10,50\"/>\n</svg>\n";
  write_film_wing(dir / "drawn.toml", "outline_file = \"w.svg\"\nspan = 50.0");
  write_film_wing(dir / "hand.toml", "outline = [[0, 0], [5, 50], [-10, 50], [-15, 0]]");
  write_rigid_wingbeat_case(dir / "drawn_case.toml", "drawn", "drawn.toml");
  write_rigid_wingbeat_case(dir / "hand_case.toml", "drawn", "hand.toml");
  ASSERT_EQ(run_flapsim("run " + (dir / "drawn_case.toml").string() + " -o " + (dir / "o1").string()), 0);
  ASSERT_EQ(run_flapsim("run " + (dir / "hand_case.toml").string() + " -o " + (dir / "o2").string()), 0);
  const double drawn = json_number(read_text(dir / "o1" / "summary.json"), "mean_lift_N");
  const double hand = json_number(read_text(dir / "o2" / "summary.json"), "mean_lift_N");
  EXPECT_GT(hand, 0.0);
  EXPECT_EQ(drawn, hand);
}

// tests/data/drawn_wing.toml: Bézier outline, a pivot circle, two drawn veins; gmsh embeds
// both veins in the membrane.
TEST(WingFromDrawingRun, TheTestDrawingMeshesWithBothVeins) {
  const flapsim::test::ScratchDir dir("drawn_wing_mesh");
  const fs::path out = dir / "out.txt";
  ASSERT_EQ(run_flapsim("mesh " + std::string(FLAPSIM_SOURCE_DIR) + "/tests/data/drawn_wing.toml -o " +
                            (dir / "m").string(),
                        out),
            0);
  EXPECT_NE(read_text(out).find("(2 veins)"), std::string::npos) << read_text(out);
}

}  // namespace
