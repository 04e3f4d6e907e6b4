// A measured cycle of kinematics as a table, inline or a CSV file's column (docs/case_file.md,
// "Measured kinematics"): a
// table whose spline accelerates with its points' scatter is warned at its values, naming the
// harmonics that fit it; `harmonics = N` flies the table's least-squares Fourier series, which
// check's summary describes; too many harmonics for the points are refused at the key.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "hover_case_text.hpp"
#include "inline_case.hpp"
#include "mbd/angle_units.hpp"
#include "pipeline/io/case_summary.hpp"

namespace {

/// hover_case_text's case with its sweep (line 4) as `points` evenly spaced values of its
/// 50 cos 2πs deg, printed with `decimals` decimals, and `extra` inside the table.
std::string measured_sweep_case(int points, int decimals, const std::string& extra = "") {
  std::string phase, deg;
  for (int i = 0; i < points; ++i) {
    const double s = static_cast<double>(i) / points;
    char value[48];
    std::snprintf(value, sizeof value, "%.*f", decimals, 50.0 * std::cos(2.0 * std::numbers::pi * s));
    phase += (i ? ", " : "") + std::to_string(s);
    deg += (i ? ", " : "") + std::string(value);
  }
  std::string text = hover_case_text("cycles = 1\n");
  const std::string sweep = "sweep = { cos_deg = [50.0] }";
  text.replace(text.find(sweep), sweep.size(),
               "sweep = { phase = [" + phase + "], deg = [" + deg + "]" + extra + " }");
  return text;
}

}  // namespace

// 1000 points printed with two decimals: their rounding is 99 % of the spline's rms
// acceleration (tests/mbd/test_fourier_fit.cpp), warned at kinematics.sweep.deg on line 4 with
// one harmonic as the fit; six decimals leave the spline the motion's.
TEST(MeasuredKinematics, ATableRoundedToTwoDecimalsIsWarnedAtItsValues) {
  const flapsim::io::Case rounded = case_from_text(measured_sweep_case(1000, 2));
  ASSERT_EQ(rounded.warnings.size(), 1u);
  EXPECT_EQ(rounded.warnings[0].key, "kinematics.sweep.deg");
  EXPECT_EQ(rounded.warnings[0].line, 4);
  EXPECT_NE(rounded.warnings[0].message.find(
                "of the rms acceleration of the spline through the table's 1000 points"),
            std::string::npos)
      << rounded.warnings[0].message;
  EXPECT_NE(rounded.warnings[0].message.find("harmonics = 1 leaves"), std::string::npos);
  EXPECT_TRUE(case_from_text(measured_sweep_case(1000, 6)).warnings.empty());
}

// A recorded wingbeat that drifts (50 points of 50 cos 2πs + 19 s deg, six decimals: its last
// point 18.2 deg above the first) is warned as a table that does not close, at its
// values (line 4), naming the closing step's steepness against the steepest interior one (2.74
// times); the scatter warning, which it set off before (94 % "scatter"), is not given. The same
// table without the drift, and five points of a sine whose closing interval straddles its
// steepest part (1.24 times), are not warned.
TEST(MeasuredKinematics, ATableThatDoesNotCloseIsWarnedAsSuch) {
  const auto table_case = [](const std::vector<double>& phase, double drift_deg, double (*shape)(double)) {
    std::string p, v;
    for (std::size_t i = 0; i < phase.size(); ++i) {
      char value[48];
      std::snprintf(value, sizeof value, "%.6f", shape(phase[i]) + drift_deg * phase[i]);
      p += (i ? ", " : "") + std::to_string(phase[i]);
      v += (i ? ", " : "") + std::string(value);
    }
    std::string text = hover_case_text("cycles = 1\n");
    const std::string sweep = "sweep = { cos_deg = [50.0] }";
    return text.replace(text.find(sweep), sweep.size(), "sweep = { phase = [" + p + "], deg = [" + v + "] }");
  };
  const auto cosine = [](double s) { return 50.0 * std::cos(2.0 * std::numbers::pi * s); };
  const auto sine = [](double s) { return 50.0 * std::sin(2.0 * std::numbers::pi * s); };
  std::vector<double> fifty;
  for (int i = 0; i < 50; ++i) fifty.push_back(i / 50.0);
  const flapsim::io::Case drifting = case_from_text(table_case(fifty, 19.0, cosine));
  ASSERT_EQ(drifting.warnings.size(), 1u);
  EXPECT_EQ(drifting.warnings[0].key, "kinematics.sweep.deg");
  EXPECT_EQ(drifting.warnings[0].line, 4);
  const std::string& what = drifting.warnings[0].message;
  EXPECT_NE(
      what.find("the table does not close: from its last point (phase 0.98, 68.2257 deg) to its first one "
                "wingbeat on (phase 1, 50 deg) it changes by -18.2 deg in 0.02 of the cycle, 2.74 times"),
      std::string::npos)
      << what;
  EXPECT_EQ(what.find("scatter"), std::string::npos) << what;
  EXPECT_TRUE(case_from_text(table_case(fifty, 0.0, cosine)).warnings.empty());
  EXPECT_TRUE(case_from_text(table_case({0.1, 0.3, 0.5, 0.7, 0.9}, 0.0, sine)).warnings.empty());
}

