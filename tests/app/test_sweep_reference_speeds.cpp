// A sweep whose rows have their coefficients on different reference speeds says so under its
// table (pipeline/app/sweep/mixed_reference_speeds.hpp). Before: a sweep of the rigid hawkmoth
// hover over the free stream printed mean CL 3.43, 17.41 and 2.06 at 0, 1 and 3 m/s in one
// column (the first on the flapping speed at r2, the others on U∞) for lifts of 8.5, 8.7 and
// 9.3 mN, and nothing told the rows apart.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace sweep_reference_speeds_test {

using namespace flapsim;

// The flat plate flapping (as sweep_test_helpers.hpp's tiny plate) with an [air] table whose
// free stream the sweep varies.
std::string reference_speed_plate_case() {
  return "name = \"plate\"\nwing = \"" + std::string(FLAPSIM_SOURCE_DIR) +
         "/wings/flat_plate.toml\"\n"
         "[kinematics]\nfrequency_hz = 26.1\n"
         "sweep = { mean_deg = 10.0, cos_deg = [50.0] }\n"
         "rotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"
         "[air]\nfreestream = [0.0, 0.0, 0.0]\n"
         "[structure]\nkind = \"rigid\"\n"
         "[numerics]\nsteps_per_cycle = 24\ncycles = 1\n"
         "chordwise_panels = 3\nspanwise_panels = 4\ncore_radius = 0.2\n[output]\nvtk_every = 0\n";
}

std::string sweep_output(const test::ScratchDir& dir, const std::string& values) {
  std::ofstream(dir / "case.toml") << reference_speed_plate_case();
  EXPECT_EQ(test::run_flapsim("sweep " + (dir / "case.toml").string() + " --vary 'air.freestream[0]=" +
                                  values + "' -j 1 -o " + (dir / "out").string(),
                              dir / "sweep.txt"),
            0);
  return test::read_text(dir / "sweep.txt");
}

TEST(SweepReferenceSpeeds, RowsInHoverAndInAFreeStreamAreNoted) {
  const test::ScratchDir dir("sweep_mixed_reference");
  const std::string text = sweep_output(dir, "0,-3");
  EXPECT_NE(text.find("note: the mean CL and CD of these rows are on different reference speeds (1 row on "
                      "flapping_r2, 1 row on free_stream"),
            std::string::npos)
      << text;
}

TEST(SweepReferenceSpeeds, RowsAllInAFreeStreamAreNotNoted) {
  const test::ScratchDir dir("sweep_one_reference");
  const std::string text = sweep_output(dir, "-2,-3");
  EXPECT_EQ(text.find("different reference speeds"), std::string::npos) << text;
  EXPECT_NE(text.find("table: "), std::string::npos) << text;  // the table was printed
}

}  // namespace sweep_reference_speeds_test
