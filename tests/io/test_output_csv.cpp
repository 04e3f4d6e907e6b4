// CSV output: the one-shot table writer and the time-series writer whose
// published file stays valid when a run dies or unwinds.

#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/csv_writer.hpp"
#include "common/scratch_dir.hpp"

#include <gtest/gtest.h>

#include <chrono>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using flapsim::io::CsvTimeSeriesWriter;
using flapsim::io::write_csv;
using flapsim::test::ScratchDir;

namespace {

std::vector<std::string> read_lines(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<double> parse_row(const std::string& line) {
  std::vector<double> v;
  std::stringstream ss(line);
  for (std::string cell; std::getline(ss, cell, ',');) v.push_back(std::strtod(cell.c_str(), nullptr));
  return v;
}

// A file is a valid series if it ends with a newline, its first line is the
// header and every row has one number per column.
void expect_valid_series(const fs::path& p, std::size_t columns, std::size_t rows) {
  std::ifstream in(p, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  const auto lines = read_lines(p);
  ASSERT_EQ(lines.size(), rows + 1);
  for (std::size_t r = 1; r < lines.size(); ++r) {
    const auto v = parse_row(lines[r]);
    ASSERT_EQ(v.size(), columns) << "row " << r;
    EXPECT_EQ(v[0], static_cast<double>(r - 1) * 0.001) << "row " << r;  // t_s column
  }
}

}  // namespace

TEST(OutputCsv, WriteCsvRoundTripsEveryDoubleExactly) {
  // std::to_chars writes the shortest text that strtod reads back to the same
  // double (C++17 [charconv]); so values come back bit for bit.
  ScratchDir dir("csv_roundtrip");
  const std::vector<std::vector<double>> rows = {
      {0.0, 1.0 / 3.0, -2.5e-17}, {1e300, -0.1, 6.02214076e23}, {std::nextafter(1.0, 2.0), 42.0, -0.0}};
  const fs::path file = dir / "sub/table.csv";  // the directory is created
  write_csv(file, {"t_s", "lift_N", "phi_rad"}, rows);
  const auto lines = read_lines(file);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "t_s,lift_N,phi_rad");
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const auto v = parse_row(lines[r + 1]);
    ASSERT_EQ(v.size(), 3u);
    for (std::size_t c = 0; c < 3; ++c) EXPECT_EQ(v[c], rows[r][c]);
  }
  EXPECT_TRUE(dir.temporaries().empty());
}

TEST(OutputCsv, WriteCsvFromMatrixAndTextCells) {
  ScratchDir dir("csv_matrix");
  Eigen::MatrixXd m(2, 2);
  m << 1.5, 2.0, -3.0, 4.25;
  write_csv(dir / "m.csv", {"y_m", "EI_Nm2"}, m);
  EXPECT_EQ(read_lines(dir / "m.csv"), (std::vector<std::string>{"y_m,EI_Nm2", "1.5,2", "-3,4.25"}));
  // RFC 4180: a cell with a comma or quote is quoted, quotes doubled.
  write_csv(dir / "t.csv", {"frequency_Hz", "kind"},
            std::vector<std::vector<std::string>>{{"12.5", "bending"}, {"30", "torsion, \"first\""}});
  EXPECT_EQ(read_lines(dir / "t.csv"),
            (std::vector<std::string>{"frequency_Hz,kind", "12.5,bending", "30,\"torsion, \"\"first\"\"\""}));
}

TEST(OutputCsv, WrongRowLengthWritesNothing) {
  ScratchDir dir("csv_bad");
  EXPECT_THROW(write_csv(dir / "bad.csv", {"a", "b"}, std::vector<std::vector<double>>{{1, 2}, {3}}),
               std::invalid_argument);
  EXPECT_TRUE(dir.files().empty());
}

TEST(OutputCsv, FailedWriteKeepsThePreviousFile) {
  ScratchDir dir("csv_keep");
  const fs::path file = dir / "x.txt";
  flapsim::io::write_text_atomically(file, "old\n");
  EXPECT_THROW(flapsim::io::write_file_atomically(file, [](std::ostream& out) {
                 out << "half of the new content";
                 throw std::runtime_error("writer failed midway");
               }),
               std::runtime_error);
  EXPECT_EQ(read_lines(file), std::vector<std::string>{"old"});
  EXPECT_TRUE(dir.temporaries().empty());
}

TEST(OutputCsv, TimeSeriesPublishesEveryNRowsAndOnClose) {
  ScratchDir dir("csv_series");
  const fs::path file = dir / "history.csv";
  CsvTimeSeriesWriter w(file, {"t_s", "lift_N", "tip_z_m"}, 3);
  expect_valid_series(file, 3, 0);  // header alone right away
  for (int i = 0; i < 7; ++i) {
    w.append({i * 0.001, 0.1 * i, -0.01 * i});
    // Published rows: the largest multiple of 3 not above the rows appended.
    EXPECT_EQ(w.published_rows(), static_cast<std::size_t>((i + 1) / 3 * 3));
    expect_valid_series(file, 3, w.published_rows());
  }
  w.close();
  expect_valid_series(file, 3, 7);
  EXPECT_TRUE(dir.temporaries().empty()) << dir.temporaries().front();
  EXPECT_EQ(dir.files(), std::vector<std::string>{"history.csv"});
}

