#include "wings/outline_csv.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>

#include "wings/input_error.hpp"

namespace flapsim::wings {

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

// Whole-field parse: "1.5e-3" ok, "1.5mm" or "" rejected.
bool parse_number(const std::string& field, double& out) {
  const std::string f = trim(field);
  if (f.empty()) return false;
  char* end = nullptr;
  errno = 0;
  out = std::strtod(f.c_str(), &end);
  return errno == 0 && end == f.c_str() + f.size() && std::isfinite(out);
}

}  // namespace

Polygon read_outline_csv(const std::string& path, const std::string& key) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, key, "cannot open the outline file");
  Polygon poly;
  std::string line;
  int line_no = 0;
  bool header_seen = false;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    if (!header_seen) {
      header_seen = true;
      std::string compact;
      for (char c : t)
        if (c != ' ' && c != '\t') compact += c;
      if (compact == "x,y") continue;
      // No header: fall through and read the line as data.
    }
    const auto comma = t.find(',');
    double x = 0.0, y = 0.0;
    if (comma == std::string::npos || t.find(',', comma + 1) != std::string::npos ||
        !parse_number(t.substr(0, comma), x) || !parse_number(t.substr(comma + 1), y))
      throw InputError(path, line_no, key, "expected a line \"x,y\" with two numbers, found \"" + t + "\"");
    poly.emplace_back(x, y);
  }
  if (poly.size() < 3)
    throw InputError(path, line_no, key,
                     "an outline needs at least 3 points, found " + std::to_string(poly.size()));
  return poly;
}

}  // namespace flapsim::wings