// With harmonics = 1 the same rounded table is flown as its series: 50 cos 2πs to within the
// rounding (0.005 deg at most), its acceleration the motion's -(2π)² 50 cos 2πs, nothing
// warned, and the summary says how far the points lie from it (q/sqrt(12) = 0.0029 deg rms).
TEST(MeasuredKinematics, AFittedTableIsItsFourierSeries) {
  const flapsim::io::Case c = case_from_text(measured_sweep_case(1000, 2, ", harmonics = 1"));
  EXPECT_TRUE(c.warnings.empty());
  using flapsim::kDegToRad;
  for (double s : {0.0, 0.1, 0.37, 0.5, 0.81}) {
    const auto a = c.kinematics.sweep.at_phase(s);
    const double w = 2.0 * std::numbers::pi;
    EXPECT_NEAR(a.value, 50.0 * kDegToRad * std::cos(w * s), 0.005 * kDegToRad) << s;
    EXPECT_NEAR(a.acceleration, -w * w * 50.0 * kDegToRad * std::cos(w * s), 0.005 * w * w * kDegToRad) << s;
  }
  ASSERT_TRUE(c.kinematics.sweep.table_fit().has_value());
  EXPECT_EQ(c.kinematics.sweep.table_fit()->points, 1000);
  EXPECT_NEAR(c.kinematics.sweep.table_fit()->residual_rms / kDegToRad, 0.01 / std::sqrt(12.0), 0.0003);
  const std::string summary = flapsim::io::describe_case(c);
  EXPECT_NE(summary.find("sweep                  1 harmonic fitted to 1000 points: the points 0.00"),
            std::string::npos)
      << summary;
}

// 10 points determine at most 4 harmonics (9 coefficients): 5 is refused at the key's line.
TEST(MeasuredKinematics, MoreHarmonicsThanThePointsDetermineAreRefusedAtTheKey) {
  const flapsim::InputError e = error_of(measured_sweep_case(10, 3, ", harmonics = 5"));
  EXPECT_EQ(e.key(), "kinematics.sweep.harmonics");
  EXPECT_EQ(e.line(), 4);
  EXPECT_NE(std::string(e.what()).find("at most 4"), std::string::npos) << e.what();
  EXPECT_NO_THROW(case_from_text(measured_sweep_case(10, 3, ", harmonics = 4")));
  EXPECT_EQ(error_of(measured_sweep_case(10, 3, ", harmonics = 0")).key(), "kinematics.sweep.harmonics");
}

