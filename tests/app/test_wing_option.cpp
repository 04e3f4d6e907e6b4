// `flapsim run CASE --wing WING` (pipeline/app/cli/wing_option.hpp; docs/case_file.md,
// "Another wing for a case"): the case flown with another wing is the case written with that
// wing, into its own default folder; what cannot work is refused naming the key.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "rigid_wingbeat_case.hpp"

namespace {

namespace fs = std::filesystem;
using flapsim::test::json_number;
using flapsim::test::read_text;
using flapsim::test::run_flapsim;
using flapsim::test::run_flapsim_capturing_stderr;
using flapsim::test::write_film_wing;
using flapsim::test::write_rigid_wingbeat_case;

constexpr const char* kRectangle = "outline = [[0, 0], [0, 50], [-15, 50], [-15, 0]]";  // mm
constexpr const char* kTrapezoid = "outline = [[0, 0], [5, 50], [-10, 50], [-15, 0]]";

// DIR/FOLDER/rectangle.toml and trapezoid.toml, and DIR/rectangle_case.toml and
// trapezoid_case.toml flapping each for a rigid wingbeat.
void write_two_wings_and_their_cases(const fs::path& dir, const std::string& folder = "") {
  const fs::path wings = folder.empty() ? dir : dir / folder;
  fs::create_directories(wings);
  write_film_wing(wings / "rectangle.toml", kRectangle);
  write_film_wing(wings / "trapezoid.toml", kTrapezoid);
  const std::string prefix = folder.empty() ? "" : folder + "/";
  write_rigid_wingbeat_case(dir / "rectangle_case.toml", "beat", prefix + "rectangle.toml");
  write_rigid_wingbeat_case(dir / "trapezoid_case.toml", "beat", prefix + "trapezoid.toml");
}

// A rigid wingbeat of a trapezoid flown by a case written for a rectangle: the mean lift of
// the case written with the trapezoid, to the last bit, and not the rectangle's.
TEST(WingOption, ACaseFlownWithAnotherWingIsThatCaseWrittenWithIt) {
  const flapsim::test::ScratchDir dir("wing_option_run");
  write_two_wings_and_their_cases(dir.path(), "wings");
  ASSERT_EQ(run_flapsim("run " + (dir / "rectangle_case.toml").string() + " --wing " +
                        (dir / "wings" / "trapezoid.toml").string() + " -o " + (dir / "o1").string()),
            0);
  ASSERT_EQ(run_flapsim("run " + (dir / "trapezoid_case.toml").string() + " -o " + (dir / "o2").string()), 0);
  ASSERT_EQ(run_flapsim("run " + (dir / "rectangle_case.toml").string() + " -o " + (dir / "o3").string()), 0);
  const std::string flown = read_text(dir / "o1" / "summary.json");
  const double with_option = json_number(flown, "mean_lift_N");
  const double written = json_number(read_text(dir / "o2" / "summary.json"), "mean_lift_N");
  const double rectangle = json_number(read_text(dir / "o3" / "summary.json"), "mean_lift_N");
  EXPECT_GT(written, 0.0);
  EXPECT_EQ(with_option, written);
  EXPECT_GT(std::abs(rectangle - written), 1e-3 * written);  // the option did change the wing
  EXPECT_NE(flown.find("trapezoid.toml\""), std::string::npos) << "summary.json's wing_file";
}

// Without -o the run goes to out/<case name>_<wing file's name>, beside the case's own out/<case name>.
TEST(WingOption, TheDefaultFolderNamesTheCaseAndTheWing) {
  const flapsim::test::ScratchDir dir("wing_option_folder");
  write_film_wing(dir / "my_wing.toml", kTrapezoid);
  write_film_wing(dir / "case_wing.toml", kRectangle);
  write_rigid_wingbeat_case(dir / "beat.toml", "beat", "case_wing.toml");
  ASSERT_EQ(flapsim::test::run_flapsim_in_shell("cd '" + dir.path().string() + "' && exec",
                                                "run beat.toml --wing my_wing.toml -q"),
            0);
  EXPECT_TRUE(fs::exists(dir / "out" / "beat_my_wing" / "summary.json"));
  EXPECT_FALSE(fs::exists(dir / "out" / "beat"));
}

// A case that flies a chain file of its own (reduced from its own wing, or documented, as
// cases/vacuum_flapping.toml's) flies no chain of another wing: --wing needs --chain with it. A missing wing
// file names --wing; --wing of a wing file is a usage error.
TEST(WingOption, WhatCannotWorkIsRefusedNamingTheKey) {
  const flapsim::test::ScratchDir dir("wing_option_refused");
  write_film_wing(dir / "w.toml", kTrapezoid);
  const std::string chain_case = std::string(FLAPSIM_SOURCE_DIR) + "/cases/vacuum_flapping.toml";
  const auto chained =
      run_flapsim_capturing_stderr(dir.path(), "run " + chain_case + " --wing " + (dir / "w.toml").string() +
                                                   " -o " + (dir / "o").string());
  EXPECT_EQ(chained.status, 2);
  EXPECT_NE(chained.err.find("vacuum_flapping.toml:16: key 'chain': the case flies its own chain file"),
            std::string::npos)
      << chained.err;  // line 16 of cases/vacuum_flapping.toml: chain = "chains/hawkmoth_10_bodies.toml"
  // Its chain is a documented one, reduced from no wing: the message does not say it was.
  EXPECT_NE(chained.err.find("not one reduced from " + (dir / "w.toml").string()), std::string::npos)
      << chained.err;
  EXPECT_EQ(chained.err.find("reduced from its own wing"), std::string::npos) << chained.err;
  EXPECT_FALSE(fs::exists(dir / "o"));
  const auto missing = run_flapsim_capturing_stderr(
      dir.path(), "check " + chain_case + " --wing " + (dir / "nothere.toml").string());
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("key '--wing': wing file not found"), std::string::npos) << missing.err;
  EXPECT_EQ(run_flapsim("check " + (dir / "w.toml").string() + " --wing " + (dir / "w.toml").string()), 1);
}

