#include "pipeline/app/sweep/sweep_values.hpp"

#include <toml++/toml.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "pipeline/io/case_file.hpp"
#include "wings/input_error.hpp"
#include "wings/toml_reader.hpp"

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
double tidy(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.12g", v);
  return std::stod(buf);
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::string cur;
  for (char c : s) {
    if (c == sep) {
      parts.push_back(cur);
      cur.clear();
    } else if (c != ' ') {
      cur += c;
    }
  }
  parts.push_back(cur);
  return parts;
}

}  // namespace

Variation parse_variation(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    bad(text, "expected KEY=start:step:stop or KEY=v1,v2,...");
  Variation v;
  v.key = text.substr(0, eq);
  const std::string values = text.substr(eq + 1);
  if (values.find(':') != std::string::npos) {
    const auto p = split(values, ':');
    if (p.size() != 3) bad(text, "a range is start:step:stop");
    const double start = parse_number(text, p[0]), step = parse_number(text, p[1]),
                 stop = parse_number(text, p[2]);
    if (step == 0.0) bad(text, "the step must not be zero");
    if ((stop - start) * step < 0.0) bad(text, "the step goes away from stop");
    const double count = std::floor((stop - start) / step + 1e-9);
    if (count > 10000) bad(text, "more than 10000 values");
    for (long i = 0; i <= static_cast<long>(count); ++i) v.values.push_back(tidy(start + i * step));
  } else {
    for (const auto& s : split(values, ',')) v.values.push_back(parse_number(text, s));
  }
  if (v.values.empty()) bad(text, "no values");
  return v;
}

io::Case load_case_with(const std::string& case_file, const std::string& key, double value) {
  // Make sure the file itself is valid first (errors then point at its real lines).
  (void)io::load_case_file(case_file);
  toml::table doc;
  try {
    doc = toml::parse_file(case_file);
  } catch (const toml::parse_error& e) {
    throw InputError(case_file, 0, "", e.what());
  }
  const auto parts = split(key, '.');
  toml::table* table = &doc;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    toml::node* n = table->get(parts[i]);
    if (!n) {
      table->insert(parts[i], toml::table{});
      n = table->get(parts[i]);
    }
    if (!n->is_table())
      throw InputError(case_file, 0, key, "'" + parts[i] + "' is not a table, cannot vary '" + key + "'");
    table = n->as_table();
  }
  const std::string& leaf = parts.back();
  if (leaf.empty()) throw InputError(case_file, 0, key, "empty key");
  const toml::node* old = table->get(leaf);
  if (old && !old->is_number())
    throw InputError(case_file, 0, key, "only numeric keys can be varied");
  if (old && old->is_integer()) {
    if (std::abs(value - std::round(value)) > 1e-9)
      throw InputError(case_file, 0, key, "is an integer; cannot set it to " + value_label(value));
    table->insert_or_assign(leaf, static_cast<int64_t>(std::llround(value)));
  } else {
    table->insert_or_assign(leaf, value);
  }
  std::ostringstream text;
  text << doc;
  try {
    return io::read_case(wings::parse_toml_string(text.str(), case_file));
  } catch (const InputError& e) {
    throw InputError(case_file, 0, key, "with " + key + " = " + value_label(value) + ": " + e.message());
  }
}

std::string value_label(double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", value);
  return buf;
}

}  // namespace flapsim::sweep
