// flapsim sweep end to end: a two-key grid (one row per combination), a sweep killed
// part-way and run again (only the missing cases run), a case that cannot run (recorded,
// the others go on) and --force.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <thread>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/app/run_results.hpp"
#include "sweep_test_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using namespace flapsim;
using test::read_sweep_table;
using test::read_text;
using test::run_flapsim;

// The value of a key of summary.json as text ("" if absent).
std::string json_value(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\": ");
  if (at == std::string::npos) return "";
  const auto begin = at + key.size() + 4;
  return json.substr(begin, json.find_first_of(",\n", begin) - begin);
}

// tools/plot_sweep.py on DIR/out/sweep.csv into DIR/plots: its exit status.
int plot_sweep(const test::ScratchDir& dir) {
  const std::string plot = "/usr/bin/python3 '" + std::string(FLAPSIM_SOURCE_DIR) +
                           "/tools/plot_sweep.py' '" + (dir / "out" / "sweep.csv").string() + "' '" +
                           (dir / "plots").string() + "' > /dev/null";
  return std::system(plot.c_str());
}

TEST(SweepRuns, TwoKeyGridGivesOneRowPerCombination) {
  const test::ScratchDir dir("sweep_grid");
  // A flexible wing of 2 bodies (spring_scale is an input of a chain only).
  std::string text = test::tiny_plate_case(24);
  text.replace(text.find("kind = \"rigid\""), 14, "kind = \"flexible\"\nbodies = 2");
  std::ofstream(dir / "case.toml") << text;
  ASSERT_EQ(run_flapsim("sweep " + (dir / "case.toml").string() +
                        " --vary kinematics.rotation_phase=-0.1,0,0.1 --vary spring_scale=1,2 -j 2 -o " +
                        (dir / "out").string()),
            0);
  const auto table = read_sweep_table((dir / "out" / "sweep.csv").string());
  ASSERT_TRUE(table.rectangular);
  ASSERT_GE(table.header.size(), 2u);
  EXPECT_EQ(table.header[0], "kinematics.rotation_phase");
  EXPECT_EQ(table.header[1], "spring_scale");
  ASSERT_EQ(table.rows.size(), 6u);  // 3 phases × 2 spring factors
  std::set<std::pair<std::string, std::string>> combinations;
  for (const auto& row : table.rows) {
    EXPECT_EQ(row.at("status"), "ok");
    combinations.insert({row.at("kinematics.rotation_phase"), row.at("spring_scale")});
    // Each row's case ran with its values: its summary.json says so.
    const std::string summary = read_text(dir / "out" / row.at("folder") / "summary.json");
    EXPECT_EQ(std::stod(json_value(summary, "rotation_phase")),
              std::stod(row.at("kinematics.rotation_phase")));
    EXPECT_EQ(std::stod(json_value(summary, "spring_scale")), std::stod(row.at("spring_scale")));
    EXPECT_EQ(std::stod(json_value(summary, "mean_lift_N")), std::stod(row.at("mean_lift_N")));
  }
  EXPECT_EQ(combinations.size(), 6u);
  EXPECT_EQ(table.rows[1].at("folder"), "01_-0.1_2");  // first key slowest

  // The plot tool draws mean lift against each varied key (tools/plot_sweep.py).
  ASSERT_EQ(plot_sweep(dir), 0);
  for (const char* name : {"sweep_kinematics_rotation_phase.png", "sweep_spring_scale.png"})
    EXPECT_EQ(read_text(dir / "plots" / name).substr(0, 4), "\x89PNG") << name;
}

// A text key varied by its words: the leading-edge models side by side in one sweep (before,
// "--vary numerics.leading_edge=none,separated" exited 2: "'none' is not a number", and a user
// ran one sweep per model). Each case runs with its model (summary.json leading_edge), the
// folders and sweep.csv carry the words, and the plot names them on its axis.
TEST(SweepRuns, AWordKeyComparesTheLeadingEdgeModels) {
  const test::ScratchDir dir("sweep_words");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(24);
  ASSERT_EQ(run_flapsim("sweep " + (dir / "case.toml").string() +
                        " --vary numerics.leading_edge=none,separated -j 2 -o " + (dir / "out").string()),
            0);
  const auto table = read_sweep_table((dir / "out" / "sweep.csv").string());
  ASSERT_TRUE(table.rectangular);
  ASSERT_EQ(table.rows.size(), 2u);
  std::map<std::string, double> lift;
  for (const auto& row : table.rows) {
    EXPECT_EQ(row.at("status"), "ok");
    const std::string model = row.at("numerics.leading_edge");
    EXPECT_EQ(row.at("folder"), (model == "none" ? "00_" : "01_") + model);
    const std::string summary = read_text(dir / "out" / row.at("folder") / "summary.json");
    EXPECT_EQ(json_value(summary, "leading_edge"), "\"" + model + "\"");
    lift[model] = std::stod(row.at("mean_lift_N"));
  }
  // The suction turned into vortex lift (Polhamus, docs/uvlm.md "Leading edge") adds to the
  // normal force of "none": the separated edge lifts more.
  EXPECT_GT(lift.at("separated"), lift.at("none"));
  ASSERT_EQ(plot_sweep(dir), 0);
  EXPECT_EQ(read_text(dir / "plots" / "sweep_numerics_leading_edge.png").substr(0, 4), "\x89PNG");
}