// sweep --wing: every case flies the wing (the sweep's row is the run of the case written
// with it); optimize --wing: its optimum.toml names that wing, so that `run` flies it again.
TEST(WingOption, SweepsAndOptimisationsFlyTheWingInEveryCase) {
  const flapsim::test::ScratchDir dir("wing_option_sweep");
  write_two_wings_and_their_cases(dir.path());
  const std::string trapezoid = (dir / "trapezoid.toml").string();
  ASSERT_EQ(run_flapsim("sweep " + (dir / "rectangle_case.toml").string() + " --wing " + trapezoid +
                        " --vary kinematics.rotation_phase=0 -q -o " + (dir / "sweep").string()),
            0);
  ASSERT_EQ(run_flapsim("run " + (dir / "trapezoid_case.toml").string() + " -q -o " + (dir / "run").string()),
            0);
  const double written = json_number(read_text(dir / "run" / "summary.json"), "mean_lift_N");
  const std::string row = read_text(dir / "sweep" / "sweep.csv");
  const std::size_t second_line = row.find('\n') + 1;  // the header, then the one case
  EXPECT_EQ(std::stod(row.substr(row.find(',', second_line) + 1)), written) << row;
  ASSERT_EQ(
      run_flapsim(
          "optimize " + (dir / "rectangle_case.toml").string() + " --wing " + trapezoid +
          " --vary kinematics.rotation_phase=-0.1:0.1 --maximize mean_lift_N --max-evaluations 2 -q -o " +
          (dir / "opt").string()),
      0);
  EXPECT_NE(read_text(dir / "opt" / "optimum.toml").find("wing = '../trapezoid.toml'"), std::string::npos)
      << read_text(dir / "opt" / "optimum.toml");
}

