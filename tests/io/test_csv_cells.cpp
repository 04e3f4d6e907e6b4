// io::split_csv_line reads back what io::write_csv writes (RFC 4180 quoting): a cell with a
// comma, one with quotes, an empty one and a CRLF line end; the sweep's and the optimiser's
// tables are read with it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "pipeline/io/csv_writer.hpp"

TEST(CsvCells, SplitReadsBackTheCellsWriteCsvQuoted) {
  const auto path = std::filesystem::temp_directory_path() / "flapsim_csv_cells_test.csv";
  const std::vector<std::string> header = {"case", "note_text", "lift_N"};
  const std::vector<std::vector<std::string>> rows = {{"a, b", "he said \"yes\"", "1.5"}, {"", "plain", "-2"}};
  flapsim::io::write_csv(path, header, rows);
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(flapsim::io::split_csv_line(line), header);
  for (const auto& row : rows) {
    ASSERT_TRUE(std::getline(in, line));
    EXPECT_EQ(flapsim::io::split_csv_line(line), row) << line;
  }
  std::filesystem::remove(path);
  // A line written on Windows: the CR goes, the cells stay.
  EXPECT_EQ(flapsim::io::split_csv_line("x,\"y,z\"\r"), (std::vector<std::string>{"x", "y,z"}));
}