TEST(SweepRuns, KilledSweepRerunsOnlyTheMissingCases) {
  const test::ScratchDir dir("sweep_resume");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(48);
  // A case table (--cases): a short first case, then longer ones, so that the kill
  // lands while the later cases are still to run.
  std::ofstream(dir / "cases.csv") << "kinematics.rotation_phase,numerics.steps_per_cycle\n"
                                      "-0.15,24\n-0.1,96\n-0.05,96\n0,96\n0.05,96\n0.1,96\n0.15,96\n";
  const std::string args = "sweep " + (dir / "case.toml").string() + " --cases " +
                           (dir / "cases.csv").string() + " -j 1 -o " + (dir / "out").string();
  // Start the sweep in the background and kill it (SIGKILL: no clean-up) as soon as
  // its first case has finished.
  const std::string start = "FLAPSIM_QUIET=1 OMP_NUM_THREADS=1 '" + std::string(FLAPSIM_BINARY) + "' " +
                            args + " > /dev/null 2>&1 & echo $! > '" + (dir / "pid").string() + "'";
  ASSERT_EQ(std::system(start.c_str()), 0);
  const pid_t pid = std::stoi(read_text(dir / "pid"));
  auto finished = [&] {
    int n = 0;
    if (fs::exists(dir / "out"))
      for (const auto& e : fs::directory_iterator(dir / "out"))
        if (fs::exists(e.path() / "summary.json")) ++n;
    return n;
  };
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (finished() == 0 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  ::kill(pid, SIGKILL);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const int done_before = finished();
  ASSERT_GE(done_before, 1);
  ASSERT_LT(done_before, 7) << "the sweep finished before it could be killed";

  // The interrupted sweep's table is valid: the header and complete rows of finished cases.
  const auto interrupted = read_sweep_table((dir / "out" / "sweep.csv").string());
  EXPECT_TRUE(interrupted.rectangular);
  EXPECT_EQ(interrupted.header.front(), "kinematics.rotation_phase");
  EXPECT_LE(interrupted.rows.size(), static_cast<std::size_t>(done_before));
  for (const auto& row : interrupted.rows) EXPECT_EQ(row.at("status"), "ok");

  std::map<std::string, std::string> before;  // folder -> summary.json of the finished cases
  for (const auto& e : fs::directory_iterator(dir / "out"))
    if (fs::exists(e.path() / "summary.json"))
      before[e.path().filename()] = read_text(e.path() / "summary.json");

  // Run again: the finished cases are kept (summary.json untouched, message "kept"), the rest run.
  ASSERT_EQ(run_flapsim(args), 0);
  const auto table = read_sweep_table((dir / "out" / "sweep.csv").string());
  ASSERT_TRUE(table.rectangular);
  ASSERT_EQ(table.rows.size(), 7u);  // the table's rows
  int kept = 0, ran = 0;
  for (const auto& row : table.rows) {
    EXPECT_EQ(row.at("status"), "ok");
    const std::string folder = row.at("folder");
    const std::string summary = read_text(dir / "out" / folder / "summary.json");
    if (before.count(folder)) {
      EXPECT_EQ(row.at("message"), "kept") << folder;
      EXPECT_EQ(summary, before.at(folder)) << folder << " was run again";  // wall time would differ
      ++kept;
    } else {
      EXPECT_EQ(row.at("message"), "") << folder;
      ++ran;
    }
  }
  EXPECT_EQ(kept, done_before);
  EXPECT_EQ(ran, 7 - done_before);

  // A third run keeps all; --force runs all again.
  ASSERT_EQ(run_flapsim(args), 0);
  for (const auto& row : read_sweep_table((dir / "out" / "sweep.csv").string()).rows)
    EXPECT_EQ(row.at("message"), "kept");
  ASSERT_EQ(run_flapsim(args + " --force"), 0);
  for (const auto& row : read_sweep_table((dir / "out" / "sweep.csv").string()).rows)
    EXPECT_EQ(row.at("message"), "");
}

TEST(SweepRuns, CaseThatCannotRunIsRecordedAndTheOthersGoOn) {
  const test::ScratchDir dir("sweep_error");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(24);
  fs::create_directories(dir / "out");
  std::ofstream(dir / "out" / "01_0") << "a file where the case's folder should be\n";
  ASSERT_EQ(run_flapsim("sweep " + (dir / "case.toml").string() +
                        " --vary kinematics.rotation_phase=-0.1,0,0.1 -j 1 -o " + (dir / "out").string()),
            0);
  const auto table = read_sweep_table((dir / "out" / "sweep.csv").string());
  ASSERT_EQ(table.rows.size(), 3u);
  EXPECT_EQ(table.rows[0].at("status"), "ok");
  EXPECT_EQ(table.rows[1].at("status"), "error");
  EXPECT_NE(table.rows[1].at("message").find("01_0"), std::string::npos) << table.rows[1].at("message");
  EXPECT_EQ(table.rows[1].at("mean_lift_N"), "nan");
  EXPECT_EQ(table.rows[2].at("status"), "ok");
  EXPECT_EQ(table.rows[0].at("rank"), "0");
  EXPECT_FALSE(table.rows[0].at("host").empty());

  // --vary takes one value each time: the case file may follow it.
  ASSERT_EQ(run_flapsim("sweep --vary kinematics.rotation_phase=0.1 --vary air.density=1.2 " +
                        (dir / "case.toml").string() + " -o " + (dir / "order").string()),
            0);
  EXPECT_EQ(read_sweep_table((dir / "order" / "sweep.csv").string()).rows.size(), 1u);
}

TEST(SweepRuns, NumericalFailureIsRecordedAndTheOthersGoOn) {
  // A flexible plate (2 bodies, reduced in process) allowed one coupling sub-iteration
  // per step cannot converge (the first iterate always moves the structure): that case
  // fails numerically; with 50 it runs.
  const test::ScratchDir dir("sweep_failed");
  std::string c = test::tiny_plate_case(24);
  c.replace(c.find("kind = \"rigid\""), 14, "kind = \"flexible\"\nbodies = 2");
  std::ofstream(dir / "case.toml") << c;
  ASSERT_EQ(run_flapsim("sweep " + (dir / "case.toml").string() +
                        " --vary numerics.max_coupling_iterations=1,50 -j 1 -o " + (dir / "out").string()),
            0);
  const auto table = read_sweep_table((dir / "out" / "sweep.csv").string());
  ASSERT_TRUE(table.rectangular);
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.rows[0].at("status"), "failed");
  EXPECT_NE(table.rows[0].at("message").find("did not converge"), std::string::npos) << table.rows[0].at("message");
  EXPECT_EQ(table.rows[0].at("mean_lift_N"), "nan");
  EXPECT_NE(read_text(dir / "out" / table.rows[0].at("folder") / "summary.json").find("\"status\": \"failed\""),
            std::string::npos);
  EXPECT_EQ(table.rows[1].at("status"), "ok");
  EXPECT_GT(std::stod(table.rows[1].at("mean_lift_N")), 0.0);
}

}  // namespace

// OMP_NUM_THREADS, when set, is a sweep's threads as it is every command's
// (docs/performance.md; docs/sweeps.md -j): a user on a shared machine who set it to 1 got
// "1 rank x 2 threads" (the machine's cores) until 2 Dec. 3 here, on any machine.
TEST(SweepRuns, TheEnvironmentsThreadCountIsTheSweepsDefault) {
  const test::ScratchDir dir("sweep_omp_threads");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(8);
  const std::string cmd = "OMP_NUM_THREADS=3 '" + std::string(FLAPSIM_BINARY) + "' sweep '" +
                          (dir / "case.toml").string() +
                          "' --vary kinematics.rotation_phase=-0.1,0,0.1 --log-every 1000 -o '" +
                          (dir / "out").string() + "' > '" + (dir / "said.txt").string() + "' 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << read_text(dir / "said.txt");
  const std::string said = read_text(dir / "said.txt");
  EXPECT_NE(said.find("1 rank x 3 threads"), std::string::npos) << said;
}
