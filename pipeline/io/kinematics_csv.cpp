#include "pipeline/io/kinematics_csv.hpp"

#include "pipeline/io/csv_writer.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>

#include "wings/loader/bounded_input_file.hpp"
#include "wings/loader/csv_number.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/text_trim.hpp"

namespace flapsim::io {

namespace {

using wings::trim;

/// The fields of a line: the cells of a comma-separated line (io::split_csv_line, quotes as
/// RFC 4180), or on a line without a comma the fields between tabs (a spreadsheet's text
/// export, whose names may hold spaces: "time (s)"), or on a line without either those
/// between runs of spaces.
std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> out;
  if (line.find(',') != std::string::npos) {
    for (const std::string& cell : split_csv_line(line)) out.push_back(trim(cell));
    return out;
  }
  if (line.find('\t') != std::string::npos) {
    std::size_t from = 0;
    for (;;) {
      const std::size_t at = line.find('\t', from);
      out.push_back(trim(line.substr(from, at - from)));
      if (at == std::string::npos) return out;
      from = at + 1;
    }
  }
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

/// Seconds per unit of a time column's name (t_s, time [s], t (ms), ...); nullopt for another name.
std::optional<double> time_unit_of(std::string name) {
  name.erase(std::remove(name.begin(), name.end(), ' '), name.end());
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char ch) { return std::tolower(ch); });
  for (const char* head : {"time", "t"})
    if (name.rfind(head, 0) == 0) {
      const std::string unit = name.substr(std::string(head).size());
      for (const auto& [text, seconds] :
           {std::pair{"_s", 1.0}, std::pair{"[s]", 1.0}, std::pair{"(s)", 1.0}, std::pair{"_ms", 1e-3},
            std::pair{"[ms]", 1e-3}, std::pair{"(ms)", 1e-3}})
        if (unit == text) return seconds;
    }
  return std::nullopt;
}

}  // namespace

