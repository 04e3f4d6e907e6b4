// `flapsim reduce` compares the FEM's first bending mode with the chain mode of the same
// shape (largest MAC), not with the chain's first mode that its own energy split calls
// bending (issue 34, item 9; docs/reduction.md, "Checking the chain against the FEM").
// Before: the first MAV film wing (25 um film) with 8 bodies was warned "first bending
// mode differs from the FEM's by +91 %" (chain 123.43 Hz against FEM 64.75 Hz, MAC 0.01)
// while the report's correlation table paired the FEM's 64.75 Hz mode with the chain's
// 66.78 Hz mode (+3.1 %).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "robustness_helpers.hpp"

using namespace flapsim::test;

namespace {

TEST(ModePairingWarning, TheFirstBendingRowIsTheCorrelationTablesPair) {
  ScratchDir dir("mode_pairing_warning");
  const FlapsimOutcome out = run_flapsim_capturing_stderr(
      dir.path(), "reduce " + kSourceDir + "/wings/mav_film_wing_25um.toml --bodies 8 -o " + (dir / "r").string());
  ASSERT_EQ(out.status, 0) << out.err;
  EXPECT_EQ(out.err.find("first bending mode differs"), std::string::npos) << out.err;
  std::ifstream in(dir / "r" / "report.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string report = text.str();
  // The row names the FEM mode and its partner; the same pair stands in the table of every
  // FEM beam mode with the chain mode that correlates best.
  const auto row = report.find("| first bending [Hz] (FEM mode ");
  ASSERT_NE(row, std::string::npos) << report;
  int fem_mode = 0, chain_mode = 0;
  ASSERT_EQ(std::sscanf(report.c_str() + row, "| first bending [Hz] (FEM mode %d, chain mode %d)", &fem_mode, &chain_mode), 2);
  const auto table = report.find("## FEM beam modes and the chain mode that correlates best");
  ASSERT_NE(table, std::string::npos);
  const std::string pair_row = "| " + std::to_string(fem_mode) + " | bending | ";
  const auto at = report.find(pair_row, table);
  ASSERT_NE(at, std::string::npos) << report.substr(table);
  const std::string line = report.substr(at, report.find('\n', at) - at);
  // | FEM mode | kind | FEM f | chain mode | chain f | error | MAC |: the fourth cell.
  std::stringstream cells(line);
  std::string cell;
  for (int i = 0; i < 5; ++i) std::getline(cells, cell, '|');
  EXPECT_EQ(std::stoi(cell), chain_mode) << line;
}

}  // namespace
