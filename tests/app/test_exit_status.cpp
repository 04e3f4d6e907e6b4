// The exit-status contract (README.md, "Exit status"): one test per status.
// 0 ok, 1 usage, 2 bad input, 3 numerical failure, 4 output or system error,
// 130/143 interrupted (test_run_signals.cpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "robustness_helpers.hpp"

namespace fs = std::filesystem;
using namespace flapsim::test;

namespace {

const std::string kTinyWing = kSourceDir + "/tests/data/valid_tiny_wing.toml";
const std::string kTinyCase = kSourceDir + "/tests/data/valid_tiny_case.toml";

TEST(ExitStatus, ZeroForSuccess) {
  EXPECT_EQ(run_flapsim("check " + kTinyWing), 0);
  EXPECT_EQ(run_flapsim("--help"), 0);
}

TEST(ExitStatus, OneForUsageErrorsOnly) {
  EXPECT_EQ(run_flapsim("run"), 1);                            // missing CASE
  EXPECT_EQ(run_flapsim("check " + kTinyWing + " --bogus"), 1);  // unknown option
  EXPECT_EQ(run_flapsim("frobnicate"), 1);                     // unknown command
}

TEST(ExitStatus, TwoForBadInput) {
  ScratchDir dir("exit_input");
  EXPECT_EQ(run_flapsim("check " + (dir / "missing.toml").string()), 2);
  EXPECT_EQ(run_flapsim("mesh " + (dir / "missing.toml").string() + " -o " + (dir / "out").string()), 2);
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(ExitStatus, ThreeForANumericalFailureOfTheRun) {
  // A two-body chain with almost no joint stiffness and a heavy tip (as in
  // test_run_command.cpp): the implicit step fails and names the step.
  ScratchDir dir("exit_numerical");
  std::ofstream(dir / "chain.toml")
      << kDivergingTwoBodyChain;
  const std::string c = replace_once(small_plate_case("flexible", 40, 0), "steps_per_cycle = 24", "steps_per_cycle = 4");
  std::ofstream(dir / "case.toml") << c;
  const int status = run_flapsim("run " + (dir / "case.toml").string() + " --chain " + (dir / "chain.toml").string() +
                                 " -o " + (dir / "out").string());
  // Deterministic: this chain diverges on every run (measured: exit 3), so anything else fails.
  ASSERT_EQ(status, 3);
  EXPECT_NE(read_text(dir / "out" / "summary.json").find("\"status\": \"failed\""), std::string::npos);
}

TEST(ExitStatus, TwoForAClampOrAMeshThatLeavesNoBeamToReduce) {
  // The tiny wing clamped up to y = 9.6 of its 10 mm: the reduction finds no beam section
  // outside the clamp and the loaded tip zone. That is the wing file's error, named at its
  // clamp_y (line 7), exit 2 with nothing written (it exited 1, the usage status, then 3, a
  // "numerical failure", leaving a folder with only its manifest; docs/reduction.md).
  ScratchDir dir("exit_reduction");
  std::ofstream(dir / "w.toml") << replace_once(read_text(kTinyWing), "clamp_y = 0.0", "clamp_y = 9.6");
  const FlapsimOutcome clamp =
      run_flapsim_capturing_stderr(dir.path(), "reduce " + (dir / "w.toml").string() +
                                                   " --bodies 2 --modes 4 -o " + (dir / "out").string());
  EXPECT_EQ(clamp.status, 2) << clamp.err;
  EXPECT_NE(clamp.err.find("w.toml:7: key 'planform.clamp_y'"), std::string::npos) << clamp.err;
  EXPECT_NE(clamp.err.find("cannot be reduced to a beam"), std::string::npos) << clamp.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
  // Its check warns of the clamp (96 % of the span range held).
  const FlapsimOutcome check = run_flapsim_capturing_stderr(dir.path(), "check " + (dir / "w.toml").string());
  EXPECT_EQ(check.status, 0) << check.err;
  EXPECT_NE(check.err.find("the clamp holds 96 % of the wing's span range"), std::string::npos) << check.err;
  // Elements of 20 mm on its 5 mm chord: the wing file's [mesh] element_size (line 26), the
  // check warning first (the FEM has a handful of nodes).
  std::ofstream(dir / "coarse.toml") << read_text(kTinyWing) << "\n[mesh]\nelement_size = 20.0\n";
  const FlapsimOutcome coarse =
      run_flapsim_capturing_stderr(dir.path(), "reduce " + (dir / "coarse.toml").string() +
                                                   " --bodies 2 --modes 4 -o " + (dir / "out2").string());
  EXPECT_EQ(coarse.status, 2) << coarse.err;
  EXPECT_NE(coarse.err.find("coarse.toml:26: key 'mesh.element_size'"), std::string::npos) << coarse.err;
  EXPECT_NE(coarse.err.find("fewer than two elements across the wing's mean chord"), std::string::npos)
      << coarse.err;
  EXPECT_FALSE(fs::exists(dir / "out2"));
}

TEST(ExitStatus, TwoForACaseWhoseWingReducedInProcessLeavesNoBodyFree) {
  // The tiny case (3 bodies, no chain file) on the tiny wing clamped up to 9.6 of its 10 mm:
  // every body lies inside the clamp. run and check reduce the wing in the setup; they said
  // "numerical failure" (exit 3); it is the wing file's clamp_y (line 7), exit 2, nothing written.
  ScratchDir dir("exit_in_process_clamp");
  std::ofstream(dir / "w.toml") << replace_once(read_text(kTinyWing), "clamp_y = 0.0", "clamp_y = 9.6");
  std::ofstream(dir / "c.toml") << replace_once(read_text(kTinyCase), "wing = \"valid_tiny_wing.toml\"",
                                                "wing = \"w.toml\"");
  for (const std::string& command : {"check " + (dir / "c.toml").string(),
                                     "run " + (dir / "c.toml").string() + " -o " + (dir / "out").string()}) {
    const FlapsimOutcome o = run_flapsim_capturing_stderr(dir.path(), command);
    EXPECT_EQ(o.status, 2) << command << ": " << o.err;
    EXPECT_NE(
        o.err.find("w.toml:7: key 'planform.clamp_y': the wing cannot be reduced to a beam: all 3 bodies lie "
                   "inside the root clamp"),
        std::string::npos)
        << o.err;
  }
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(ExitStatus, FourForAnUnwritableOutputFolderOfEveryCommand) {
  // A regular file where the output folder should be: an output error (4), not blamed on
  // the input file (the issue: mesh blamed the wing file, run exited 1).
  ScratchDir dir("exit_output");
  std::ofstream(dir / "file") << "x\n";
  std::ofstream(dir / "case.toml") << small_plate_case();
  const std::string out = " -o " + (dir / "file" / "sub").string();
  EXPECT_EQ(run_flapsim("mesh " + kTinyWing + out), 4);
  EXPECT_EQ(run_flapsim("modes " + kTinyWing + " --modes 4" + out), 4);
  EXPECT_EQ(run_flapsim("reduce " + kTinyWing + " --bodies 2 --modes 4" + out), 4);
  EXPECT_EQ(run_flapsim("run " + (dir / "case.toml").string() + out), 4);
}

}  // namespace