KinematicsCsvColumn read_kinematics_csv(const std::string& path, const std::string& column,
                                        double frequency_hz, const std::string& key, bool fitted) {
  wings::check_bounded_input_file(path, key, "the kinematics file", kMaxKinematicsCsvBytes);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, key, "cannot open the kinematics file");
  KinematicsCsvColumn out;
  std::vector<int> lines;
  std::string line;
  int line_no = 0, header_line = 0;
  std::size_t index = 0, width = 0;
  double seconds = 0.0;  // a time column's unit; 0: phases
  while (std::getline(in, line)) {
    ++line_no;
    if (line.find('\0') != std::string::npos)
      throw InputError(path, line_no, key, "the kinematics file holds a NUL byte: not a text file");
    const std::string t = trim(line_no == 1 ? wings::without_byte_order_mark(line) : line);
    if (t.empty() || t[0] == '#') continue;
    const std::vector<std::string> f = fields_of(t);
    if (header_line == 0) {
      header_line = line_no;
      // Spreadsheets set to a decimal comma (German, French) write fields between semicolons.
      if (t.find(';') != std::string::npos)
        throw InputError(
            path, line_no, key,
            "fields separated by semicolons (a spreadsheet set to decimal commas): save the table "
            "with a decimal point and commas between the fields, found \"" +
                t.substr(0, 80) + "\"");
      width = f.size();
      if (f[0] != "phase") {
        const auto unit = time_unit_of(f[0]);
        if (!unit)
          throw InputError(
              path, line_no, key,
              "the header's first column is the phase ('phase', fractions of the wingbeat) or the "
              "time with its unit ('t_s', 'time [s]', 't_ms', ...), found '" +
                  f[0] + "'");
        if (!(frequency_hz > 0.0))
          throw InputError(path, line_no, key, "a time column needs the wingbeat's frequency");
        seconds = *unit;
        out.from_times = true;
      }
      const auto it = std::find(f.begin() + 1, f.end(), trim(column));
      if (it == f.end()) {
        std::string names;
        for (std::size_t i = 1; i < f.size(); ++i) names += (i > 1 ? ", '" : "'") + f[i] + "'";
        throw InputError(path, line_no, key,
                         "no column '" + column + "' in the header (its columns after the first: " +
                             (names.empty() ? "none" : names) + ")");
      }
      index = static_cast<std::size_t>(it - f.begin());
      continue;
    }
    if (f.size() != width)
      throw InputError(path, line_no, key,
                       std::to_string(f.size()) + " fields where the header has " + std::to_string(width));
    double p = 0.0, v = 0.0;
    if (!wings::parse_csv_number(f[0], p) || !wings::parse_csv_number(f[index], v))
      throw InputError(path, line_no, key,
                       "expected numbers in the first column and in '" + column + "', found '" + f[0] +
                           "' and '" + f[index] + "'");
    out.phase.push_back(p);
    out.values.push_back(v);
    lines.push_back(line_no);
  }
  if (in.bad()) throw InputError(path, line_no, key, "reading the kinematics file failed");
  if (header_line == 0) throw InputError(path, 0, key, "the kinematics file has no header line");
  if (out.phase.size() < 3)
    throw InputError(path, line_no, key,
                     "at least 3 rows are needed, found " + std::to_string(out.phase.size()));
  // Rows in the order they were measured: a time column (fitted or not) and a phase column alike.
  for (std::size_t i = 1; i < out.phase.size(); ++i)
    if (!(out.phase[i] > out.phase[i - 1]))
      throw InputError(path, lines[i], key,
                       seconds > 0.0 ? "the times must increase from row to row"
                                     : "the first column must increase from row to row");
  if (seconds > 0.0) {
    // The phase (t − t0) f from the first row's time. Times are written rounded: a last row
    // within 1 % of its spacing of a whole number of periods on is the closing row (the next
    // wingbeat's start; phase 1 of a single wingbeat).
    const double t0 = out.phase.front() * seconds;
    const std::size_t n = out.phase.size();
    const double last_spacing = (out.phase[n - 1] - out.phase[n - 2]) * seconds * frequency_hz;
    for (std::size_t i = 0; i < n; ++i) {
      double p = (out.phase[i] * seconds - t0) * frequency_hz;
      if (i + 1 == n && p >= 0.5 && std::abs(p - std::round(p)) <= 0.01 * last_spacing) p = std::round(p);
      if (p > 1.0 && !fitted) {
        char text[400];
        std::snprintf(
            text, sizeof text,
            "the times span more than one wingbeat: this row is %.9g s after the first row's, phase %.6f of "
            "the %.9g s period of %.6g Hz%s (give one wingbeat, or fit them all: with harmonics = N the "
            "wingbeats fold onto one, and the series is their mean wingbeat's)",
            out.phase[i] * seconds - t0, p, 1.0 / frequency_hz, frequency_hz,
            i + 1 < n ? ", and rows follow it" : "");
        throw InputError(path, lines[i], key, text);
      }
      out.phase[i] = p;
    }
    if (fitted) {
      // Several wingbeats fold onto one, phase frac((t − t0) f), and the series fitted to all
      // their rows is their mean wingbeat's. A closing row is the next wingbeat's start, dropped
      // as a phase column's (its value is a measurement, not checked against the first row's).
      if (out.phase.back() >= 1.0 && out.phase.back() == std::round(out.phase.back())) {
        out.phase.pop_back();
        out.values.pop_back();
        lines.pop_back();
        if (out.phase.size() < 3)
          throw InputError(path, line_no, key, "at least 3 rows besides the closing one");
      }
      for (double& p : out.phase) p -= std::floor(p);
      out.lines = std::move(lines);
      return out;
    }
  }
  for (std::size_t i = 0; i < out.phase.size(); ++i)
    if (out.phase[i] < 0.0 || out.phase[i] > 1.0)
      throw InputError(path, lines[i], key,
                       "a phase outside [0, 1]: phases are fractions of the wingbeat (f t)");
  if (out.phase.back() == 1.0) {
    const double first = out.values.front(), closing = out.values.back();
    if (out.phase.front() != 0.0)
      throw InputError(path, lines.back(), key,
                       "phase 1 is phase 0 of the next wingbeat, which the table has no row for");
    if (!fitted && std::abs(closing - first) > 1e-9 * std::max(1.0, std::abs(first))) {
      char text[300];
      std::snprintf(
          text, sizeof text,
          "the last row is phase 0 of the next wingbeat, so its '%s' must repeat the first row's: %.10g "
          "against %.10g (a wingbeat that does not close; drop the row, or fit the table: harmonics = N)",
          column.c_str(), closing, first);
      throw InputError(path, lines.back(), key, text);
    }
    out.phase.pop_back();
    out.values.pop_back();
    if (out.phase.size() < 3)
      throw InputError(path, lines.back(), key, "at least 3 rows besides the closing one");
    lines.pop_back();
  }
  out.lines = std::move(lines);
  return out;
}

}  // namespace flapsim::io
