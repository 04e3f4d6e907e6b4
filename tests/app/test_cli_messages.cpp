// Messages a user reads when something goes wrong.
// - A run that fails names the step as the progress line and history.csv count it. Before:
//   after "step 51/80" and 51 rows of history.csv the message said "step 51 (t = 0.065 s):
//   multibody step 51 (t = 0.065 s): ..." for the 52nd step (0-based, and twice).
// - A numeric option out of range says so in one short line. Before: `--threads 0` printed
//   "Value 0 not in range 0.000000 to 179769313486231570814527423731704356798070567525844996…"
//   (DBL_MAX written out, 300 digits). The exit status stays 1 (a malformed option is a
//   usage error, test_threads_option.cpp).
// - A chain that misses the FEM's first modes by more than 10 % gets a warning. Before:
//   only the numbers on the summary line (an aspect-ratio-0.17 plate: -24 % / -26 %, exit 0).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "robustness_helpers.hpp"

using namespace flapsim::test;

namespace {

long json_integer(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\": ");
  return at == std::string::npos ? -1 : std::strtol(json.c_str() + at + key.size() + 4, nullptr, 10);
}

TEST(CliMessages, AFailedRunNamesTheStepAsTheProgressLineCountsIt) {
  // The diverging two-body chain of ExitStatus.ThreeForANumericalFailureOfTheRun.
  ScratchDir dir("message_step");
  std::ofstream(dir / "chain.toml")
      << kDivergingTwoBodyChain;
  std::ofstream(dir / "case.toml")
      << replace_once(small_plate_case("flexible", 40, 0), "steps_per_cycle = 24", "steps_per_cycle = 4");
  const FlapsimOutcome r = run_flapsim_capturing_stderr(dir.path(), "run " + (dir / "case.toml").string() + " --chain " +
                                                 (dir / "chain.toml").string() + " -o " + (dir / "out").string());
  ASSERT_EQ(r.status, 3) << r.err;
  const std::string summary = read_text(dir / "out" / "summary.json");
  const long done = json_integer(summary, "steps");
  const std::string history = read_text(dir / "out" / "history.csv");
  EXPECT_EQ(static_cast<long>(std::count(history.begin(), history.end(), '\n')) - 1, done);
  const std::string failing = "step " + std::to_string(done + 1) + " (to t = ";
  EXPECT_NE(r.err.find(failing), std::string::npos) << r.err;
  EXPECT_NE(summary.find(failing), std::string::npos) << summary;
  EXPECT_EQ(r.err.find("multibody step"), std::string::npos) << "the step named twice: " << r.err;
}

