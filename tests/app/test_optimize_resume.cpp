// flapsim optimize resumed (issue 33): an optimisation stopped by --max-evaluations and run
// again does not run any evaluated point again, and ends where an uninterrupted one ends.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "sweep_test_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using namespace flapsim;

// The points of evaluations.csv, in order (their inputs hashes).
std::vector<std::string> evaluated_hashes(const fs::path& dir) {
  std::vector<std::string> hashes;
  for (const auto& row : test::read_sweep_table((dir / "evaluations.csv").string()).rows)
    hashes.push_back(row.at("inputs_hash"));
  return hashes;
}

// A second search in the same folder that finds no optimum (a constraint no point meets,
// exit 2 "no optimum.toml written") left the first search's optimum.toml beside its own
// evaluations and report: `flapsim run DIR/optimum.toml` and make optimize-plots took another
// problem's optimum. A search removes the earlier search's optimum and report when it starts.
TEST(OptimizeResume, ASearchWithoutAnOptimumLeavesNoEarlierSearchsOptimum) {
  const test::ScratchDir dir("optimize_stale_optimum");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(24);
  const std::string start = "optimize " + (dir / "case.toml").string() +
                            " --vary kinematics.rotation_phase=-0.25:0.15 --max-evaluations 3 -q -o " +
                            (dir / "opt").string();
  ASSERT_EQ(test::run_flapsim(start + " --maximize mean_lift_N"), 0);
  ASSERT_TRUE(fs::exists(dir / "opt" / "optimum.toml"));
  EXPECT_EQ(test::run_flapsim(start + " --maximize lift_per_power_N_W --constraint 'mean_lift_N>=1'"), 2);
  EXPECT_FALSE(fs::exists(dir / "opt" / "optimum.toml"));
  const std::string report = test::read_text(dir / "opt" / "report.md");
  EXPECT_NE(report.find("lift_per_power_N_W"), std::string::npos) << report;  // this search's report
}

TEST(OptimizeResume, AnInterruptedOptimisationRerunsNoEvaluatedPoint) {
  const test::ScratchDir dir("optimize_resume");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(24);
  const std::string command = "optimize " + (dir / "case.toml").string() +
                              " --vary kinematics.rotation_phase=-0.25:0.15 --vary kinematics.frequency_hz=20:30"
                              " --maximize mean_lift_N -q";

  // Stopped after 4 evaluations (BOBYQA's first model takes 2n + 1 = 5 points).
  ASSERT_EQ(test::run_flapsim(command + " --max-evaluations 4 -o " + (dir / "opt").string()), 0);
  const std::vector<std::string> first = evaluated_hashes(dir / "opt");
  ASSERT_EQ(first.size(), 4u);
  EXPECT_NE(test::read_text(dir / "opt" / "report.md").find("maximum number of evaluations"), std::string::npos);
  // Each run's summary.json, to tell whether the rerun ran it again (its wall time would change).
  std::vector<std::string> summaries;
  for (const std::string& h : first) summaries.push_back(test::read_text(dir / "opt" / "runs" / h / "summary.json"));

  // Run again to the end: the 4 points are kept (their files untouched), the rest run.
  ASSERT_EQ(test::run_flapsim(command + " -o " + (dir / "opt").string()), 0);
  const std::vector<std::string> resumed = evaluated_hashes(dir / "opt");
  ASSERT_GT(resumed.size(), first.size());
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(resumed[i], first[i]);
    EXPECT_EQ(test::read_text(dir / "opt" / "runs" / first[i] / "summary.json"), summaries[i]) << "run again: " << first[i];
  }
  const std::string report = test::read_text(dir / "opt" / "report.md");
  EXPECT_NE(report.find(" run, 4 kept: evaluated before"), std::string::npos) << report;
  std::size_t folders = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir / "opt" / "runs")) ++folders;
  EXPECT_EQ(folders, resumed.size());  // one run per evaluated point

  // Deterministic: an uninterrupted optimisation evaluates the same points in the same order
  // and writes the same optimum.
  ASSERT_EQ(test::run_flapsim(command + " -o " + (dir / "whole").string()), 0);
  EXPECT_EQ(evaluated_hashes(dir / "whole"), resumed);
  EXPECT_EQ(test::read_text(dir / "whole" / "optimum.toml"), test::read_text(dir / "opt" / "optimum.toml"));

  // The plot tool draws the optimisation (tools/plot_optimize.py, make optimize-plots).
  const std::string plot = "/usr/bin/python3 '" + std::string(FLAPSIM_SOURCE_DIR) + "/tools/plot_optimize.py' '" +
                           (dir / "whole").string() + "' '" + (dir / "plots").string() + "' > /dev/null";
  ASSERT_EQ(std::system(plot.c_str()), 0);
  for (const char* name : {"optimize_objective.png", "optimize_path.png", "optimize_lift_cycle.png"})
    EXPECT_EQ(test::read_text(dir / "plots" / name).substr(0, 4), "\x89PNG") << name;
  // Its --help is its usage, and a folder that is no optimisation is said to be one (exit 2,
  // nothing made). Until 2 Dec both ended in a traceback after making FOLDER/plots
  // ("--help/plots" in the current folder).
  const std::string tool = "cd '" + dir.path().string() + "' && /usr/bin/python3 '" +
                           std::string(FLAPSIM_SOURCE_DIR) + "/tools/plot_optimize.py' ";
  EXPECT_EQ(std::system((tool + "--help > help.txt").c_str()), 0);
  EXPECT_NE(test::read_text(dir / "help.txt").find("Usage: plot_optimize.py DIR"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "--help"));
  const int status = std::system((tool + "plots 2> none.txt").c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2) << status;
  EXPECT_NE(test::read_text(dir / "none.txt").find("not a flapsim optimize folder"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "plots" / "plots"));

  // A third run of the same command runs nothing.
  ASSERT_EQ(test::run_flapsim(command + " -o " + (dir / "whole").string()), 0);
  EXPECT_NE(test::read_text(dir / "whole" / "report.md").find("(0 run, "), std::string::npos);
}

