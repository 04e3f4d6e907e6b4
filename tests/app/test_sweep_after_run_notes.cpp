// What a run's results say after it (pipeline/app/after_run_notes.hpp) reaches sweep.csv's
// message column, a kept row and the optimiser, as `flapsim run`'s report warns of it; a case
// folder holding another command's outputs is not the sweep's to replace; a kept row keeps the
// rank and host that ran it (docs/sweeps.md, "The table"). Found on 5 Dec: a `shed` hover whose
// sheet came apart (its CL jumping by 251 in a step, mean CL 10.4) was an "ok" row warned only
// that `shed` is experimental, and an optimiser chose it as the optimum unwarned; a sweep into a
// folder whose case sub-folder held `flapsim reduce`'s outputs replaced its summary.json
// silently, where `flapsim run` refuses (exit 4).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/app/after_run_notes.hpp"
#include "pipeline/app/sweep/sweep_table.hpp"
#include "sweep_test_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using namespace flapsim;

app::RunResults results_with(const char* leading_edge, double cl_jump, double zigzag_deg) {
  app::RunResults r;
  r.set("case", "plate");
  r.set("leading_edge", leading_edge);
  r.set("largest_CL_jump", cl_jump);
  r.set("largest_CL_jump_step", 169L);
  r.set("largest_tip_zigzag_deg", zigzag_deg);
  r.set("largest_tip_zigzag_step", 75L);
  return r;
}

TEST(AfterRunNotes, ASheetComeApartAndAZigzaggingTipAreNotedAsTheReportWarnsOfThem) {
  const auto notes = app::after_run_notes(results_with("shed", 251.0, 5.86));
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_EQ(notes[0], "shed sheet came apart: CL changed by 251 in a step (into step 169)");
  EXPECT_EQ(notes[1], "tip zigzags from step to step: 5.86 deg (step 75)");
  // The report's bounds: a jump of 7 (a sheet that held) and a zigzag of 0.48° are not noted,
  // nor a jump of another model (it sheds no sheet).
  EXPECT_TRUE(app::after_run_notes(results_with("shed", 7.0, 0.48)).empty());
  EXPECT_TRUE(app::after_run_notes(results_with("separated", 251.0, 0.0)).empty());
  // A kept row says them after "kept", as the row of the run did.
  EXPECT_EQ(sweep::kept_message(results_with("shed", 251.0, 0.0)),
            "kept; shed sheet came apart: CL changed by 251 in a step (into step 169)");
  // The optimiser's advice names the constraint that keeps a search where the model holds.
  const std::string advice = app::after_run_advice(results_with("shed", 251.0, 5.86));
  EXPECT_NE(advice.find("--constraint largest_CL_jump<=10"), std::string::npos) << advice;
  EXPECT_NE(advice.find("--constraint largest_tip_zigzag_deg<=1"), std::string::npos) << advice;
  EXPECT_TRUE(app::after_run_advice(results_with("shed", 7.0, 0.48)).empty());
}

TEST(SweepFolders, ACaseFolderHoldingAnotherCommandsOutputsIsNotReplaced) {
  const test::ScratchDir dir("sweep_clashing_case_folder");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(24);
  // `flapsim reduce` of the plate into what will be the sweep's first case folder.
  ASSERT_EQ(test::run_flapsim("reduce " + std::string(FLAPSIM_SOURCE_DIR) +
                              "/wings/flat_plate.toml --bodies 3 -o " + (dir / "out" / "00_0").string()),
            0);
  const std::string reduced = test::read_text(dir / "out" / "00_0" / "summary.json");
  ASSERT_EQ(test::run_flapsim("sweep " + (dir / "case.toml").string() +
                              " --vary kinematics.rotation_phase=0,0.1 -j 1 -q -o " + (dir / "out").string()),
            0);
  const auto table = test::read_sweep_table((dir / "out" / "sweep.csv").string());
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.rows[0].at("status"), "error");
  EXPECT_NE(
      table.rows[0].at("message").find("the folder holds the outputs of 'flapsim reduce' (summary.json)"),
      std::string::npos)
      << table.rows[0].at("message");
  EXPECT_EQ(test::read_text(dir / "out" / "00_0" / "summary.json"), reduced);  // reduce's, untouched
  EXPECT_TRUE(fs::exists(dir / "out" / "00_0" / "chain.toml"));
  EXPECT_EQ(table.rows[1].at("status"), "ok");  // the other case runs
}

TEST(SweepFolders, AKeptRowKeepsTheRankAndHostThatRanIt) {
  const test::ScratchDir dir("sweep_kept_rank");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(24);
  const std::string args = "sweep " + (dir / "case.toml").string() +
                           " --vary kinematics.rotation_phase=0,0.1 -j 1 -q -o " + (dir / "out").string();
  ASSERT_EQ(test::run_flapsim(args), 0);
  // As if another rank on another machine had run the second case: its row says so.
  const fs::path table_path = dir / "out" / "sweep.csv";
  std::string text = test::read_text(table_path);
  const std::string host = sweep::host_name();
  const std::string row_end = ",0," + host + "\n";
  const auto last = text.rfind(row_end);
  ASSERT_NE(last, std::string::npos) << text;
  text.replace(last, row_end.size(), ",1,node17\n");
  std::ofstream(table_path) << text;
  ASSERT_EQ(test::run_flapsim(args), 0);  // both kept
  const auto table = test::read_sweep_table(table_path.string());
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.rows[0].at("message"), "kept");
  EXPECT_EQ(table.rows[0].at("rank"), "0");
  EXPECT_EQ(table.rows[0].at("host"), host);
  EXPECT_EQ(table.rows[1].at("message"), "kept");
  EXPECT_EQ(table.rows[1].at("rank"), "1");  // before: the rank that found it kept, 0
  EXPECT_EQ(table.rows[1].at("host"), "node17");
}

}  // namespace
