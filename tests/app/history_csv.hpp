#pragma once
/// \file
/// \brief A run's history.csv read back for tests: one row per step (row n − 1 is step
/// n), values by column name (columns: docs/fsi.md, "history.csv").

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace flapsim::test {

struct HistoryCsv {
  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;

  /// The column's index; a missing name fails the test and gives names.size().
  std::size_t index(const std::string& name) const {
    const auto c = std::find(names.begin(), names.end(), name);
    EXPECT_NE(c, names.end()) << name;
    return static_cast<std::size_t>(c - names.begin());
  }
  /// The value of step `step` (1-based) in column `name` (NaN if the column is missing).
  double at(long step, const std::string& name) const {
    const std::size_t c = index(name);
    return c == names.size() ? NAN : rows.at(static_cast<std::size_t>(step - 1)).at(c);
  }
  /// The whole column (empty if missing).
  std::vector<double> column(const std::string& name) const {
    const std::size_t c = index(name);
    std::vector<double> x;
    if (c == names.size()) return x;
    for (const auto& r : rows) x.push_back(r.at(c));
    return x;
  }
};

inline HistoryCsv read_history_csv(const std::filesystem::path& file) {
  HistoryCsv h;
  std::ifstream in(file);
  EXPECT_TRUE(in.good()) << file;
  std::string line, cell;
  std::getline(in, line);
  for (std::stringstream s(line); std::getline(s, cell, ',');) h.names.push_back(cell);
  while (std::getline(in, line)) {
    std::vector<double> r;
    for (std::stringstream s(line); std::getline(s, cell, ',');) r.push_back(std::stod(cell));
    h.rows.push_back(r);
  }
  return h;
}

}  // namespace flapsim::test