// The inputs hash leaves out the ParaView interval (io::input_hash), so a point's run found
// by its hash may have no series: an optimisation run again with --vtk-every (for pictures
// of the points an earlier one evaluated without them) runs those points again, and they
// write their series; it kept them all and wrote none. Run once more, they are kept; run
// with --force and no series, they leave none of the earlier run's series behind.
TEST(OptimizeResume, ARerunAskingForParaViewSeriesRunsThePointsThatHaveNone) {
  const test::ScratchDir dir("optimize_resume_vtk");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(8);
  const std::string command = "optimize " + (dir / "case.toml").string() +
                              " --vary kinematics.rotation_phase=-0.25:0.15 --maximize mean_lift_N"
                              " --max-evaluations 3 -q -o " +
                              (dir / "opt").string();
  const auto evaluations_line = [&dir] {
    const std::string report = test::read_text(dir / "opt" / "report.md");
    const auto at = report.find("- evaluations: ");
    return at == std::string::npos ? std::string() : report.substr(at, report.find(" kept", at) - at);
  };
  ASSERT_EQ(test::run_flapsim(command), 0);
  const std::vector<std::string> points = evaluated_hashes(dir / "opt");
  ASSERT_EQ(points.size(), 3u);
  EXPECT_EQ(evaluations_line(), "- evaluations: 3 (3 run, 0");
  for (const std::string& h : points) EXPECT_FALSE(fs::exists(dir / "opt" / "runs" / h / "chain.pvd")) << h;

  ASSERT_EQ(test::run_flapsim(command + " --vtk-every 4"), 0);
  EXPECT_EQ(evaluated_hashes(dir / "opt"), points);  // the same search
  EXPECT_EQ(evaluations_line(), "- evaluations: 3 (3 run, 0");
  for (const std::string& h : points)
    for (const char* series : {"chain.pvd", "wing.pvd", "wake.pvd"})
      EXPECT_TRUE(fs::exists(dir / "opt" / "runs" / h / series)) << h << " " << series;

  ASSERT_EQ(test::run_flapsim(command + " --vtk-every 4"), 0);
  EXPECT_EQ(evaluations_line(), "- evaluations: 3 (0 run, 3");

  // Run again without series (--force): each point's folder is cleared of the earlier run's
  // files first, as a sweep's case is, so no series stays beside the new history.
  ASSERT_EQ(test::run_flapsim(command + " --force"), 0);
  EXPECT_EQ(evaluations_line(), "- evaluations: 3 (3 run, 0");
  for (const std::string& h : points) {
    EXPECT_TRUE(fs::exists(dir / "opt" / "runs" / h / "summary.json")) << h;
    for (const char* stale : {"chain.pvd", "wing.pvd", "wake.pvd", "run.pvsm", "vtk"})
      EXPECT_FALSE(fs::exists(dir / "opt" / "runs" / h / stale)) << h << " " << stale;
  }
}

// A second search in the folder of an earlier one (other bounds): its progress lines numbered
// its evaluations 1, 2, … and "best … at evaluation 1", where evaluations.csv and report.md
// number the same points after the earlier rows (4, 5, …): "evaluation N" on stderr could not
// be found in the table. One numbering now, the table's.
TEST(OptimizeResume, TheProgressLinesNumberTheEvaluationsAsTheTableDoes) {
  const test::ScratchDir dir("optimize_numbering");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(12);
  const std::string start = "optimize " + (dir / "case.toml").string() + " --maximize mean_lift_N -o " +
                            (dir / "opt").string() + " --vary kinematics.rotation_phase=";
  ASSERT_EQ(test::run_flapsim(start + "-0.25:-0.05 --max-evaluations 3 -q"), 0);
  const auto before = test::read_sweep_table((dir / "opt" / "evaluations.csv").string()).rows.size();
  ASSERT_GE(before, 3u);
  const auto second = test::run_flapsim_capturing_stderr(dir.path(), start + "0.05:0.15 --max-evaluations 2");
  ASSERT_EQ(second.status, 0) << second.err;
  const auto rows = test::read_sweep_table((dir / "opt" / "evaluations.csv").string()).rows;
  ASSERT_EQ(rows.size(), before + 2);
  for (std::size_t k = before; k < rows.size(); ++k) {
    const std::string number = rows[k].at("evaluation");
    EXPECT_NE(second.err.find("optimize: evaluation " + number + " (run)"), std::string::npos)
        << "evaluation " << number << ":\n"
        << second.err;
  }
  EXPECT_EQ(second.err.find("optimize: evaluation 1 ("), std::string::npos) << second.err;
}

}  // namespace
