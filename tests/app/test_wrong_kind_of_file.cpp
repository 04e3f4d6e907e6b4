// A wing, case or chain file given where another kind belongs (a new user's slip: `flapsim run
// wings/flat_plate.toml`). Before: the file's tables were listed as unknown keys of the kind
// expected — "flat_plate.toml:14: key 'materials': unknown key (a typo?); expected one of: name,
// ..., kinematics, ..." — as if the user had mistyped a key. Now each loader names the kind of
// file it was given and what takes it; exit status 2, nothing written.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "robustness_helpers.hpp"

using namespace flapsim::test;

namespace {

TEST(WrongKindOfFile, EachLoaderNamesTheKindItWasGiven) {
  ScratchDir dir("wrong_kind");
  const std::string wing = kSourceDir + "/wings/flat_plate.toml", case_file = kSourceDir + "/cases/hover.toml",
                    chain = kSourceDir + "/cases/chains/three_body.toml", out = (dir / "out").string();
  struct Expected {
    std::string args, message;
  };
  const Expected expected[] = {
      {"run " + wing + " -o " + out, "this is a wing file (it has [planform]), not a case file"},
      {"sweep " + wing + " --vary kinematics.rotation_phase=0,0.1 -o " + out,
       "this is a wing file (it has [planform]), not a case file"},
      {"run " + chain + " -o " + out, "this is a chain file (it has [[bodies]]"},
      {"reduce " + case_file + " -o " + out, "this is a case file (it has [kinematics]), not a wing file (no "
                                             "[planform]): its wing is ../wings/hawkmoth.toml"},
      {"mesh " + chain + " -o " + out, "this is a chain file (it has [[bodies]]"},
      {"run " + case_file + " --chain " + wing + " -o " + out, "this is a wing file (it has [planform]), not a "
                                                               "chain file"},
      {"check " + chain, "a chain file (it has [[bodies]]): check reads wing and case files"},
  };
  for (const Expected& e : expected) {
    const FlapsimOutcome r = run_flapsim_capturing_stderr(dir.path(), e.args);
    EXPECT_EQ(r.status, 2) << e.args << "\n" << r.err;
    EXPECT_NE(r.err.find(e.message), std::string::npos) << e.args << "\n" << r.err;
    EXPECT_EQ(r.err.find("unknown key"), std::string::npos) << e.args << "\n" << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "out")) << "nothing written";
}

}  // namespace