// A table of times in seconds (a 20 Hz wingbeat sampled 20 times: 0 … 0.0475 s) read as
// phases leaves 0.95 of the cycle without a point: refused at its phases, named as times and
// the period to divide by (before, its spline swung the sweep to 580 deg, warned only as an
// amplitude in the wrong unit). A table over phases 0 … 0.4 is refused without that guess;
// one whose largest gap is half the cycle is read.
TEST(MeasuredKinematics, ATableOfTimesInSecondsIsRefusedNamingThePeriod) {
  std::string text = measured_sweep_case(20, 3);
  const std::size_t from = text.find("phase = [") + 9, to = text.find(']', from);
  std::string seconds;
  for (int i = 0; i < 20; ++i) seconds += (i ? ", " : "") + std::to_string(i / 400.0);
  const flapsim::InputError e = error_of(text.replace(from, to - from, seconds));
  EXPECT_EQ(e.key(), "kinematics.sweep.phase");
  EXPECT_EQ(e.line(), 4);
  EXPECT_NE(std::string(e.what()).find("leave 0.953 of the cycle without a point (from phase 0.0475 on)"),
            std::string::npos)
      << e.what();
  EXPECT_NE(
      std::string(e.what()).find("times in seconds? The last, 0.0475, is 0.95 of the 20 Hz period: divide "
                                 "them by the period, 0.05 s"),
      std::string::npos)
      << e.what();
  std::string part_case = hover_case_text("cycles = 1\n");
  part_case.insert(part_case.find("[structure]"),
                   "deviation = { phase = [0.0, 0.2, 0.4], deg = [0, 5, 0] }\n");
  const flapsim::InputError partial = error_of(part_case);
  EXPECT_EQ(partial.key(), "kinematics.deviation.phase");
  EXPECT_EQ(std::string(partial.what()).find("times in seconds"), std::string::npos) << partial.what();
  std::string half_case = hover_case_text("cycles = 1\n");
  half_case.insert(half_case.find("[structure]"),
                   "deviation = { phase = [0.0, 0.25, 0.5], deg = [0, 5, 0] }\n");
  EXPECT_NO_THROW(case_from_text(half_case));
}

namespace {

/// A CSV file in the temporary folder holding `text`; removed with the object.
struct TemporaryCsv {
  explicit TemporaryCsv(const std::string& name, const std::string& text)
      : path((std::filesystem::temp_directory_path() / ("flapsim_" + std::to_string(::getpid()) + "_" + name))
                 .string()) {
    std::ofstream(path) << text;
  }
  ~TemporaryCsv() { std::filesystem::remove(path); }
  std::string path;
};

/// hover_case_text's case (20 Hz) with its sweep (line 4) a column of a CSV file.
std::string csv_sweep_case(const std::string& path, const std::string& column,
                           const std::string& extra = "") {
  std::string text = hover_case_text("cycles = 1\n");
  const std::string sweep = "sweep = { cos_deg = [50.0] }";
  return text.replace(text.find(sweep), sweep.size(),
                      "sweep = { file = \"" + path + "\", column = \"" + column + "\"" + extra + " }");
}

/// One 20 Hz wingbeat, 40 rows and the closing one, times in ms: 50 cos 2πs in 'phi' (nine
/// digits), 90 in 'alpha', the closing row's phi `closing_phi` (50 closes the wingbeat).
std::string wingbeat_csv(double closing_phi = 50.0) {
  std::string text = "# a wingbeat\nt [ms], phi, alpha\n";
  for (int i = 0; i <= 40; ++i) {
    char row[96];
    const double phi = i == 40 ? closing_phi : 50.0 * std::cos(2.0 * std::numbers::pi * i / 40.0);
    std::snprintf(row, sizeof row, "%.4f, %.9f, 90\n", 50.0 * i / 40.0, phi);
    text += row;
  }
  return text;
}

}  // namespace

// A measured wingbeat as a CSV file with its times in milliseconds (docs/case_file.md,
// "Measured kinematics"): the column is the spline through 40 points (the closing row
// dropped) of the 20 Hz case: 50 cos 2πs to the spline's error (5/384 h⁴ max|f⁗| = 0.0013 deg).
TEST(MeasuredKinematics, ACsvColumnWithTimesInMillisecondsIsOneWingbeat) {
  const TemporaryCsv csv("wingbeat.csv", wingbeat_csv());
  const flapsim::io::Case c = case_from_text(csv_sweep_case(csv.path, "phi"));
  EXPECT_TRUE(c.warnings.empty());
  for (double s : {0.0, 0.1, 0.37, 0.5, 0.81})
    EXPECT_NEAR(c.kinematics.sweep.at_phase(s).value,
                50.0 * flapsim::kDegToRad * std::cos(2.0 * std::numbers::pi * s), 0.0013 * flapsim::kDegToRad)
        << s;
}

