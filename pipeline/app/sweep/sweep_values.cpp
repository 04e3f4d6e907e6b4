#include "pipeline/app/sweep/sweep_values.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

#include "pipeline/io/case_file.hpp"
#include "pipeline/io/csv_writer.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/text_trim.hpp"

namespace flapsim::sweep {

namespace {

[[noreturn]] void bad(const std::string& text, const std::string& why) {
  throw InputError("", 0, "--vary", "'" + text + "': " + why);
}

double parse_number(const std::string& whole, const std::string& s) {
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(s, &used);
  } catch (const std::exception&) {
    bad(whole, "'" + s + "' is not a number");
  }
  if (used != s.size() || !std::isfinite(v)) bad(whole, "'" + s + "' is not a number");
  return v;
}

// Rounds away the binary noise of start + i·step (0.1 + 3·0.05 = 0.25000000000000006).
// A value that should be zero is noise alone (−0.3 + 3·0.1 = 5.55e-17, which "%.12g" keeps):
// below 1e-9 of the step it is zero (it named the case's folder "03_5.551115123e-17").
double tidy(double v, double step) {
  if (std::abs(v) < 1e-9 * std::abs(step)) return 0.0;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.12g", v);
  return std::stod(buf);
}

// The parts without the blanks around them; blanks inside stay ("2 6" is no number, a path
// "my wings/a.toml" keeps its space: before, both lost it, and "2 6" ran 26 Hz).
std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::size_t from = 0;
  for (std::size_t at = s.find(sep); at != std::string::npos; from = at + 1, at = s.find(sep, from))
    parts.push_back(wings::trim(s.substr(from, at - from)));
  parts.push_back(wings::trim(s.substr(from)));
  return parts;
}

}  // namespace

bool is_word_value(const std::string& s) {
  if (s.empty() || !std::isalpha(static_cast<unsigned char>(s.front()))) return false;
  for (char c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') return false;
  std::string lower;
  for (char c : s) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower != "inf" && lower != "nan" && lower != "infinity";
}

Assignment word_assignment(const std::string& key, const std::string& word) { return {key, 0.0, word}; }

bool takes_paths(const std::string& key) { return key == "wing"; }

Variation parse_variation(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    bad(text, "expected KEY=start:step:stop or KEY=v1,v2,...");
  Variation v;
  v.key = wings::trim(text.substr(0, eq));
  if (v.key.empty()) bad(text, "expected KEY=start:step:stop or KEY=v1,v2,...");
  const std::string values = text.substr(eq + 1);
  if (takes_paths(v.key)) {  // wing=wings/a.toml,wings/b.toml
    for (const auto& s : split(values, ','))
      if (s.empty())
        bad(text, "an empty path in the list of wing files");
      else
        v.values.push_back(word_assignment(v.key, s));
  } else if (values.find(':') != std::string::npos) {
    const auto p = split(values, ':');
    if (p.size() != 3) bad(text, "a range is start:step:stop");
    const double start = parse_number(text, p[0]), step = parse_number(text, p[1]),
                 stop = parse_number(text, p[2]);
    if (step == 0.0) bad(text, "the step must not be zero");
    if ((stop - start) * step < 0.0) bad(text, "the step goes away from stop");
    const double count = std::floor((stop - start) / step + 1e-9);  // steps: count + 1 values
    if (count + 1.0 > kMaxVaryValues) bad(text, "more than " + std::to_string(kMaxVaryValues) + " values");
    for (long i = 0; i <= static_cast<long>(count); ++i)
      v.values.push_back({v.key, tidy(start + i * step, step)});
  } else {
    for (const auto& s : split(values, ','))
      v.values.push_back(is_word_value(s) ? word_assignment(v.key, s)
                                          : Assignment{v.key, parse_number(text, s)});
  }
  if (v.values.empty()) bad(text, "no values");
  if (v.values.size() > kMaxVaryValues) bad(text, "more than " + std::to_string(kMaxVaryValues) + " values");
  return v;
}

std::vector<CasePoint> cartesian_grid(const std::vector<Variation>& variations) {
  std::set<std::string> keys;
  double count = 1.0;
  for (const Variation& v : variations) {
    if (!keys.insert(v.key).second) bad(v.key, "the key is varied twice");
    count *= static_cast<double>(v.values.size());
  }
  if (count > 1e6) throw InputError("", 0, "--vary", "the grid has more than 1000000 cases");
  std::vector<CasePoint> points{CasePoint{}};
  for (const Variation& v : variations) {
    std::vector<CasePoint> next;
    next.reserve(points.size() * v.values.size());
    for (const CasePoint& p : points)
      for (const Assignment& value : v.values) {
        CasePoint q = p;
        q.push_back(value);
        next.push_back(std::move(q));
      }
    points = std::move(next);
  }
  return points;
}

io::Case load_case_with(const std::string& case_file, const std::string& key, double value) {
  return load_case_with(case_file, Assignment{key, value});
}

io::Case load_case_with(const std::string& case_file, const Assignment& a) {
  (void)io::load_case_file(case_file);  // errors in the file itself point at its real lines
  return io::load_case_file(case_file, {{a.key, value_text(a)}});
}

std::string value_label(double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", value);
  return buf;
}

std::string value_text(double value) { return io::format_number(value); }

std::string value_label(const Assignment& a) {
  if (takes_paths(a.key)) return std::filesystem::path(a.word).stem().string();
  return a.word.empty() ? value_label(a.value) : a.word;
}

std::string value_text(const Assignment& a) {
  if (a.word.empty()) return value_text(a.value);
  if (a.word == "true" || a.word == "false") return a.word;
  return "\"" + a.word + "\"";  // a word has no quote or backslash to escape
}

std::pair<double, std::string> value_key(const Assignment& a) { return {a.value, a.word}; }

}  // namespace flapsim::sweep
