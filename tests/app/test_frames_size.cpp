// The disk space of a run's ParaView frames (pipeline/app/frames_size.hpp). A run writes a
// frame of the wing, the wake and the structure every `vtk_every` steps (default 1), and the
// wake's frame holds the whole wake: a 48-wingbeat hover of a 60 mm wing at 60 steps a
// wingbeat wrote 2.2 GB with the case's defaults, and neither check nor run said a word
// (the estimate now says ~2.3 GB and warns). Measured against the files runs write.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/app/frames_size.hpp"
#include "pipeline/app/resource_estimate.hpp"
#include "pipeline/io/case_file.hpp"
#include "pipeline/io/free_space.hpp"

namespace {

namespace fs = std::filesystem;
using namespace flapsim;

// A flat plate flapped in hover, 6 x 10 panels, `cycles` wingbeats of 30 steps.
std::string flapped_plate(int cycles, int vtk_every) {
  return "name = \"plate\"\nwing = \"" + std::string(FLAPSIM_SOURCE_DIR) +
         "/wings/flat_plate.toml\"\n"
         "[kinematics]\nfrequency_hz = 26.1\n"
         "sweep = { cos_deg = [50.0] }\nrotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"
         "[structure]\nkind = \"rigid\"\n"
         "[numerics]\nsteps_per_cycle = 30\ncycles = " +
         std::to_string(cycles) +
         "\nchordwise_panels = 6\nspanwise_panels = 10\n[output]\nvtk_every = " + std::to_string(vtk_every) +
         "\n";
}

std::uintmax_t folder_bytes(const fs::path& dir) {
  std::uintmax_t sum = 0;
  for (const auto& f : fs::directory_iterator(dir)) sum += f.file_size();
  return sum;
}

// Source: the files of the run itself. Within 15 %: the frames' compression depends on the
// numbers they hold (the constants were measured on other wings, 4 Dec 2026).
TEST(FramesSize, TheEstimateIsTheSizeOfTheFramesTheRunWrites) {
  const test::ScratchDir dir("frames_size_run");
  // A flapped plate with a frame every step and every third; the Robofly revolving with a
  // shed leading edge (the wake's frames hold the sheet's rings), every step.
  std::ofstream(dir / "plate.toml") << flapped_plate(4, 1);
  const std::string robofly = std::string(FLAPSIM_SOURCE_DIR) + "/cases/robofly_revolving.toml";
  for (const auto& [case_file, every] :
       {std::pair{(dir / "plate.toml").string(), 1}, {(dir / "plate.toml").string(), 3}, {robofly, 1}}) {
    const fs::path out = dir / ("out_" + fs::path(case_file).stem().string() + std::to_string(every));
    ASSERT_EQ(test::run_flapsim("run '" + case_file + "' --vtk-every " + std::to_string(every) + " -o '" +
                                out.string() + "'"),
              0)
        << case_file;
    const double written = static_cast<double>(folder_bytes(out / "vtk"));
    io::Case c = io::load_case_file(case_file);
    const double estimated = app::frames_bytes(c, every, 0);
    EXPECT_NEAR(estimated / written, 1.0, 0.15) << case_file << ", vtk_every " << every << ": " << estimated
                                                << " B estimated, " << written << " B written";
    // The estimate's line counts them with the case's own interval.
    c.output.vtk_every = every;
    EXPECT_EQ(app::estimate_run(c, 1).frames_bytes, estimated);
  }
}

// The interval a warning names, from its text.
int named_interval(const std::string& warning) {
  const auto at = warning.find("vtk_every = ");
  return at == std::string::npos ? -1 : std::stoi(warning.substr(at + 12));
}

TEST(FramesSize, ALongRunsFramesAreWarnedWithTheIntervalThatKeepsThemUnderAGigabyte) {
  const test::ScratchDir dir("frames_size_warning");
  // 6000 steps: the wake's frames grow to 60 000 rings.
  std::ofstream(dir / "long.toml") << flapped_plate(200, 1);
  io::Case c = io::load_case_file((dir / "long.toml").string());
  ASSERT_GT(app::frames_bytes(c, 1, 0), 5e9);  // about 50 B a ring: 6000 frames of 30 000 rings on average
  const std::string w = app::frames_size_warning(c, 0, std::nullopt);
  const int every = named_interval(w);
  ASSERT_GT(every, 1) << w;
  EXPECT_LE(app::frames_bytes(c, every, 0), app::kLargeFramesBytes) << w;
  EXPECT_GT(app::frames_bytes(c, every / 2, 0), app::kLargeFramesBytes) << w;  // not far more than needed
  // A short run's, no warning; more than the disk has, said so, with an interval that fills
  // at most half of it.
  std::ofstream(dir / "short.toml") << flapped_plate(4, 1);
  const io::Case s = io::load_case_file((dir / "short.toml").string());
  EXPECT_EQ(app::frames_size_warning(s, 0, std::nullopt), "");
  const std::string full = app::frames_size_warning(s, 0, 1e6);
  EXPECT_NE(full.find("more than the 1 MB free where the run writes"), std::string::npos) << full;
  EXPECT_LE(app::frames_bytes(s, named_interval(full), 0), 0.5e6) << full;
  // None written (vtk_every = 0, or run --vtk-every 0), none warned.
  c.output.vtk_every = 0;
  EXPECT_EQ(app::frames_bytes(c, 0, 0), 0.0);
  EXPECT_EQ(app::frames_size_warning(c, 0, std::nullopt), "");
  // check says it, beside the estimate.
  const auto outcome =
      test::run_flapsim_capturing_stderr(dir.path(), "check '" + (dir / "long.toml").string() + "'");
  EXPECT_EQ(outcome.status, 0) << outcome.err;
  EXPECT_NE(outcome.err.find("the run's ParaView frames will take about"), std::string::npos) << outcome.err;
}

// The space left where a run writes, for an output folder not made yet: its nearest existing
// parent's (source: std::filesystem::space of that folder, asked again; the two calls a moment
// apart agree within 1 %).
TEST(FramesSize, TheFreeSpaceOfAFolderNotMadeYetIsItsParentsFileSystems) {
  const test::ScratchDir dir("frames_size_free_space");
  const std::optional<double> free = io::free_bytes_where(dir / "not" / "made" / "yet");
  ASSERT_TRUE(free.has_value());
  EXPECT_NEAR(*free / static_cast<double>(fs::space(dir.path()).available), 1.0, 0.01);
}

}  // namespace
