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

// The cells of a row, separated by commas; a cell in double quotes (a spreadsheet's text
// cells, R's write.csv quotes every cell and the header) may hold commas, and "" in it is a
// quote (RFC 4180). Before, quotes were dropped only around a whole data cell: a quoted
// header was an unknown key '"kinematics.rotation_phase"', and "my wing,v2.toml" two cells.
std::vector<std::string> cells_of(const std::string& line, const std::string& path, int number) {
  std::vector<std::string> cells;
  std::size_t i = 0;
  while (true) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    std::string cell;
    if (i < line.size() && line[i] == '"') {
      for (++i;; ++i) {
        if (i >= line.size())
          throw InputError(path, number, "", "a quote (\") opened and not closed in the row");
        if (line[i] != '"') {
          cell += line[i];
        } else if (i + 1 < line.size() && line[i + 1] == '"') {
          cell += '"';
          ++i;
        } else {
          ++i;
          break;
        }
      }
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
      if (i < line.size() && line[i] != ',')
        throw InputError(path, number, "", "text after the closing quote of the cell \"" + cell + "\"");
    } else {
      std::string raw;
      while (i < line.size() && line[i] != ',') raw += line[i++];
      cell = trim(raw);
    }
    cells.push_back(std::move(cell));
    if (i >= line.size()) break;
    ++i;  // the comma
  }
  return cells;
}

// For a number written with a decimal comma ("20,5", a spreadsheet's CSV in such a locale,
// quoted): ": the table's decimal mark is a point (20.5, not "20,5")"; otherwise "".
std::string decimal_comma_hint(const std::string& s) {
  const auto comma = s.find(',');
  if (comma == std::string::npos || s.find(',', comma + 1) != std::string::npos) return "";
  std::string with_point = s;
  with_point[comma] = '.';
  double v = 0.0;
  const auto r = std::from_chars(with_point.data(), with_point.data() + with_point.size(), v);
  if (r.ec != std::errc() || r.ptr != with_point.data() + with_point.size()) return "";
  return ": the table's decimal mark is a point (" + with_point + ", not \"" + s + "\")";
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
    const std::vector<std::string> cells = cells_of(t, path, number);
    if (header) {
      // A table of one column whose name holds a ';' was written with semicolons (a
      // spreadsheet's CSV in a locale whose decimal mark is the comma).
      if (cells.size() == 1 && cells[0].find(';') != std::string::npos)
        throw InputError(
            path, number, "",
            "the header \"" + cells[0] +
                "\" is separated by ';': the table's cells are separated by "
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
    if (cells.size() != table.keys.size())
      throw InputError(path, number, "",
                       "the row has " + std::to_string(cells.size()) + " cells, the header " +
                           std::to_string(table.keys.size()));
    CasePoint point;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const std::string& s = cells[i];
      if (is_word_value(s) || (takes_paths(table.keys[i]) && !s.empty())) {  // shed, true; a wing file
        point.push_back(word_assignment(table.keys[i], s));
        continue;
      }
      double v = 0.0;
      const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
      if (s.empty() || r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(v))
        throw InputError(path, number, table.keys[i], "'" + s + "' is not a number" + decimal_comma_hint(s));
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
