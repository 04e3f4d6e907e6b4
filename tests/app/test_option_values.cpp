// Option values a user gets wrong (README, "Exit status": a usage error is status 1, with
// nothing written): an empty -o or --chain (an unset shell variable: `--chain "$CHAIN"` ran the
// wing reduced in process, `-o ""` wrote into out/<case name>), a one-body reduction or mode
// naming (a chain no case can run: a case's structure.bodies is at least 2), and check warns
// about a --chain the case does not use, as run does.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "robustness_helpers.hpp"

namespace fs = std::filesystem;
using namespace flapsim::test;

TEST(OptionValues, EmptyPathsAndAOneBodyReductionAreUsageErrors) {
  ScratchDir dir("option_values");
  const fs::path rigid = dir / "rigid.toml", flexible = dir / "flexible.toml";
  std::ofstream(rigid) << small_plate_case("rigid");
  std::ofstream(flexible) << small_plate_case("flexible");
  const fs::path out = dir / "out";
  EXPECT_EQ(run_flapsim("run " + flexible.string() + " --chain '' -o " + out.string()), 1);
  EXPECT_EQ(run_flapsim("run " + rigid.string() + " -o ''"), 1);
  EXPECT_EQ(run_flapsim("check " + flexible.string() + " --chain ''"), 1);
  EXPECT_EQ(run_flapsim("reduce " + kSourceDir + "/wings/flat_plate.toml -o ''"), 1);
  EXPECT_EQ(run_flapsim("reduce " + kSourceDir + "/wings/flat_plate.toml --bodies 1 -o " + out.string()), 1);
  EXPECT_EQ(run_flapsim("modes " + kSourceDir + "/wings/flat_plate.toml --bodies 1 -o " + out.string()), 1);
  EXPECT_FALSE(fs::exists(out));
}

TEST(OptionValues, CheckWarnsAboutAChainTheCaseDoesNotUseAsRunDoes) {
  ScratchDir dir("option_values_check");
  const fs::path rigid = dir / "rigid.toml";
  std::ofstream(rigid) << small_plate_case("rigid");
  std::ofstream(dir / "chain.toml") << "";  // never read: the case is rigid
  const FlapsimOutcome check =
      run_flapsim_capturing_stderr(dir.path(), "check " + rigid.string() + " --chain " + (dir / "chain.toml").string());
  EXPECT_EQ(check.status, 0) << check.err;
  EXPECT_NE(check.err.find("--chain " + (dir / "chain.toml").string() + " is not used"), std::string::npos) << check.err;
}
