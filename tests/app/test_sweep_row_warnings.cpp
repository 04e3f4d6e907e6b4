// A case's warnings are in its row of sweep.csv, also those its varied values cause in the
// case or wing file, and a case kept when the sweep runs again keeps them. Before: a value
// the case file warns about (numerics.far_wake_cycles = 1 in hover) gave a row "ok" with an
// empty message (the terminal showed the base case's warnings only), and a kept row said
// "kept" whatever warnings its run had had.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "sweep_test_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using namespace flapsim;

// The far-wake warning of case_file.cpp (warn_far_wake_outside_measured_range) up to its first
// ": ", named by its key: 1 cycle lies outside kHoverFarWakeCyclesMin–Max = 0.5–0.625.
const std::string kFarWakeNote =
    "numerics.far_wake_cycles: far_wake_cycles = 1 in hover is outside the measured range 0.5 to 0.625";

// The tiny plate's sweep over numerics.far_wake_cycles = 0.5 (in the measured range) and 1.
std::string far_wake_sweep(const test::ScratchDir& dir) {
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(24);
  return "sweep " + (dir / "case.toml").string() + " --vary numerics.far_wake_cycles=0.5,1 -j 1 -o " +
         (dir / "out").string();
}

TEST(SweepRowWarnings, AVariedValueTheCaseFileWarnsAboutIsInItsRow) {
  const test::ScratchDir dir("sweep_row_case_warning");
  ASSERT_EQ(test::run_flapsim(far_wake_sweep(dir)), 0);
  const auto table = test::read_sweep_table((dir / "out" / "sweep.csv").string());
  ASSERT_TRUE(table.rectangular);
  ASSERT_EQ(table.rows.size(), 2u);             // two values
  EXPECT_EQ(table.rows[0].at("message"), "");   // 0.5 is within the measured range: no warning
  EXPECT_EQ(table.rows[1].at("status"), "ok");  // a warning, not a failure
  EXPECT_EQ(table.rows[1].at("message"), kFarWakeNote);
}

TEST(SweepRowWarnings, AVariedValueTheWingFileWarnsAboutIsInItsRowQuoted) {
  const test::ScratchDir dir("sweep_row_wing_warning");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(24);
  ASSERT_EQ(test::run_flapsim("sweep " + (dir / "case.toml").string() +
                              " --vary wing.materials.pet.density=1390,5 -j 1 -o " + (dir / "out").string()),
            0);
  const auto table = test::read_sweep_table((dir / "out" / "sweep.csv").string());
  ASSERT_TRUE(table.rectangular);  // the message's comma is quoted
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.rows[0].at("message"), "");  // PET's 1390 kg/m³ (wings/flat_plate.toml)
  // wing_file.cpp's check_density below 10 kg/m³, up to its first ": ", with the sweep's key.
  EXPECT_EQ(
      table.rows[1].at("message"),
      "wing.materials.pet.density: 5 kg/m³ is below 10 kg/m³, lighter than any wing material; density is "
      "in kg/m³");
}

TEST(SweepRowWarnings, AKeptRowCarriesTheWarningsItsRunHad) {
  const test::ScratchDir dir("sweep_row_kept_warning");
  const std::string args = far_wake_sweep(dir);
  ASSERT_EQ(test::run_flapsim(args), 0);
  const std::string summary = test::read_text(dir / "out" / "01_1" / "summary.json");
  ASSERT_EQ(test::run_flapsim(args), 0);  // the same command again keeps both cases
  const auto table = test::read_sweep_table((dir / "out" / "sweep.csv").string());
  ASSERT_TRUE(table.rectangular);
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.rows[0].at("message"), "kept");                   // its run had no warning
  EXPECT_EQ(table.rows[1].at("message"), "kept; " + kFarWakeNote);  // the first run's row, after "kept"
  EXPECT_EQ(table.rows[1].at("status"), "ok");
  EXPECT_EQ(test::read_text(dir / "out" / "01_1" / "summary.json"), summary);  // not run again
}

TEST(RunSummaryWarnings, ARunRecordsItsWarningsInItsSummaryAsASweepRowGivesThem) {
  // `flapsim run` of the tiny plate with far_wake_cycles = 1 in hover: its summary.json's
  // "warnings" is the sweep row's note above (the same words for the same case); without a
  // warning the entry is absent (run_recorder.hpp: set only when there are any).
  const test::ScratchDir dir("run_summary_warnings");
  std::string text = test::tiny_plate_case(24);
  std::ofstream(dir / "plain.toml") << text;
  const auto at = text.find("[numerics]");
  ASSERT_NE(at, std::string::npos);
  text.insert(at + std::string("[numerics]").size(), "\nfar_wake_cycles = 1");
  std::ofstream(dir / "warned.toml") << text;
  for (const std::string name : {"plain", "warned"})
    ASSERT_EQ(test::run_flapsim("run " + (dir / (name + ".toml")).string() + " -q -o " + (dir / name).string()), 0)
        << name;
  const std::string warned = test::read_text(dir / "warned" / "summary.json");
  EXPECT_NE(warned.find("\"warnings\": \"" + kFarWakeNote + "\""), std::string::npos) << warned;
  EXPECT_EQ(test::read_text(dir / "plain" / "summary.json").find("\"warnings\""), std::string::npos);
}

}  // namespace
