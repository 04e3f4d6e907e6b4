// From a drawing to lift (docs/wing_file.md, "A wing from a drawing"): a case whose wing is
// an SVG drawing runs, and gives the lift of the same wing written as points, bit for bit;
// the shipped test drawing meshes with both of its veins.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace {

namespace fs = std::filesystem;
using flapsim::test::json_number;
using flapsim::test::read_text;
using flapsim::test::run_flapsim;

constexpr const char* kMembrane =
    "[materials.film]\nyoungs_modulus = 4.0e9\npoisson_ratio = 0.3\ndensity = 1400.0\n"
    "[membrane]\nthickness = 0.01\nmaterial = \"film\"\n";

void write_case(const fs::path& file, const std::string& wing) {
  std::ofstream(file) << "name = \"drawn\"\nwing = \"" << wing
                      << "\"\n[kinematics]\nfrequency_hz = 25\nsweep = { cos_deg = [60.0] }\n"
                         "rotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n[structure]\nkind = \"rigid\"\n"
                         "[numerics]\nsteps_per_cycle = 20\ncycles = 1\n";
}

// The trapezoid of wings.WingFromDrawing.* (tip right, leading edge up; outline (0, 0), (5, 50),
// (−10, 50), (−15, 0) mm by hand) flapped rigidly for a wingbeat: the same mean lift as the
// inline outline, to the last bit (the same points, up to the outline's starting point, which
// the lattice does not see).
TEST(WingFromDrawingRun, ADrawnWingFliesAsTheSameWingWrittenAsPoints) {
  const flapsim::test::ScratchDir dir("drawn_wing_run");
  std::ofstream(dir / "w.svg") << "<svg xmlns=\"http://www.w3.org/2000/svg\">\n"
                                  "<polygon id=\"outline\" points=\"10,20 110,10 110,40 10,50\"/>\n</svg>\n";
  std::ofstream(dir / "drawn.toml")
      << "length_unit = \"mm\"\n[planform]\noutline_file = \"w.svg\"\nspan = 50.0\n"
         "clamp_y = 0.5\n"
      << kMembrane;
  std::ofstream(dir / "hand.toml") << "length_unit = \"mm\"\n[planform]\n"
                                      "outline = [[0, 0], [5, 50], [-10, 50], [-15, 0]]\nclamp_y = 0.5\n"
                                   << kMembrane;
  write_case(dir / "drawn_case.toml", "drawn.toml");
  write_case(dir / "hand_case.toml", "hand.toml");
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
