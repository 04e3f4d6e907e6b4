// Load and marker points far off the wing (pipeline/app/far_point_warning.hpp): written in
// another unit than the case file's length_unit. Points of [[markers]] are in metres by
// default; a tip marker of the 40 mm plate written [0, 40, 0] (meant in mm) lies 40 m from
// its body, a thousand times the wing's length, and was unwarned until 3 Dec (its path in
// history.csv ran 40 m out).
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include "common/scratch_dir.hpp"
#include "pipeline/app/far_point_warning.hpp"
#include "pipeline/app/setup_warnings.hpp"
#include "pipeline/io/case_file.hpp"

namespace {

using flapsim::test::ScratchDir;

const std::string kFarSource = FLAPSIM_SOURCE_DIR;

// A two-body chain hover of wings/flat_plate.toml (R = 40 mm) in vacuum with `top`-level keys
// and the [[markers]] / [[loads]] tables `tables`.
flapsim::io::Case plate_with(const ScratchDir& dir, const std::string& top, const std::string& tables) {
  const auto file = dir / "plate.toml";
  std::ofstream(file)
      << "name = \"plate\"\n"
      << top << "wing = \"" << kFarSource
      << "/wings/flat_plate.toml\"\nair = \"none\"\n[kinematics]\nfrequency_hz = 26.1\n"
         "sweep = { mean_deg = 10.0, cos_deg = [50.0] }\nrotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"
         "[structure]\nkind = \"flexible\"\n"
         "bodies = 2\n[numerics]\ncycles = 1\n"
      << tables;
  return flapsim::io::load_case_file(file.string());
}

std::vector<std::string> warnings_of(const flapsim::io::Case& c) {
  return flapsim::app::far_point_warnings(c, flapsim::app::build_fsi_setup(c, {}));
}

}  // namespace

TEST(FarPointWarning, AMarkerWrittenInMillimetresInAFileInMetresIsWarned) {
  ScratchDir dir("far_point_marker");
  const auto c = plate_with(dir, "", "[[markers]]\nname = \"tip\"\nbody = 2\npoint = [0.0, 40.0, 0.0]\n");
  const std::vector<std::string> w = warnings_of(c);
  ASSERT_EQ(w.size(), 1u);
  // 40 m against the plate's 40 mm: 1000 times; the case's line 16 is the marker's point.
  EXPECT_NE(
      w[0].find("marker 'tip' lies 40 m from its body's origin, 1e+03 times the wing's length (0.04 m)"),
      std::string::npos)
      << w[0];
  EXPECT_NE(w[0].find("plate.toml:16, key 'markers[0].point'"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("was it written in mm (length_unit = \"mm\")?"), std::string::npos) << w[0];
  // The setup's warnings carry it, its headline naming the key (summary.json's notes).
  const auto all = flapsim::app::setup_warnings(c, flapsim::app::build_fsi_setup(c, {}));
  ASSERT_EQ(std::count(all.begin(), all.end(), w[0]), 1);
  EXPECT_NE(flapsim::app::warning_headline(w[0]).find("markers[0].point"), std::string::npos);
}

TEST(FarPointWarning, PointsOnTheWingInEitherUnitAreNotWarned) {
  ScratchDir dir("far_point_on_wing");
  EXPECT_TRUE(warnings_of(plate_with(dir, "", "[[markers]]\nbody = 2\npoint = [0.0, 0.04, 0.0]\n")).empty());
  EXPECT_TRUE(warnings_of(plate_with(dir, "length_unit = \"mm\"\n",
                                     "[[markers]]\nbody = 2\npoint = [0.0, 40.0, 0.0]\n"))
                  .empty());
  // Twice the wing's length is the limit: 79 mm from body 1's origin is not warned, 81 mm is.
  EXPECT_TRUE(warnings_of(plate_with(dir, "", "[[markers]]\nbody = 1\npoint = [0.0, 0.079, 0.0]\n")).empty());
  EXPECT_EQ(warnings_of(plate_with(dir, "", "[[markers]]\nbody = 1\npoint = [0.0, 0.081, 0.0]\n")).size(),
            1u);
}

TEST(FarPointWarning, ALoadsPointInCentimetresInAFileInMillimetresIsWarned) {
  // 400 in a file in mm is 0.4 m, ten wing lengths: warned, with the unit that would put it
  // on the wing (um: 0.4 mm; the first of m, cm, mm, um that does).
  ScratchDir dir("far_point_load");
  const std::string load =
      "[[loads]]\nbody = 1\nframe = \"body\"\nforce_z = 1e-4\npoint = [0.0, 400.0, 0.0]\n";
  const std::vector<std::string> w = warnings_of(plate_with(dir, "length_unit = \"mm\"\n", load));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(
      w[0].find("the load's point lies 400 mm from its body's origin, 10 times the wing's length (40 mm)"),
      std::string::npos)
      << w[0];
  EXPECT_NE(w[0].find("key 'loads[0].point'"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("was it written in um (length_unit = \"um\")?"), std::string::npos) << w[0];
}