// What a user's CSV may get wrong, each named at the CSV file's line under the case's key.
TEST(MeasuredKinematics, ACsvTablesMistakesAreNamedAtTheirLine) {
  const auto error_with = [](const std::string& csv_text, const std::string& column,
                             const std::string& extra = "") {
    const TemporaryCsv csv("mistake.csv", csv_text);
    const flapsim::InputError e = error_of(csv_sweep_case(csv.path, column, extra));
    EXPECT_EQ(e.key(), "kinematics.sweep.file");
    EXPECT_EQ(e.file(), csv.path);
    return std::make_pair(e.line(), std::string(e.what()));
  };
  // A column that is not in the header: the header's columns.
  auto [line, what] = error_with(wingbeat_csv(), "sweep");
  EXPECT_EQ(line, 2);
  EXPECT_NE(what.find("no column 'sweep' in the header (its columns after the first: 'phi', 'alpha')"),
            std::string::npos)
      << what;
  // A first column that is neither a phase nor a time with its unit.
  std::tie(line, what) = error_with("angle,phi\n0,1\n0.5,2\n0.7,1\n", "phi");
  EXPECT_EQ(line, 1);
  EXPECT_NE(what.find("the time with its unit ('t_s', 'time [s]', 't_ms', ...), found 'angle'"),
            std::string::npos);
  // Two wingbeats of times (100 ms at 20 Hz): the first row beyond one.
  std::string two = "t_s,phi\n";
  for (int i = 0; i <= 20; ++i) two += std::to_string(0.005 * i) + "," + std::to_string(i % 4) + "\n";
  std::tie(line, what) = error_with(two, "phi");
  EXPECT_EQ(line, 13);  // t = 0.055 s, the first after 0.05 s
  EXPECT_NE(what.find("the times span more than one wingbeat"), std::string::npos) << what;
  // A closing row that does not repeat the first: refused, unless the table is fitted.
  std::tie(line, what) = error_with(wingbeat_csv(50.2), "phi");
  EXPECT_EQ(line, 43);
  EXPECT_NE(what.find("must repeat the first row's: 50.2 against 50"), std::string::npos) << what;
  const TemporaryCsv open_wingbeat("open.csv", wingbeat_csv(50.2));
  EXPECT_NO_THROW(case_from_text(csv_sweep_case(open_wingbeat.path, "phi", ", harmonics = 1")));
}

// Three 20 Hz wingbeats of times, 37 rows each (not a divisor of the period's rows: the folded
// phases interleave), fitted with one harmonic: the wingbeats fold onto one and the series
// through all 111 rows is 50 cos 2πs (its coefficients exact to round-off, the rows on it).
TEST(MeasuredKinematics, AFittedCsvOfSeveralWingbeatsIsTheirMeanWingbeat) {
  std::string text = "time (s)\tphi\n";  // tab-separated, as a spreadsheet's text export
  for (int i = 0; i < 111; ++i) {
    const double t = 0.15 * i / 111.0, s = 20.0 * t;
    char row[64];
    std::snprintf(row, sizeof row, "%.17g\t%.17g\n", t, 50.0 * std::cos(2.0 * std::numbers::pi * s));
    text += row;
  }
  const TemporaryCsv csv("three_wingbeats.csv", text);
  const flapsim::io::Case c = case_from_text(csv_sweep_case(csv.path, "phi", ", harmonics = 1"));
  ASSERT_TRUE(c.kinematics.sweep.table_fit().has_value());
  EXPECT_EQ(c.kinematics.sweep.table_fit()->points, 111);
  EXPECT_LT(c.kinematics.sweep.table_fit()->residual_largest, 1e-12);
  for (double s : {0.0, 0.3, 0.6})
    EXPECT_NEAR(c.kinematics.sweep.at_phase(s).value,
                50.0 * flapsim::kDegToRad * std::cos(2.0 * std::numbers::pi * s), 1e-12)
        << s;
  // Unfitted, the same rows are refused at the first beyond one wingbeat (i = 38 of 0 … 110, line 40).
  const flapsim::InputError e = error_of(csv_sweep_case(csv.path, "phi"));
  EXPECT_EQ(e.line(), 40);
  EXPECT_NE(std::string(e.what()).find("with harmonics = N the wingbeats fold onto one"), std::string::npos)
      << e.what();
}

