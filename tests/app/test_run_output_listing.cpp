// What a run says of its outputs, found by a user's own wings (6 Dec): the report's list of
// files left out the markers' paths (README and docs/output_files.md list
// marker_<k>_path.vtp); --vtk-every beyond the run's steps wrote a series of step 0 alone,
// the wing at rest, without a word; and -o naming an existing file said "cannot create
// directory: Not a directory".
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

using namespace flapsim;

namespace {

const std::string kTinyCase =
    std::string(FLAPSIM_SOURCE_DIR) + "/tests/data/valid_tiny_case.toml";  // 40 steps, 1 marker

// The report's stdout of `flapsim run ARGS`, and its exit status.
std::string run_report(const test::ScratchDir& dir, const std::string& args, int* status) {
  *status = test::run_flapsim(args, dir / "report.txt");
  return test::read_text(dir / "report.txt");
}

}  // namespace

TEST(RunOutputListing, TheReportNamesTheMarkersPaths) {
  test::ScratchDir dir("run_output_markers");
  int status = -1;
  const std::string report =
      run_report(dir, "run " + kTinyCase + " --vtk-every 10 -o " + (dir / "out").string(), &status);
  ASSERT_EQ(status, 0) << report;
  ASSERT_TRUE(std::filesystem::exists(dir / "out" / "marker_1_path.vtp"));
  EXPECT_NE(report.find("tip_path.vtp, marker_1_path.vtp)"), std::string::npos) << report;
}

TEST(RunOutputListing, AFrameIntervalBeyondTheRunIsWarned) {
  test::ScratchDir dir("run_output_interval");
  const std::string warning =
      "flapsim: warning: [output] vtk_every = 50 is more than the run's 40 steps: the ParaView "
      "series holds step 0 alone";
  const auto run = test::run_flapsim_capturing_stderr(
      dir.path(), "run " + kTinyCase + " -q --vtk-every 50 -o " + (dir / "out").string());
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.err.find(warning), std::string::npos) << run.err;
  // The summary keeps it among the run's warnings (up to the first colon).
  EXPECT_NE(
      test::read_text(dir / "out" / "summary.json").find("vtk_every = 50 is more than the run's 40 steps"),
      std::string::npos);
  // 40 steps, a frame every 40: step 0 and step 40, nothing said.
  const auto every_40 = test::run_flapsim_capturing_stderr(
      dir.path(), "run " + kTinyCase + " -q --vtk-every 40 -o " + (dir / "out40").string());
  ASSERT_EQ(every_40.status, 0) << every_40.err;
  EXPECT_EQ(every_40.err.find("vtk_every"), std::string::npos) << every_40.err;
  // check reads the case's own value.
  std::string text = test::read_text(kTinyCase);
  text.replace(text.find("valid_tiny_wing.toml"), 20,
               std::string(FLAPSIM_SOURCE_DIR) + "/tests/data/valid_tiny_wing.toml");
  std::ofstream(dir / "case.toml") << text << "\n[output]\nvtk_every = 50\n";
  const auto check = test::run_flapsim_capturing_stderr(dir.path(), "check " + (dir / "case.toml").string());
  EXPECT_EQ(check.status, 0) << check.err;
  EXPECT_NE(check.err.find(warning), std::string::npos) << check.err;
}

TEST(RunOutputListing, AnOutputThatIsAFileIsNamedAsSuch) {
  test::ScratchDir dir("run_output_file");
  std::ofstream(dir / "afile.txt") << "mine\n";
  const auto out = test::run_flapsim_capturing_stderr(
      dir.path(), "run " + kTinyCase + " -q -o " + (dir / "afile.txt").string());
  EXPECT_EQ(out.status, 4) << out.err;
  EXPECT_NE(out.err.find("exists and is not a directory"), std::string::npos) << out.err;
  EXPECT_EQ(test::read_text(dir / "afile.txt"), "mine\n");
}