TEST(OutputCsv, TimeSeriesWithAMaximumIntervalPublishesAfterTwiceTheRows) {
  // publish_every 2, at most an hour between publications: published after 2, 4, 8 and 16
  // rows (each time as many new rows as were published), then at close().
  ScratchDir dir("csv_series_interval");
  const fs::path file = dir / "history.csv";
  CsvTimeSeriesWriter w(file, {"t_s", "lift_N"}, 2, std::chrono::hours(1));
  for (std::size_t rows = 1; rows <= 20; ++rows) {
    w.append({static_cast<double>(rows - 1) * 0.001, 1.0 + static_cast<double>(rows)});
    const std::size_t expected = rows < 2 ? 0 : rows < 4 ? 2 : rows < 8 ? 4 : rows < 16 ? 8 : 16;
    EXPECT_EQ(w.published_rows(), expected) << "after row " << rows;
    expect_valid_series(file, 2, w.published_rows());
  }
  w.close();
  expect_valid_series(file, 2, 20);
  EXPECT_TRUE(dir.temporaries().empty());
  // The interval long past at every row (1 ns): every 2 rows, as without one.
  CsvTimeSeriesWriter due(dir / "due.csv", {"t_s"}, 2, std::chrono::nanoseconds(1));
  for (int i = 0; i < 9; ++i) due.append({i * 0.001});
  EXPECT_EQ(due.published_rows(), 8u);
  EXPECT_THROW(CsvTimeSeriesWriter(dir / "bad.csv", {"t_s"}, 2, -std::chrono::seconds(1)), std::invalid_argument);
}

TEST(OutputCsv, TimeSeriesOfAKilledProcessIsValidUpToTheLastPublication) {
  // The child appends 5 rows with publication every 2 rows and dies without
  // running any destructor (std::_Exit), as a crashed or killed run would.
  ScratchDir dir("csv_crash");
  const fs::path file = dir / "history.csv";
  EXPECT_EXIT(
      {
        auto* w = new CsvTimeSeriesWriter(file, {"t_s", "lift_N"}, 2);
        for (int i = 0; i < 5; ++i) w->append({i * 0.001, 1.0 + i});
        std::_Exit(0);
      },
      ::testing::ExitedWithCode(0), "");
  expect_valid_series(file, 2, 4);
}

TEST(OutputCsv, TimeSeriesUnwoundByAnExceptionKeepsEveryRow) {
  // A diverging run throws NumericalFailure; the writer's destructor publishes
  // every row appended before it.
  ScratchDir dir("csv_unwind");
  const fs::path file = dir / "history.csv";
  try {
    CsvTimeSeriesWriter w(file, {"t_s", "lift_N"}, 100);
    for (int i = 0; i < 5; ++i) w.append({i * 0.001, 2.0 * i});
    throw std::runtime_error("diverged");
  } catch (const std::runtime_error&) {
  }
  expect_valid_series(file, 2, 5);
  EXPECT_TRUE(dir.temporaries().empty());
}

TEST(OutputCsv, TimeSeriesRejectsRowsOfTheWrongLength) {
  ScratchDir dir("csv_series_bad");
  CsvTimeSeriesWriter w(dir / "h.csv", {"t_s", "lift_N"}, 1);
  EXPECT_THROW(w.append({1.0}), std::invalid_argument);
  EXPECT_THROW(w.append({1.0, 2.0, 3.0}), std::invalid_argument);
  w.append({0.0, 2.0});
  w.close();
  expect_valid_series(dir / "h.csv", 2, 1);
}

TEST(OutputCsv, NonFiniteValuesAreWrittenAsNanAndInf) {
  EXPECT_EQ(flapsim::io::format_number(std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(flapsim::io::format_number(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(flapsim::io::format_number(-std::numeric_limits<double>::infinity()), "-inf");
  EXPECT_EQ(flapsim::io::format_number(0.046), "0.046");
}

TEST(OutputCsv, UnwritableDirectoryIsAnOutputErrorNamingThePath) {
  // A regular file where the output directory should be (as with "-o" pointing at a file).
  ScratchDir dir("csv_unwritable");
  flapsim::io::write_text_atomically(dir / "taken", "x\n");
  try {
    write_csv(dir / "taken/table.csv", {"a"}, std::vector<std::vector<double>>{{1.0}});
    FAIL() << "expected OutputError";
  } catch (const flapsim::io::OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("taken"), std::string::npos) << e.what();
  }
  EXPECT_THROW(CsvTimeSeriesWriter(dir / "taken/history.csv", {"t_s"}), flapsim::io::OutputError);
  EXPECT_EQ(dir.files(), std::vector<std::string>{"taken"});
}