// A fitted CSV of times ending in its closing row (one period after the first row's time, the
// next wingbeat's start): the row is dropped, as a fitted phase column's phase-1 row is
// (docs/case_file.md, "the closing row ... dropped as the next wingbeat's start"). Before, the
// row was folded to phase 0 and fitted: with 500 in it the series' phi(0) was 31 deg off and its
// points 68 deg (rms) from it (41 points). Now 40 points, the series 50 cos 2πs to the rows' nine digits.
TEST(MeasuredKinematics, AFittedCsvOfTimesDropsItsClosingRow) {
  for (const double closing : {50.0, 500.0}) {
    const TemporaryCsv csv("fitted_closing.csv", wingbeat_csv(closing));
    const flapsim::io::Case c = case_from_text(csv_sweep_case(csv.path, "phi", ", harmonics = 1"));
    ASSERT_TRUE(c.kinematics.sweep.table_fit().has_value());
    EXPECT_EQ(c.kinematics.sweep.table_fit()->points, 40) << closing;
    EXPECT_LT(c.kinematics.sweep.table_fit()->residual_largest, 1e-8) << closing;
    EXPECT_NEAR(c.kinematics.sweep.at_phase(0.0).value, 50.0 * flapsim::kDegToRad, 1e-9) << closing;
  }
  // Two whole wingbeats and the closing row (81 rows of 20 Hz, every 1.25 ms): 80 points.
  std::string two = "t_ms,phi\n";
  for (int i = 0; i <= 80; ++i)
    two += std::to_string(1.25 * i) + "," +
           (i == 80 ? std::string("7") : std::to_string(50.0 * std::cos(2.0 * std::numbers::pi * i / 40.0))) +
           "\n";
  const TemporaryCsv csv("fitted_two.csv", two);
  const flapsim::io::Case c = case_from_text(csv_sweep_case(csv.path, "phi", ", harmonics = 1"));
  ASSERT_TRUE(c.kinematics.sweep.table_fit().has_value());
  EXPECT_EQ(c.kinematics.sweep.table_fit()->points, 80);
  EXPECT_NEAR(c.kinematics.sweep.at_phase(0.0).value, 50.0 * flapsim::kDegToRad, 1e-6);
}

// Times out of order are named as such at the row (before, the first two rows swapped gave "a
// phase outside [0, 1]"), and a table that leaves half the cycle without a row is named at the
// CSV's row the gap starts from (before, at the case file's line).
TEST(MeasuredKinematics, ACsvsTimesOutOfOrderAndItsGapAreNamedInTheCsv) {
  const TemporaryCsv swapped("swapped.csv", "t_ms,phi\n5,40\n0,50\n10,20\n20,-10\n30,-40\n");
  flapsim::InputError e = error_of(csv_sweep_case(swapped.path, "phi"));
  EXPECT_EQ(e.file(), swapped.path);
  EXPECT_EQ(e.line(), 3);
  EXPECT_NE(std::string(e.what()).find("the times must increase from row to row"), std::string::npos)
      << e.what();
  const TemporaryCsv gap("gap.csv", "# rows up to phase 0.3\nphase,phi\n0,60\n0.1,50\n0.2,40\n0.3,30\n");
  e = error_of(csv_sweep_case(gap.path, "phi"));
  EXPECT_EQ(e.file(), gap.path);
  EXPECT_EQ(e.key(), "kinematics.sweep.file");
  EXPECT_EQ(e.line(), 6);  // phase 0.3, the gap's start
  EXPECT_NE(std::string(e.what()).find("the points leave 0.7 of the cycle without a point"),
            std::string::npos)
      << e.what();
}