// A sweep over wings: `--vary wing=a.toml,b.toml` (paths from the current folder, as --wing's)
// or a case table's `wing` column flies each wing as its own case, named by its file in the
// case's folder; each row is the run of the case written with that wing, bit for bit.
TEST(WingOption, ASweepOverWingsFliesEachAsTheCaseWrittenWithIt) {
  const flapsim::test::ScratchDir dir("wing_option_vary");
  write_two_wings_and_their_cases(dir.path());
  const std::string cd = "cd '" + dir.path().string() + "' && exec";
  ASSERT_EQ(flapsim::test::run_flapsim_in_shell(
                cd, "sweep rectangle_case.toml --vary wing=trapezoid.toml,rectangle.toml -q -o grid"),
            0);
  std::ofstream(dir / "wings.csv") << "wing\ntrapezoid.toml\nrectangle.toml\n";
  ASSERT_EQ(
      flapsim::test::run_flapsim_in_shell(cd, "sweep rectangle_case.toml --cases wings.csv -q -o table"), 0);
  for (const char* c : {"trapezoid", "rectangle"})
    ASSERT_EQ(run_flapsim("run " + (dir / (std::string(c) + "_case.toml")).string() + " -q -o " +
                          (dir / (std::string("run_") + c)).string()),
              0);
  const double trapezoid = json_number(read_text(dir / "run_trapezoid" / "summary.json"), "mean_lift_N");
  const double rectangle = json_number(read_text(dir / "run_rectangle" / "summary.json"), "mean_lift_N");
  for (const char* sweep : {"grid", "table"}) {
    SCOPED_TRACE(sweep);
    EXPECT_EQ(json_number(read_text(dir / sweep / "00_trapezoid" / "summary.json"), "mean_lift_N"),
              trapezoid);
    EXPECT_EQ(json_number(read_text(dir / sweep / "01_rectangle" / "summary.json"), "mean_lift_N"),
              rectangle);
    const std::string table = read_text(dir / sweep / "sweep.csv");
    EXPECT_EQ(table.rfind("wing,", 0), 0u) << table;
    EXPECT_NE(table.find("\ntrapezoid.toml,"), std::string::npos) << table;  // the path as given
  }
  EXPECT_NE(trapezoid, rectangle);
  // A missing wing names the value; --wing and a varied wing at once are refused.
  const auto missing =
      run_flapsim_capturing_stderr(dir.path(), "sweep " + (dir / "rectangle_case.toml").string() +
                                                   " --vary wing=nothere.toml -q -o " + (dir / "x").string());
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("wing file not found: nothere.toml (a path from the current folder"),
            std::string::npos)
      << missing.err;
  const auto both = run_flapsim_capturing_stderr(
      dir.path(), "sweep " + (dir / "rectangle_case.toml").string() + " --wing " +
                      (dir / "trapezoid.toml").string() + " --vary wing=rectangle.toml -q -o " +
                      (dir / "y").string());
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.err.find("give the wings one way"), std::string::npos) << both.err;
  // A chain file is one wing's: a case with its own chain, or --chain, with varied wings.
  const auto chained = run_flapsim_capturing_stderr(
      dir.path(), "sweep " + std::string(FLAPSIM_SOURCE_DIR) + "/cases/vacuum_flapping.toml --vary wing=" +
                      (dir / "rectangle.toml").string() + " -q -o " + (dir / "z").string());
  EXPECT_EQ(chained.status, 2);
  EXPECT_NE(chained.err.find("vacuum_flapping.toml:16: key 'chain': the sweep varies 'wing'"),
            std::string::npos)
      << chained.err;
  EXPECT_FALSE(fs::exists(dir / "x"));
  EXPECT_FALSE(fs::exists(dir / "y"));
  EXPECT_FALSE(fs::exists(dir / "z"));
}

}  // namespace
