// The chain-vs-FEM errors of report.md and summary.json against a zero FEM value: there is
// no relative error, and it must not read as a perfect match. A bending-moment load case
// that loaded nothing (tip zone on one line, test_tip_zone_on_a_line.cpp) gave "FEM 0,
// chain 0.000308 rad, +0.00 %".
#include <gtest/gtest.h>

#include <cmath>

#include "pipeline/io/reduction_files.hpp"
#include "reduction/reduction_report.hpp"

TEST(RelativeErrorOfZero, AZeroFemValueHasNoRelativeErrorAndTheReportSaysSo) {
  using flapsim::reduction::relative_error;
  EXPECT_NEAR(relative_error(1.1, 1.0), 0.1, 1e-15);  // chain / FEM − 1
  EXPECT_TRUE(std::isnan(relative_error(0.000308203, 0.0)));
  EXPECT_EQ(flapsim::io::format_percent(relative_error(0.000308203, 0.0)), "n/a");
  EXPECT_EQ(flapsim::io::format_percent(-0.0024), "-0.24 %");
}
