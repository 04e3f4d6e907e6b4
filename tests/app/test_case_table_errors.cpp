// A --cases table's problems are reported against the table: its file, the line and the
// column's key (docs/sweeps.md, "Case tables"; the README's exit-status contract: "the
// message names file, line and key; nothing written"). Before: a typo in the header
// ("kinematics.rotaton_phase") was reported as "case.toml: key 'kinematics.rotaton_phase':
// with kinematics.rotaton_phase = -0.1: unknown key ... (value given as an override)" —
// the case file, which does not hold the key, and no line; a typo in a table's name
// ("kinematic.frequency_hz") as "case.toml:1: key 'kinematic'", the case file's first line.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "pipeline/app/sweep/case_table.hpp"
#include "robustness_helpers.hpp"

using namespace flapsim::test;

namespace {

// `flapsim sweep CASE --cases TABLE -o DIR`: the exit status and stderr.
FlapsimOutcome sweep_with_table(const ScratchDir& dir, const std::string& table_text) {
  std::ofstream(dir / "case.toml") << small_plate_case("rigid", 1, 0);
  std::ofstream(dir / "table.csv") << table_text;
  return run_flapsim_capturing_stderr(dir.path(), "sweep '" + (dir / "case.toml").string() + "' --cases '" +
                                                              (dir / "table.csv").string() + "' -o '" +
                                                              (dir / "out").string() + "'");
}

// The message's location: "flapsim: error: <dir>/table.csv:LINE: key 'KEY': ".
std::string located(const ScratchDir& dir, int line, const std::string& key) {
  return "flapsim: error: " + (dir / "table.csv").string() + ":" + std::to_string(line) + ": key '" + key + "': ";
}

TEST(CaseTableErrors, ATypoInTheHeaderNamesTheTablesHeaderLineAndTheKey) {
  ScratchDir dir("table_typo");
  // A comment and a blank line first: the header is line 3.
  const FlapsimOutcome r = sweep_with_table(dir, "# rotation phases\n\nkinematics.rotaton_phase,air.density\n-0.1,1.2\n");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.rfind(located(dir, 3, "kinematics.rotaton_phase") + "unknown key", 0), 0u) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out")) << "nothing written";
}

TEST(CaseTableErrors, ATypoInATablesNameOrAWingKeyIsTheHeadersToo) {
  ScratchDir dir("table_typo_table");
  FlapsimOutcome r = sweep_with_table(dir, "kinematic.frequency_hz\n20\n");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.rfind(located(dir, 1, "kinematic.frequency_hz") + "unknown key", 0), 0u) << r.err;
  r = sweep_with_table(dir, "kinematics.frequency_hz,wing.membrane.thicknes\n20,0.2\n");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.rfind(located(dir, 1, "wing.membrane.thicknes") + "unknown key", 0), 0u) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out")) << "nothing written";
}

TEST(CaseTableErrors, ABadValueNamesItsRowsLine) {
  ScratchDir dir("table_value");
  // Row 3 (line 4, after a blank line) has a negative frequency: the case file's bound (0, 1e6].
  FlapsimOutcome r = sweep_with_table(dir, "kinematics.frequency_hz,wing.membrane.thickness\n20,0.2\n\n-5,0.2\n");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.rfind(located(dir, 4, "kinematics.frequency_hz") + "value -5 out of range", 0), 0u) << r.err;
  // A wing key's value: membrane.thickness must be > 0 (docs/wing_file.md).
  r = sweep_with_table(dir, "kinematics.frequency_hz,wing.membrane.thickness\n20,0.2\n20,-0.2\n");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.rfind(located(dir, 3, "wing.membrane.thickness") + "value -0.2 out of range", 0), 0u) << r.err;
  r = sweep_with_table(dir, "spring_scale\n0\n");  // checked before the rule of keys that change nothing
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find(located(dir, 2, "spring_scale") + "must be > 0"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out")) << "nothing written";
}

// A spreadsheet's "CSV UTF-8": a byte-order mark before the header, CR LF line ends. Before:
// "table.csv:1: key '\xEF\xBB\xBFkinematics.rotation_phase': unknown key (a typo?); expected
// one of: name, ..., kinematics, ..." (the mark invisible). A table written with ';' (a
// locale whose decimal mark is the comma) says so at its header.
TEST(CaseTableErrors, AByteOrderMarkIsSkippedAndSemicolonsAreNamed) {
  ScratchDir dir("table_bom");
  std::ofstream(dir / "bom.csv", std::ios::binary) << "\xEF\xBB\xBFkinematics.rotation_phase,air.density\r\n-0.1,1.2\r\n";
  const auto table = flapsim::sweep::read_case_table((dir / "bom.csv").string());
  ASSERT_EQ(table.keys.size(), 2u);
  EXPECT_EQ(table.keys[0], "kinematics.rotation_phase");
  ASSERT_EQ(table.points.size(), 1u);
  EXPECT_EQ(table.points[0][1].value, 1.2);
  const FlapsimOutcome r = sweep_with_table(dir, "kinematics.rotation_phase;air.density\n-0,1;1,2\n");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find((dir / "table.csv").string() + ":1: the header \"kinematics.rotation_phase;air.density\" is "
                                                       "separated by ';'"),
            std::string::npos)
      << r.err;
}

// A number with a decimal comma in quotes ("20,5", a spreadsheet's CSV in such a locale) is
// one quoted cell; the message says the decimal mark is a point. Before: the comma split it
// ("the row has 2 cells, the header 1 (the row has quotes: ...)").
TEST(CaseTableErrors, AQuotedDecimalCommaIsNamed) {
  ScratchDir dir("table_quoted_comma");
  const FlapsimOutcome r = sweep_with_table(dir, "kinematics.frequency_hz\n\"20,5\"\n");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find(located(dir, 2, "kinematics.frequency_hz") +
                       "'20,5' is not a number: the table's decimal mark is a point (20.5, not \"20,5\")"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

// Quoted cells as spreadsheets and R's write.csv write them (RFC 4180): a quoted header, a
// quoted path holding a comma, "" for a quote. Before: the header was the unknown key
// '"kinematics.rotation_phase"', and "my wing,v2.toml" two cells.
TEST(CaseTableErrors, QuotedCellsAreReadAsSpreadsheetsWriteThem) {
  ScratchDir dir("table_quoted_cells");
  std::ofstream(dir / "t.csv") << "\"kinematics.rotation_phase\", \"numerics.leading_edge\",\"wing\"\n"
                                  "\"-0.1\",\"shed\", \"my wing,v2.toml\" \n0.1,none,\"a \"\"b\"\".toml\"\n";
  const flapsim::sweep::CaseTable t = flapsim::sweep::read_case_table((dir / "t.csv").string());
  ASSERT_EQ(t.keys.size(), 3u);
  EXPECT_EQ(t.keys[0], "kinematics.rotation_phase");
  EXPECT_EQ(t.keys[2], "wing");
  ASSERT_EQ(t.points.size(), 2u);
  EXPECT_EQ(t.points[0][0].value, -0.1);
  EXPECT_EQ(t.points[0][1].word, "shed");
  EXPECT_EQ(t.points[0][2].word, "my wing,v2.toml");
  EXPECT_EQ(t.points[1][2].word, "a \"b\".toml");
  // A quote left open is named at its row.
  const FlapsimOutcome r = sweep_with_table(dir, "kinematics.rotation_phase\n\"-0.1\n");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find((dir / "table.csv").string() + ":2: a quote (\") opened and not closed in the row"),
            std::string::npos)
      << r.err;
}

}  // namespace
