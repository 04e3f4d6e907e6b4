// A run too large for the memory names the key that makes it so. A 400 x 400 lattice of
// 2 cycles needs 2 x 160000^2 x 8 B = 410 GB for its influence matrix and LU alone
// (resource_estimate.cpp), whatever the run's length; before, the error named
// numerics.cycles and advised a shorter run or a bounded wake.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "sweep_test_helpers.hpp"

using namespace flapsim;

TEST(MemoryRefusal, ALatticeTooLargeForTheMemoryNamesThePanels) {
  test::ScratchDir dir("memory_refusal");
  std::string text = test::tiny_plate_case(24);
  const std::string small = "chordwise_panels = 3\nspanwise_panels = 4";
  text.replace(text.find(small), small.size(), "chordwise_panels = 400\nspanwise_panels = 400");
  std::ofstream(dir / "case.toml") << text;
  const auto out = test::run_flapsim_capturing_stderr(dir.path(), "check " + (dir / "case.toml").string());
  EXPECT_EQ(out.status, 2) << out.err;
  // The case's lines: name, wing, [kinematics] + 4, [structure], kind, [numerics], steps,
  // cycles, chordwise (13), spanwise (14).
  EXPECT_NE(out.err.find("case.toml:14: key 'numerics.spanwise_panels': the run needs about "), std::string::npos)
      << out.err;
  EXPECT_NE(out.err.find("of it the lattice of 400 x 400 panels needs 410 GB"), std::string::npos) << out.err;
}
