#include "wings/loader/outline_csv.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>

#include "wings/loader/bounded_input_file.hpp"
#include "wings/loader/csv_number.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/text_trim.hpp"

namespace flapsim::wings {

namespace {

// The two fields of a data line: split at its one comma, or, on a line without a comma, at
// the tabs or spaces between two words (a tab-separated "XY coordinates" export). False when
// the line is not two fields so.
bool two_fields(const std::string& t, std::string& a, std::string& b) {
  const auto comma = t.find(',');
  if (comma != std::string::npos) {
    if (t.find(',', comma + 1) != std::string::npos) return false;
    a = t.substr(0, comma);
    b = t.substr(comma + 1);
    return true;
  }
  const auto gap = t.find_first_of(" \t");
  if (gap == std::string::npos) return false;
  const auto second = t.find_first_not_of(" \t", gap);
  if (second == std::string::npos || t.find_first_of(" \t", second) != std::string::npos) return false;
  a = t.substr(0, gap);
  b = t.substr(second);
  return true;
}

// A header line: two fields, the first a name starting with x, the second one starting with y,
// either maybe followed by a unit or a note ("x_mm", "x [mm]", "X_coord"; case ignored). The
// unit is not read: a CSV outline is scaled to the wing file's `span`.
bool is_header(const std::string& t) {
  std::string a, b;
  if (!two_fields(t, a, b)) return false;
  const auto starts_with = [](const std::string& field, char letter) {
    const std::string f = trim(field);
    return !f.empty() && std::tolower(static_cast<unsigned char>(f[0])) == letter;
  };
  return starts_with(a, 'x') && starts_with(b, 'y');
}

}  // namespace

OutlineCsv read_outline_csv_lines(const std::string& path, const std::string& key) {
  // Bounded: a regular file of limited size (not /dev/zero, a FIFO or a folder).
  check_bounded_input_file(path, key, "the outline file", kMaxOutlineFileBytes);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, key, "cannot open the outline file");
  OutlineCsv out;
  std::string line;
  int line_no = 0;
  bool header_seen = false;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.find('\0') != std::string::npos)
      throw InputError(path, line_no, key, "the outline file holds a NUL byte: not a text file");
    const std::string t = trim(line_no == 1 ? without_byte_order_mark(line) : line);
    if (t.empty() || t[0] == '#') continue;
    std::string xs, ys;
    double x = 0.0, y = 0.0;
    if (!header_seen) {
      header_seen = true;
      if (is_header(t)) continue;  // "x,y", "X<tab>Y", "x_mm,y_mm", "x [mm], y [mm]"
      if (two_fields(t, xs, ys) && !parse_csv_number(xs, x) && !parse_csv_number(ys, y))
        throw InputError(path, line_no, key,
                         "a header line names x first, then y (\"x,y\", \"x [mm],y [mm]\"), found \"" +
                             t.substr(0, 80) + (t.size() > 80 ? "..." : "") +
                             "\": x is the chordwise and y the spanwise coordinate (docs/wing_file.md)");
      // No header: fall through and read the line as data.
    }
    if (!two_fields(t, xs, ys) || !parse_csv_number(xs, x) || !parse_csv_number(ys, y))
      throw InputError(path, line_no, key,
                       "expected a line \"x,y\" (or x and y separated by tabs or spaces) with two finite "
                       "numbers (no denormals), found \"" +
                           t.substr(0, 80) + (t.size() > 80 ? "..." : "") + "\"");
    if (out.points.size() >= kMaxOutlinePoints)
      throw InputError(path, line_no, key,
                       "more than " + std::to_string(kMaxOutlinePoints) +
                           " outline points (meshing costs about n^2: simplify the outline to "
                           "the mesh size, docs/wing_file.md)");
    out.points.emplace_back(x, y);
    out.lines.push_back(line_no);
  }
  if (in.bad()) throw InputError(path, line_no, key, "reading the outline file failed");
  if (out.points.size() < 3)
    throw InputError(path, line_no, key,
                     "an outline needs at least 3 points, found " + std::to_string(out.points.size()));
  return out;
}

Polygon read_outline_csv(const std::string& path, const std::string& key) {
  return read_outline_csv_lines(path, key).points;
}

}  // namespace flapsim::wings