// A spreadsheet set to decimal commas writes fields between semicolons ("t [ms];phi" and
// "0,0;60,0"): named as such at the header's line, where before the header was split at its
// space and "found 't'" blamed the first column's name. A quoted comma-separated header
// ("phi, measured" with a comma inside quotes, as RFC 4180 writes it) is one name.
TEST(MeasuredKinematics, ASemicolonSeparatedCsvIsNamedAndQuotedNamesAreRead) {
  const TemporaryCsv semicolons("semicolons.csv", "t [ms];phi\n0,0;60,0\n10,0;30,0\n20,0;-10,0\n");
  const flapsim::InputError e = error_of(csv_sweep_case(semicolons.path, "phi"));
  EXPECT_EQ(e.line(), 1);
  EXPECT_NE(std::string(e.what()).find("fields separated by semicolons"), std::string::npos) << e.what();
  std::string quoted = "phase,\"phi, measured\"\n";
  for (int i = 0; i < 8; ++i)
    quoted += std::to_string(i / 8.0) + "," +
              std::to_string(50.0 * std::cos(2.0 * std::numbers::pi * i / 8.0)) + "\n";
  const TemporaryCsv csv("quoted.csv", quoted);
  const flapsim::io::Case c = case_from_text(csv_sweep_case(csv.path, "phi, measured"));
  EXPECT_NEAR(c.kinematics.sweep.at_phase(0.25).value, 0.0, 1e-6);  // the spline through 50 cos 2πs at a knot
  EXPECT_NEAR(c.kinematics.sweep.at_phase(0.0).value, 50.0 * flapsim::kDegToRad, 1e-6);
}

// A wingbeat recorded at another frequency than the case's: 40 rows of 50 cos 2πs over a
// 40 ms wingbeat (25 Hz) and its closing row at 40 ms, flown at the case's 20 Hz, puts the
// closing row at phase 0.8: an ordinary point, and the wing would hold 50° over the last
// 20 % of the cycle. Before: flown without a word (a user's 28 Hz record at 26.1 Hz lifted
// 6.7 % more than the harmonic wingbeat). Now warned at the CSV's last row, naming the
// frequency the rows imply; the same record at 25 Hz, and a row that does not repeat the
// first's value, are not warned.
TEST(MeasuredKinematics, ACsvRecordedAtAnotherFrequencyIsWarned) {
  std::string text = "t_ms,phi\n";
  for (int i = 0; i <= 40; ++i) {
    char row[64];
    std::snprintf(row, sizeof row, "%d,%.9f\n", i, 50.0 * std::cos(2.0 * std::numbers::pi * i / 40.0));
    text += row;
  }
  const TemporaryCsv csv("recorded_25hz.csv", text);
  const flapsim::io::Case c = case_from_text(csv_sweep_case(csv.path, "phi"));
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_EQ(c.warnings[0].file, csv.path);
  EXPECT_EQ(c.warnings[0].line, 42);  // the header, then rows 0…40
  EXPECT_EQ(c.warnings[0].key, "kinematics.sweep.file");
  EXPECT_NE(c.warnings[0].message.find(
                "the last row repeats the first row's 'phi' (50) as a wingbeat's closing row "
                "does, but lies at phase 0.8000 of the case's 20 Hz wingbeat: the rows look "
                "like one wingbeat of 40 ms (25 Hz)"),
            std::string::npos)
      << c.warnings[0].message;
  EXPECT_NE(c.warnings[0].message.find("over the last 20.0 % of the cycle; give frequency_hz = 25"),
            std::string::npos)
      << c.warnings[0].message;
  // At the record's own 25 Hz the row closes the wingbeat and is dropped: nothing said.
  std::string at_25 = csv_sweep_case(csv.path, "phi");
  at_25.replace(at_25.find("frequency_hz = 20.0"), 19, "frequency_hz = 25.0");
  EXPECT_TRUE(case_from_text(at_25).warnings.empty());
  // The rows without the closing one (the last at 39 ms, phase 0.78, 49.4°): not warned.
  const TemporaryCsv open("recorded_open.csv", text.substr(0, text.rfind("40,")));
  EXPECT_TRUE(case_from_text(csv_sweep_case(open.path, "phi")).warnings.empty());
}
