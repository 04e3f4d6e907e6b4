// A wing that moves trailing edge first is warned (pipeline/app/trailing_edge_first_warning.hpp;
// docs/kinematics.md, "Which edge leads"). Until 3 Dec the Robofly case at rotation 160° (a
// plate revolving trailing edge first) ran without a word to CL +1.64, CD −0.60 and a
// negative aerodynamic power with leading_edge = "none": the lattice sheds at the wing
// file's trailing edge, which there leads.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "common/scratch_dir.hpp"
#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/app/setup_warnings.hpp"
#include "pipeline/app/trailing_edge_first_warning.hpp"
#include "pipeline/io/case_file.hpp"

namespace trailing_edge_first_test {

using flapsim::test::ScratchDir;

std::string shipped(const std::string& name) {
  std::ifstream in(std::string(FLAPSIM_SOURCE_DIR) + "/cases/" + name);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A shipped case's text with `from` replaced by `to` (once), its wing path made absolute.
flapsim::io::Case edited(const ScratchDir& dir, const std::string& name, const std::string& from,
                         const std::string& to) {
  std::string text = shipped(name);
  if (!from.empty()) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  const std::string wing = "wing = \"../wings/";
  if (const auto at = text.find(wing); at != std::string::npos)
    text.replace(at, wing.size(), "wing = \"" FLAPSIM_SOURCE_DIR "/wings/");
  const auto file = dir / name;
  std::ofstream(file) << text;
  return flapsim::io::load_case_file(file.string());
}

double share_of(const flapsim::io::Case& c) {
  return flapsim::app::trailing_edge_first_share(c, flapsim::app::build_fsi_setup(c, {}));
}

TEST(TrailingEdgeFirstWarning, APlateRevolvingAt160DegreesIsWarnedAndAt20Not) {
  // The Robofly case revolves at a constant rate: its angle of attack is the rotation
  // throughout, so the share is 1 at 160° (every sample beyond 90°) and 0 at 20°.
  ScratchDir dir("trailing_edge_first_revolving");
  const auto back = edited(dir, "robofly_revolving.toml", "rotation = 50.0", "rotation = 160.0");
  const auto setup = flapsim::app::build_fsi_setup(back, {});
  EXPECT_DOUBLE_EQ(flapsim::app::trailing_edge_first_share(back, setup), 1.0);
  const std::string w = flapsim::app::trailing_edge_first_warning(back, setup);
  EXPECT_NE(w.find("trailing edge first for 100 % of its last wingbeat"), std::string::npos) << w;
  EXPECT_NE(w.find("kinematics.rotation"), std::string::npos) << w;
  bool listed = false;
  for (const std::string& s : flapsim::app::setup_warnings(back, setup)) listed = listed || s == w;
  EXPECT_TRUE(listed);
  const auto front = edited(dir, "robofly_revolving.toml", "rotation = 50.0", "rotation = 20.0");
  EXPECT_DOUBLE_EQ(share_of(front), 0.0);
}

TEST(TrailingEdgeFirstWarning, TheHoversRotationPhasesAndAStreamThatOutrunsTheBackstrokeAreNotWarned) {
  // The rotation-phase study's extremes: the wing flips early or late, trailing edge first
  // around the reversals. By hand (φ = 10° + 50° cos 2π(s + δψ), α = 90° − 45° sin 2πs,
  // the geometric angle α on the downstroke and 180° − α on the upstroke, weighted by φ̇²,
  // 7200 samples): 0.306 at δψ = −0.20, 0.049 at +0.10, 0 at 0. A share, not a majority:
  // not warned. Lua et al.'s hover: 0. The hawkmoth's stroke in a 10 m/s stream along the
  // stroke plane (docs/case_file.md: −135° at mid-upstroke, the stream outrunning the
  // backstroke): a share, 0.2–0.3, not warned either.
  ScratchDir dir("trailing_edge_first_hover");
  for (const auto& [phase, expected] : {std::pair{"-0.20", 0.306}, {"0.10", 0.049}, {"0.0", 0.0}}) {
    const auto c = edited(dir, "rotation_phase_rigid.toml", "rotation_phase = 0.0",
                          std::string("rotation_phase = ") + phase);
    const auto setup = flapsim::app::build_fsi_setup(c, {});
    EXPECT_NEAR(flapsim::app::trailing_edge_first_share(c, setup), expected, 0.003)
        << "rotation phase " << phase;
    EXPECT_EQ(flapsim::app::trailing_edge_first_warning(c, setup), "") << "rotation phase " << phase;
  }
  EXPECT_EQ(share_of(edited(dir, "lua_rigid.toml", "", "")), 0.0);
  const auto stream = edited(dir, "rotation_phase_rigid.toml", "freestream = [0.0, 0.0, 0.0]",
                             "freestream = [-10.0, 0.0, 0.0]");
  const double share = share_of(stream);
  std::printf("[ value ] the hover's stroke in a 10 m/s stream: trailing edge first for %.3f\n", share);
  EXPECT_GT(share, 0.2);
  EXPECT_LT(share, flapsim::app::kTrailingEdgeFirstShare);
}

TEST(TrailingEdgeFirstWarning,
     AHoverWhoseRotationIsWrittenAboutZeroFliesItsUpstrokeTrailingEdgeFirstAndIsWarned) {
  // Lua et al.'s stroke (φ = 60° cos 2πft) with the rotation written about 0° instead of 90°
  // (α = 60° sin 2πft): on the downstroke (φ̇ < 0) the geometric angle is α, 0…60°, leading
  // edge first; on the upstroke it is 180° − α, 180…240°, trailing edge first throughout. The
  // stroke is symmetric, so by hand the share is exactly 1/2 (the φ̇²-weighted samples of the
  // upstroke); until 4 Dec the bound was "more than half" and this ran without a word.
  ScratchDir dir("trailing_edge_first_about_zero");
  const auto c = edited(dir, "lua_rigid.toml", "rotation = { mean_deg = 90.0, sin_deg = [-60.0] }",
                        "rotation = { mean_deg = 0.0, sin_deg = [60.0] }");
  const auto setup = flapsim::app::build_fsi_setup(c, {});
  EXPECT_NEAR(flapsim::app::trailing_edge_first_share(c, setup), 0.5, 1e-9);
  const std::string w = flapsim::app::trailing_edge_first_warning(c, setup);
  EXPECT_NE(w.find("trailing edge first for 50 % of its last wingbeat"), std::string::npos) << w;
  // The same stroke written about 90° (the shipped case): 0, not warned.
  const auto right = edited(dir, "lua_rigid.toml", "", "");
  EXPECT_EQ(flapsim::app::trailing_edge_first_warning(right, flapsim::app::build_fsi_setup(right, {})), "");
}

TEST(TrailingEdgeFirstWarning, AWingSetAt90DegreesMovesBroadsideAndIsNotWarned) {
  // The MAV film wing's root stands at 90° (its film twists to the angle it flies at): its
  // angle is 90° to round-off at every sample, which counted half the samples until the
  // 1e-6 rad margin.
  ScratchDir dir("trailing_edge_first_broadside");
  EXPECT_EQ(share_of(edited(dir, "mav_film_wing.toml", "", "")), 0.0);
}

}  // namespace trailing_edge_first_test
