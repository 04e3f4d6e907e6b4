// A free stream close to the vertical (a climb or a descent): lift is taken normal to the
// stream in the vertical plane through it and drag along it, so the force that holds the wing
// up is reported as drag. A user's hover with freestream = [-0.01, 0, -1] (0.57° off the
// vertical) reported a drag of −5.3 mN and a lift of 0.17 mN for an upward force of 5.31 mN,
// without a word (pipeline/app/steep_stream_warning.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/app/steep_stream_warning.hpp"

using namespace flapsim;

namespace {

io::Case case_in_stream(const Eigen::Vector3d& u) {
  io::Case c;
  c.air.enabled = true;
  c.air.freestream = u;
  return c;
}

}  // namespace

TEST(SteepStreamWarning, AStreamWithinTenDegreesOfTheVerticalIsWarned) {
  // atan(0.01 / 1) = 0.573°: a climb (the air falls past the wing), the up-force a negative drag.
  const std::string climb = app::steep_stream_warning(case_in_stream({-0.01, 0.0, -1.0}));
  EXPECT_NE(
      climb.find("the free stream is 0.57 deg from the vertical (a climb: the air falls past the wing)"),
      std::string::npos)
      << climb;
  EXPECT_NE(climb.find("reported as negative drag"), std::string::npos) << climb;
  EXPECT_NE(climb.find("mean_Fz_N"), std::string::npos) << climb;
  // A descent: the air rises past the wing, the up-force a positive drag.
  EXPECT_NE(app::steep_stream_warning(case_in_stream({0.0, 0.1, 1.0})).find("descent"), std::string::npos);
  // 10° is the limit: atan(0.18) = 10.2° is not warned, atan(0.17) = 9.65° is.
  EXPECT_EQ(app::steep_stream_warning(case_in_stream({0.18, 0.0, -1.0})), "");
  EXPECT_NE(app::steep_stream_warning(case_in_stream({0.17, 0.0, -1.0})), "");
  // Forward flight, hover, vacuum: nothing.
  EXPECT_EQ(app::steep_stream_warning(case_in_stream({-2.5, 0.0, 0.0})), "");
  EXPECT_EQ(app::steep_stream_warning(case_in_stream({0.0, 0.0, 0.0})), "");
  io::Case vacuum = case_in_stream({-0.01, 0.0, -1.0});
  vacuum.air.enabled = false;
  EXPECT_EQ(app::steep_stream_warning(vacuum), "");
}

TEST(SteepStreamWarning, CheckSaysItAndAVerticalStreamIsRefusedWithTheWayOut) {
  test::ScratchDir dir("steep_stream");
  const std::string source = FLAPSIM_SOURCE_DIR;
  std::string text = test::read_text(source + "/tests/data/valid_tiny_case.toml");
  text.replace(text.find("valid_tiny_wing.toml"), 20, source + "/tests/data/valid_tiny_wing.toml");
  std::ofstream(dir / "steep.toml") << text << "\n[air]\nfreestream = [-0.01, 0.0, -1.0]\n";
  const auto steep = test::run_flapsim_capturing_stderr(dir.path(), "check " + (dir / "steep.toml").string());
  EXPECT_EQ(steep.status, 0) << steep.err;
  EXPECT_NE(steep.err.find("warning: the free stream is 0.57 deg from the vertical"), std::string::npos)
      << steep.err;
  std::ofstream(dir / "vertical.toml") << text << "\n[air]\nfreestream = [0.0, 0.0, -1.0]\n";
  const auto vertical =
      test::run_flapsim_capturing_stderr(dir.path(), "check " + (dir / "vertical.toml").string());
  EXPECT_EQ(vertical.status, 2) << vertical.err;
  EXPECT_NE(vertical.err.find("air.freestream"), std::string::npos) << vertical.err;
  EXPECT_NE(vertical.err.find("read the vertical force, summary.json's mean_Fz_N"), std::string::npos)
      << vertical.err;
}
