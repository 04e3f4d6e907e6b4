// flapsim reduce's beam.csv where a cell identifies no stiffness (reduction/beam_properties.cpp,
// docs/reduction.md "Stiffness: per cell"): a rounded 25 µm Mylar wing on a tapering CFRP spar
// (tests/data/rod_film_25um_wing.toml), whose sections' fit follows the film twisting about
// the spar. Until 2 Dec beam.csv gave EI < 0 at 24 of its 40 stations (down to −4.1e-5 N m²)
// without a word; the spar's own E π d⁴/64 is 2.0e-3 → 1.3e-4 N m².
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/io/csv_writer.hpp"

namespace {

using flapsim::test::read_text;

TEST(ReduceBeam, AFilmsUnturnedSectionsIdentifyNoStiffness) {
  const flapsim::test::ScratchDir dir("reduce_beam_film");
  ASSERT_EQ(flapsim::test::run_flapsim("reduce " FLAPSIM_SOURCE_DIR
                                       "/tests/data/rod_film_25um_wing.toml --bodies 8 -o " +
                                       (dir / "out").string()),
            0);
  std::ifstream in(dir / "out" / "beam.csv");
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  const std::vector<std::string> header = flapsim::io::split_csv_line(line);
  std::size_t ei_column = header.size();
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == "EI_N_m2") ei_column = i;
  ASSERT_LT(ei_column, header.size());
  int stations = 0, unidentified = 0;
  while (std::getline(in, line)) {
    const double ei = std::stod(flapsim::io::split_csv_line(line).at(ei_column));
    ++stations;
    if (std::isnan(ei))
      ++unidentified;
    else
      EXPECT_GT(ei, 0.0) << "station " << stations;  // no stiffness below zero
  }
  EXPECT_EQ(stations, 40);
  EXPECT_GT(unidentified, 0);  // 24 measured (2 Dec)
  EXPECT_LT(unidentified, stations);
  // The report says so, with the same count.
  const std::string report = read_text(dir / "out" / "report.md");
  EXPECT_NE(report.find("beam.csv's EI is not identified at " + std::to_string(unidentified) + " and GJ at"),
            std::string::npos)
      << report;
}

}  // namespace

namespace {

// The first bending pair of the same wing (reduction_report.cpp, docs/reduction.md "MAC"):
// the MAC in the chain's coordinates pairs the FEM's first bending mode (717.1 Hz at 8 bodies)
// with the chain's bending mode at 711.9 Hz, −0.74 %; until 2 Dec the surface samples paired
// it with the chain's first torsion mode, 66.7 Hz, and every command warned of −90.7 %.
TEST(ReduceBeam, AFilmWingsFirstBendingModePairsWithTheChainsBendingMode) {
  const flapsim::test::ScratchDir dir("reduce_film_pairs");
  const auto out = flapsim::test::run_flapsim_capturing_stderr(
      dir.path(), "reduce " FLAPSIM_SOURCE_DIR "/tests/data/rod_film_25um_wing.toml --bodies 8 -o " +
                      (dir / "out").string());
  ASSERT_EQ(out.status, 0) << out.err;
  EXPECT_EQ(out.err.find("first bending mode differs"), std::string::npos) << out.err;
  const std::string summary = read_text(dir / "out" / "summary.json");
  const double fem = flapsim::test::json_number(summary, "bending_fem_hz");
  const double chain = flapsim::test::json_number(summary, "bending_chain_hz");
  EXPECT_NEAR(chain / fem, 1.0, 0.02) << chain << " against " << fem;  // −0.74 % measured
  EXPECT_GT(chain, 5.0 * flapsim::test::json_number(summary, "torsion_chain_hz"));
}

}  // namespace