TEST(CliMessages, AnOptionValueOutOfRangeGetsAShortMessage) {
  ScratchDir dir("message_option");
  const std::string wing = kSourceDir + "/tests/data/valid_tiny_wing.toml";
  for (const std::string& bad : {std::string("--threads 0"), std::string("--threads two")}) {
    const FlapsimOutcome r = run_flapsim_capturing_stderr(dir.path(), "check " + wing + " " + bad);
    EXPECT_EQ(r.status, 1) << bad;
    EXPECT_NE(r.err.find("not a whole number from 1 to 4096"), std::string::npos) << bad << ": " << r.err;
    EXPECT_LT(r.err.size(), 200u) << bad << ": " << r.err;
  }
  const FlapsimOutcome s = run_flapsim_capturing_stderr(dir.path(), "run " + kSourceDir + "/tests/data/valid_tiny_case.toml --spring-scale -1 -o " +
                                                 (dir / "out").string());
  EXPECT_EQ(s.status, 1);
  EXPECT_NE(s.err.find("'-1' is not a number > 0"), std::string::npos) << s.err;
  EXPECT_LT(s.err.size(), 200u) << s.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

TEST(CliMessages, AnUnknownCommandIsNamedWithTheCommandsThereAre) {
  // Before: "A subcommand is required", as if none had been given.
  ScratchDir dir("message_command");
  const FlapsimOutcome r = run_flapsim_capturing_stderr(dir.path(), "bogus");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("unknown command 'bogus'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("check, mesh, modes, reduce, run, sweep, optimize"), std::string::npos) << r.err;
  EXPECT_EQ(run_flapsim_capturing_stderr(dir.path(), "--version").status, 0);
}

TEST(CliMessages, AChainThatMissesTheFemIsWarnedAbout) {
  // The first MAV film wing (25 um film) with 4 bodies: first bending +132 % (MAC-paired) (docs/reduction.md, "Film wings").
  ScratchDir dir("message_mismatch");
  const FlapsimOutcome mav = run_flapsim_capturing_stderr(dir.path(), "reduce " + kSourceDir + "/wings/mav_film_wing_25um.toml --bodies 4 --modes 6 -o " +
                                                   (dir / "mav").string());
  EXPECT_EQ(mav.status, 0);
  EXPECT_NE(mav.err.find("warning: the chain's first bending mode differs from the FEM's by +1"), std::string::npos)
      << mav.err;
  // A plate whose first modes the chain follows (-3 % / -1 %): no mode warning. (Its static rows,
  // 2 bodies over a 10 mm plate with the loaded tip zone inside the measured body, miss by
  // -11 % (the bending rotation conjugate to a moment on the tip body; -44 % when it was read at
  // the measured body) / +65 % and are warned about on their own: test_static_mismatch_warning.cpp.)
  const FlapsimOutcome tiny = run_flapsim_capturing_stderr(dir.path(), "reduce " + kSourceDir + "/tests/data/valid_tiny_wing.toml --bodies 2 "
                                                    "--modes 4 -o " + (dir / "tiny").string());
  EXPECT_EQ(tiny.status, 0);
  EXPECT_EQ(tiny.err.find("mode differs"), std::string::npos) << tiny.err;
}

TEST(CliMessages, ChainAndSpringOptionsOfARigidCaseAreSaidToBeUnused) {
  // Before: `run RIGID.toml --chain chain.toml --spring-scale 2` ran the rigid wing without a word.
  ScratchDir dir("message_rigid_options");
  std::ofstream(dir / "case.toml") << small_plate_case("rigid", 1, 0);
  std::ofstream(dir / "chain.toml") << "[[bodies]]\nlength = 0.04\nmass = 1e-5\ncenter_of_mass = [0, 0.02, 0]\n"
                                       "inertia = [[1e-9,0,0],[0,1e-10,0],[0,0,1e-9]]\n";
  const FlapsimOutcome r = run_flapsim_capturing_stderr(dir.path(), "run " + (dir / "case.toml").string() + " --chain " +
                                                 (dir / "chain.toml").string() + " --spring-scale 2 -o " +
                                                 (dir / "out").string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("warning: --chain"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("warning: --spring-scale is not used"), std::string::npos) << r.err;
  // Unused, they are no part of the run: its inputs hash and summary.json are those of the
  // run without them (they changed the hash, so a sweep or optimisation keyed on it took the
  // same run for another).
  ASSERT_EQ(run_flapsim("run " + (dir / "case.toml").string() + " -q -o " + (dir / "plain").string()), 0);
  const std::string with = read_text(dir / "out" / "summary.json"),
                    without = read_text(dir / "plain" / "summary.json");
  const auto hash = [](const std::string& json) {
    const std::size_t at = json.find("\"inputs_hash\"");
    return at == std::string::npos ? std::string() : json.substr(at, 90);
  };
  EXPECT_FALSE(hash(with).empty()) << with;
  EXPECT_EQ(hash(with), hash(without));
  EXPECT_EQ(flapsim::test::json_number(with, "spring_scale"), 1.0);
}

}  // namespace

namespace {

TEST(CliMessages, ACouplingThatDoesNotConvergeShowsItsChangeAndTolerance) {
  // One sub-iteration per step never converges (the first iterate always moves the
  // structure; SweepRuns.NumericalFailureIsRecordedAndTheOthersGoOn). Before, the message
  // wrote both numbers with six decimals: "structure change 0.000001 rad, tolerance
  // 0.000001" for the 25 um MAV film wing, "tolerance 0.000000" for a tolerance of 1e-9.
  ScratchDir dir("message_coupling");
  std::ofstream(dir / "case.toml")
      << small_plate_case("flexible", 1, 0, "max_coupling_iterations = 1\ncoupling_tolerance = 1e-9\n");
  const FlapsimOutcome r = run_flapsim_capturing_stderr(dir.path(), "run " + (dir / "case.toml").string() + " -o " + (dir / "out").string());
  ASSERT_EQ(r.status, 3) << r.err;
  EXPECT_NE(r.err.find("did not converge in 1 sub-iterations"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("tolerance 1e-09)"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("0.000000"), std::string::npos) << r.err;
}

}  // namespace
