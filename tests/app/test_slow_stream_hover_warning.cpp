// A flapping wing in a free stream too slow to carry its wake away meets it as in hover
// (pipeline/app/slow_stream_hover_warning.hpp; docs/uvlm.md, "Hover over many cycles"): with
// the whole wake free, a free stream's default, its later cycles grow erratic. Until 4 Dec a
// 0.02 m/s stream made a hover a forward flight with the whole wake free and no word.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/app/slow_stream_hover_warning.hpp"
#include "pipeline/io/case_file.hpp"

namespace {

using namespace flapsim::test;

const std::string kSource = FLAPSIM_SOURCE_DIR;

/// A rigid wings/flat_plate.toml (R = 40 mm, chord 10 mm) swept ±50° at 26.1 Hz in a stream
/// of `stream` m/s along -x, with `numerics` in its [numerics] table.
std::string plate_text(const std::string& stream, const std::string& numerics) {
  return "name = \"plate\"\nwing = \"" + kSource +
         "/wings/flat_plate.toml\"\n[kinematics]\nfrequency_hz = 26.1\nsweep = { mean_deg = 10.0, cos_deg = "
         "[50.0] "
         "}\nrotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n[structure]\nkind = "
         "\"rigid\"\n[air]\nfreestream = [-" +
         stream + ", 0.0, 0.0]\n[numerics]\n" + numerics;
}

std::string warning_for(const ScratchDir& dir, const std::string& stream, const std::string& numerics,
                        double* chords = nullptr) {
  const auto file = dir / "plate.toml";
  std::ofstream(file) << plate_text(stream, numerics);
  const flapsim::io::Case c = flapsim::io::load_case_file(file.string());
  const flapsim::app::FsiSetup setup = flapsim::app::build_fsi_setup(c, {});
  if (chords) *chords = flapsim::app::wake_travel_per_half_stroke_chords(c, setup);
  return flapsim::app::slow_stream_hover_warning(c, setup);
}

}  // namespace

// By hand: U∞ T/2 = 0.1 m/s × 0.5/26.1 s = 1.9157 mm = 0.19157 of the 10 mm chord. The
// limit, one chord, is a stream of 2 × 26.1 Hz × 10 mm = 0.522 m/s.
TEST(SlowStreamHoverWarning, AStreamThatCarriesTheWakeLessThanAChordAHalfStrokeIsWarned) {
  const ScratchDir dir("slow_stream_hover");
  double chords = 0.0;
  const std::string w = warning_for(dir, "0.1", "cycles = 3\n", &chords);
  EXPECT_NEAR(chords, 0.1 * 0.5 / 26.1 / 0.01, 1e-9);
  EXPECT_NE(w.find("carries the wake 0.19 mean chords in a half stroke"), std::string::npos) << w;
  EXPECT_NE(w.find("plate.toml:"), std::string::npos) << w;
  EXPECT_NE(w.find("key 'numerics.far_wake_cycles'"), std::string::npos) << w;
  EXPECT_NE(w.find("set far_wake_cycles = 0.5"), std::string::npos) << w;
  EXPECT_NE(warning_for(dir, "0.52", "cycles = 3\n"), "");
  EXPECT_EQ(warning_for(dir, "0.53", "cycles = 3\n"), "");
  EXPECT_EQ(warning_for(dir, "5.0", "cycles = 3\n"), "");
}

TEST(SlowStreamHoverWarning, AFarWakeOneCycleOrAStraightWakeIsNotWarned) {
  const ScratchDir dir("slow_stream_hover_not");
  EXPECT_EQ(warning_for(dir, "0.1", "cycles = 3\nfar_wake_cycles = 0.5\n"), "");
  EXPECT_EQ(warning_for(dir, "0.1", "cycles = 1\n"), "");  // it meets its wake once, as a hover's first cycle
  EXPECT_EQ(warning_for(dir, "0.1", "cycles = 3\nwake_max_rows = 40\n"), "");
  EXPECT_EQ(warning_for(dir, "0.1", "cycles = 3\nfree_wake = false\n"), "");
}

TEST(SlowStreamHoverWarning, CheckPrintsIt) {
  const ScratchDir dir("slow_stream_hover_check");
  std::ofstream(dir / "plate.toml") << plate_text("0.02", "cycles = 4\n");
  const auto out = run_flapsim_capturing_stderr(dir.path(), "check " + (dir / "plate.toml").string());
  EXPECT_EQ(out.status, 0);
  EXPECT_NE(out.err.find("carries the wake 0.04 mean chords in a half stroke"), std::string::npos) << out.err;
}
