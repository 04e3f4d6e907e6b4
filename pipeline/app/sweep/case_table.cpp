#include "pipeline/app/sweep/case_table.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include "wings/loader/input_error.hpp"
#include "wings/loader/text_trim.hpp"

namespace flapsim::sweep {

using wings::trim;
using wings::without_byte_order_mark;

namespace {

std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  std::string cur;
  for (char c : line) {
    if (c == ',') {
      cells.push_back(trim(cur));
      cur.clear();
    } else {
      cur += c;
    }
  }
  cells.push_back(trim(cur));
  return cells;
}

}  // namespace

CaseTable read_case_table(const std::string& path) {
  // A regular file (/dev/zero or a FIFO would be read without end).
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw InputError(path, 0, "--cases", "not a regular file (a device, FIFO or folder)");
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "--cases", "cannot open the case table for reading");
  CaseTable table;
  std::string line;
  int number = 0;
  bool header = true;
  while (std::getline(in, line)) {
    ++number;
    const std::string t = trim(number == 1 ? without_byte_order_mark(line) : line);
    if (t.empty() || t.front() == '#') continue;
    const auto cells = cells_of(t);
    if (header) {
      // A table of one column whose name holds a ';' was written with semicolons (a
      // spreadsheet's CSV in a locale whose decimal mark is the comma).
      if (cells.size() == 1 && cells[0].find(';') != std::string::npos)
        throw InputError(path, number, "",
                         "the header \"" + cells[0] + "\" is separated by ';': the table's cells are separated by "
                         "commas, with a point as the decimal mark (kinematics.rotation_phase,air.density)");
      std::set<std::string> seen;
      for (const std::string& k : cells) {
        if (k.empty()) throw InputError(path, number, "", "empty column name in the header");
        if (!seen.insert(k).second) throw InputError(path, number, k, "the column appears twice");
      }
      table.keys = cells;
      table.header_line = number;
      header = false;
      continue;
    }
    if (cells.size() != table.keys.size()) {
      // A quoted number with a decimal comma ("20,5", as a spreadsheet in such a locale
      // writes it) splits into two cells: say so rather than count cells.
      const bool quoted_comma = t.find('"') != std::string::npos;
      throw InputError(path, number, "",
                       "the row has " + std::to_string(cells.size()) + " cells, the header " +
                           std::to_string(table.keys.size()) +
                           (quoted_comma ? " (the row has quotes: the table's cells are plain numbers separated by "
                                           "commas, with a point as the decimal mark: 20.5, not \"20,5\")"
                                         : ""));
    }
    CasePoint point;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      // A spreadsheet may quote its text cells ("shed"): one pair of quotes around a cell is dropped.
      const std::string& cell = cells[i];
      const bool quoted = cell.size() >= 2 && cell.front() == '"' && cell.back() == '"' &&
                          cell.find('"', 1) == cell.size() - 1;
      const std::string s = quoted ? cell.substr(1, cell.size() - 2) : cell;
      if (is_word_value(s) || (takes_paths(table.keys[i]) && !s.empty())) {  // shed, true; a wing file
        point.push_back(word_assignment(table.keys[i], s));
        continue;
      }
      double v = 0.0;
      const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
      if (s.empty() || r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(v))
        throw InputError(path, number, table.keys[i], "'" + s + "' is not a number");
      point.push_back({table.keys[i], v});
    }
    table.points.push_back(std::move(point));
    table.lines.push_back(number);
  }
  if (header) throw InputError(path, 0, "--cases", "the case table has no header");
  if (table.points.empty()) throw InputError(path, 0, "--cases", "the case table has no rows");
  return table;
}

}  // namespace flapsim::sweep
