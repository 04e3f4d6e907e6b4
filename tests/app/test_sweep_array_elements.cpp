// Array elements as varied keys, KEY[i] (docs/sweeps.md, "What can be varied"): the
// amplitudes of a harmonic series (`sweep = { cos_deg = [50.0] }`) for flapsim sweep and
// flapsim optimize, and the refusals of an element that is not there or not a number.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "optimize_test_helpers.hpp"
#include "pipeline/app/sweep/sweep_case.hpp"
#include "sweep_test_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using namespace flapsim;

// tiny_plate_case with its stroke amplitude written as `amplitude` (degrees).
std::string plate_with_stroke(const std::string& amplitude) {
  std::string text = test::tiny_plate_case(12);
  const std::string from = "cos_deg = [50.0]";
  text.replace(text.find(from), from.size(), "cos_deg = [" + amplitude + "]");
  return text;
}

// A varied element gives the case the file would be with that value written in it: the
// same resolved inputs (io::input_hash of every field of the case) and, run, the same lift.
TEST(SweepArrayElements, AVariedAmplitudeIsTheCaseWithThatAmplitudeWritten) {
  const test::ScratchDir dir("sweep_array_elements");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(12);
  std::ofstream(dir / "case40.toml") << plate_with_stroke("40.0");
  const sweep::SweepInputs varied{(dir / "case.toml").string(), "", 1.0, ""};
  const sweep::SweepInputs written{(dir / "case40.toml").string(), "", 1.0, ""};
  const auto by_element = sweep::resolve_case(varied, {{"kinematics.sweep.cos_deg[0]", 40.0}});
  EXPECT_EQ(by_element.inputs_hash, sweep::resolve_case(written, {}).inputs_hash);
  EXPECT_NE(by_element.inputs_hash, sweep::resolve_case(varied, {}).inputs_hash);

  ASSERT_EQ(test::run_flapsim("sweep " + (dir / "case.toml").string() +
                              " --vary 'kinematics.sweep.cos_deg[0]=40,60' -q -o " + (dir / "grid").string()),
            0);
  const auto grid = test::read_sweep_table((dir / "grid" / "sweep.csv").string());
  ASSERT_EQ(grid.rows.size(), 2u);
  EXPECT_EQ(grid.header.front(), "kinematics.sweep.cos_deg[0]");
  ASSERT_EQ(test::run_flapsim("run " + (dir / "case40.toml").string() + " -q -o " + (dir / "run40").string()), 0);
  const std::string summary = test::read_text(dir / "run40" / "summary.json");
  const std::string case40 = test::read_text(dir / "grid" / grid.rows[0].at("folder") / "summary.json");
  EXPECT_EQ(test::summary_value(case40, "inputs_hash"), "\"" + by_element.inputs_hash + "\"");
  EXPECT_EQ(std::stod(grid.rows[0].at("mean_lift_N")), std::stod(test::summary_value(summary, "mean_lift_N")));
  // A larger stroke moves the wing faster: more lift (quasi-steady, lift ~ amplitude^2).
  EXPECT_GT(std::stod(grid.rows[1].at("mean_lift_N")), std::stod(grid.rows[0].at("mean_lift_N")));
}

struct BadElement {
  const char* vary;  // the --vary key
  const char* says;  // what the message says
};

// Out of range, not an array, not a number: exit 2 naming the key, for sweep and optimize,
// nothing written.
TEST(SweepArrayElements, AnElementThatIsNotThereOrNotANumberExitsTwoNamingTheKey) {
  const test::ScratchDir dir("sweep_array_element_errors");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(12);
  const BadElement cases[] = {
      {"kinematics.sweep.cos_deg[1]",
       "'kinematics.sweep.cos_deg' has 1 element (indices from 0): index 1 is out of range"},
      {"kinematics.rotation_phase[0]",
       "'kinematics.rotation_phase' is a floating-point number, not an array"},
      {"kinematics.sweep[0]", "'kinematics.sweep' is a table, not an array"},
      {"wing.planform.outline[0]", "'planform.outline[0]' is an array, not a number"},
      {"wing.planform.outline[4][1]",
       "'planform.outline' has 4 elements (indices from 0): index 4 is out of range"},
      {"kinematics.sweep.cos_deg[x]", "not a dotted key"},
      // A number for the whole array: the message says how to set one of its numbers
      // (until 4 Dec it said only "expected an array of numbers, found an integer").
      {"kinematics.sweep.cos_deg",
       "to set one element of the array give its index, as kinematics.sweep.cos_deg[0]"},
  };
  for (const BadElement& c : cases)
    for (const std::string command : {"sweep", "optimize"}) {
      const fs::path out = dir / "out";
      fs::remove_all(out);
      const std::string vary = std::string(c.vary) + (command == "sweep" ? "=40,60" : "=40:60");
      const auto outcome = test::run_flapsim_capturing_stderr(
          dir.path(), command + " " + (dir / "case.toml").string() + " --vary '" + vary + "'" +
                          (command == "optimize" ? " --maximize mean_lift_N" : "") + " -o " + out.string());
      EXPECT_EQ(outcome.status, 2) << command << " " << vary << "\n" << outcome.err;
      EXPECT_NE(outcome.err.find(c.vary), std::string::npos) << command << " " << vary << "\n" << outcome.err;
      EXPECT_NE(outcome.err.find(c.says), std::string::npos) << command << " " << vary << "\n" << outcome.err;
      EXPECT_FALSE(fs::exists(out)) << command << " " << vary << ": nothing may be written";
    }
}

}  // namespace
