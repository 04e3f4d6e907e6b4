// `flapsim check` of a flexible case whose wing, reduced in process, fails in the numerics
// exits as `flapsim run` does: status 3, "numerical failure". Before, check exited 4
// ("system error") where run exited 3: cmd_check.cpp built the setup without the
// numerical-stage wrapper (pipeline/app/numerical_stage.hpp) that fsi_run.cpp uses.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "robustness_helpers.hpp"

namespace {

using namespace flapsim::test;

TEST(CheckNumericalSetup, CheckExitsThreeWhereRunDoes) {
  ScratchDir dir("check_numerical_setup");
  // tests/data/valid_tiny_wing.toml with its material's Young's modulus at 1e-300 Pa (any
  // positive modulus is accepted): the element stiffnesses underflow, and the clamped FEM's
  // stiffness matrix is numerically not positive definite (CHOLMOD) in the reduction's static
  // solve, a numerical failure of the setup in both commands.
  std::ifstream in(kSourceDir + "/tests/data/valid_tiny_wing.toml");
  std::string wing((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  wing = replace_once(wing, "youngs_modulus = 4.0e9", "youngs_modulus = 1e-300");
  ASSERT_NE(wing.find("1e-300"), std::string::npos);
  std::ofstream(dir / "wing.toml") << wing;
  std::string c = replace_once(small_plate_case("flexible", 1, 0), kSourceDir + "/wings/flat_plate.toml",
                               (dir / "wing.toml").string());
  std::ofstream(dir / "case.toml") << c;
  const FlapsimOutcome run =
      run_flapsim_capturing_stderr(dir.path(), "run " + (dir / "case.toml").string() + " -o " + (dir / "out").string());
  const FlapsimOutcome check = run_flapsim_capturing_stderr(dir.path(), "check " + (dir / "case.toml").string());
  EXPECT_EQ(run.status, 3) << run.err;
  EXPECT_EQ(check.status, 3) << check.err;  // was 4 ("system error") before the fix
  EXPECT_NE(check.err.find("numerical failure: check setup: "), std::string::npos) << check.err;
  EXPECT_NE(check.err.find("not positive definite"), std::string::npos) << check.err;
}

}  // namespace
