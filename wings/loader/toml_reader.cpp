#include "wings/loader/toml_reader.hpp"
#include "wings/loader/file_extension.hpp"
#include "wings/loader/toml_syntax_error.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "wings/loader/input_error.hpp"
#include "wings/loader/toml_key_path.hpp"
#include "wings/loader/toml_preflight.hpp"

namespace flapsim::wings {

struct TomlTable::Document {
  std::string file;
  toml::table root;
  double length_scale = 1.0;  // [m per file unit]
  std::string length_unit = "m";
  std::vector<std::string> overridden;  // dotted keys set by apply_overrides
};

namespace {

const toml::table* as_tbl(const void* p) { return static_cast<const toml::table*>(p); }
const toml::node* as_node(const void* p) { return static_cast<const toml::node*>(p); }

int line_of_node(const toml::node& n, int fallback) {
  const auto line = static_cast<int>(n.source().begin.line);
  return line > 0 ? line : fallback;
}

std::string format_number(double v) {
  std::ostringstream s;
  s.precision(12);
  s << v;
  return s.str();
}

}  // namespace

// --- Bounds ----------------------------------------------------------------------------

bool Bounds::contains(double v) const {
  const bool lo_ok = min_open ? v > min : v >= min;
  const bool hi_ok = max_open ? v < max : v <= max;
  return lo_ok && hi_ok;
}

std::string Bounds::describe() const {
  const bool has_lo = min > -1e299, has_hi = max < 1e299;
  if (has_lo && has_hi)
    return std::string("in ") + (min_open ? "(" : "[") + format_number(min) + ", " +
           format_number(max) + (max_open ? ")" : "]");
  if (has_lo) return std::string(min_open ? "> " : ">= ") + format_number(min);
  if (has_hi) return std::string(max_open ? "< " : "<= ") + format_number(max);
  return "any number";
}

std::optional<double> length_unit_in_metres(std::string_view unit) {
  if (unit == "m") return 1.0;
  if (unit == "cm") return 1e-2;
  if (unit == "mm") return 1e-3;
  if (unit == "um") return 1e-6;
  return std::nullopt;
}

// --- parsing ---------------------------------------------------------------------------

TomlTable::TomlTable(std::shared_ptr<Document> doc, const void* table, std::string path, int line)
    : doc_(std::move(doc)), table_(table), path_(std::move(path)), line_(line > 0 ? line : 1) {}

TomlTable parse_toml_string(std::string_view text, const std::string& name) {
  refuse_toml_the_parser_cannot_read_safely(text, name);
  auto doc = std::make_shared<TomlTable::Document>();
  doc->file = name;
  try {
    doc->root = toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    const int line = static_cast<int>(e.source().begin.line);
    const SyntaxErrorContext where = syntax_error_context(text, line);
    throw InputError(name, line, where.key,
                     "TOML syntax error: " + std::string(e.description()) + (where.hint.empty() ? "" : "; " + where.hint));
  }
  const void* root = &doc->root;
  return TomlTable(std::move(doc), root, "", 1);
}

void TomlTable::apply_overrides(const std::vector<std::pair<std::string, std::string>>& overrides) {
  for (const auto& [dotted, value_text] : overrides) {
    const auto refuse = [this, &dotted = dotted](const std::string& why) {
      return OverrideInputError(file(), dotted, "override: " + why, dotted);
    };
    try {
      (void)parse_key_path(dotted);
    } catch (const KeyPathError& e) {
      throw refuse(e.what());
    }
    toml::table parsed;
    try {
      const std::string text = "v = " + value_text;
      refuse_toml_the_parser_cannot_read_safely(text, "override");
      parsed = toml::parse(std::string_view(text), std::string_view("override"));
    } catch (const InputError& e) {
      throw refuse("\"" + value_text + "\" is not a TOML value (" + e.message() + ")");
    } catch (const toml::parse_error& e) {
      throw refuse("\"" + value_text + "\" is not a TOML value (" + std::string(e.description()) +
                   "); quote strings: '\"cosine\"'");
    }
    // The tables on the way are created; an array element (KEY[i]) must exist and be a number.
    const toml::node& value = *parsed.get("v");
    try {
      const ValueSlot slot = find_value_slot(*const_cast<toml::table*>(as_tbl(table_)), dotted, true);
      if (slot.array && !value.is_number())
        throw KeyPathError("'" + dotted + "' is an element of an array of numbers: its value must be a number, not " +
                           toml_type_name(value));
      slot.set(value);
    } catch (const KeyPathError& e) {
      throw refuse(e.what());
    }
    doc_->overridden.push_back(key_path(dotted));
  }
}

void TomlTable::remove_key(std::string_view table, std::string_view key) {
  auto* root = const_cast<toml::table*>(as_tbl(table_));
  if (auto* sub = root->get_as<toml::table>(table)) sub->erase(key);
}

TomlTable parse_toml_file(const std::string& path) {
  // Bounded: a regular file of limited size. /dev/zero or a FIFO used to be read without end.
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!ec && std::filesystem::exists(status)) {
    if (!std::filesystem::is_regular_file(status))
      throw InputError(path, 0, "", "not a regular file (a device, FIFO or folder): give a TOML file");
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > kMaxTomlFileBytes)
      throw InputError(path, 0, "", "the file is larger than " + std::to_string(kMaxTomlFileBytes) +
                                        " bytes: not a wing, case or chain file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "", std::string("cannot open the file for reading: ") + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path, 0, "", "cannot read the file");
  try {
    return parse_toml_string(text.str(), path);
  } catch (const InputError& e) {
    // An outline or a drawing given where a wing file belongs (`flapsim mesh wing.svg`,
    // `run --wing outline.csv`): its first line is no TOML.
    const std::string ext = lower_case_extension(path);
    if (ext != ".svg" && ext != ".csv") throw;
    throw InputError(
        e.file(), e.line(), e.key(),
        e.message() + "; an " + (ext == ".svg" ? "SVG drawing" : "outline CSV") +
            " is not a wing file: a wing file (TOML, docs/wing_file.md) names it with [planform] "
            "outline_file and gives its membrane, veins and materials");
  }
}

// --- location and errors ------------------------------------------------------------------

const std::string& TomlTable::file() const { return doc_->file; }

std::string TomlTable::directory() const {
  return std::filesystem::path(doc_->file).parent_path().string();
}

std::string TomlTable::key_path(std::string_view key) const {
  if (path_.empty()) return std::string(key);
  return path_ + "." + std::string(key);
}

const void* TomlTable::node(std::string_view key) const { return as_tbl(table_)->get(key); }

int TomlTable::line_of(std::string_view key) const {
  const auto* n = as_node(node(key));
  return n ? line_of_node(*n, line_) : line_;
}

void TomlTable::raise(int line, const std::string& key_path, const std::string& message) const {
  // A value set by an override has no line in the file: say where it came from instead.
  // The problem concerns the override when it is about its key, a part of its value, or a
  // table on its path (a typo in a table's name: "kinematic.frequency_hz" is an unknown
  // table "kinematic", not a problem of the file's first line), or the array of an
  // overridden element ("sin_deg" when "sin_deg[0]" was set).
  for (const auto& k : doc_->overridden)
    if (key_path == k || key_path.rfind(k + ".", 0) == 0 || key_path.rfind(k + "[", 0) == 0 ||
        k.rfind(key_path + ".", 0) == 0 || k.rfind(key_path + "[", 0) == 0) {
      // A number given for an array ("sin_deg=-30" for sin_deg = [-45.0]): the way to set
      // one of its numbers is its index (docs/sweeps.md).
      if (key_path == k && message.rfind("expected an array", 0) == 0)
        throw OverrideInputError(
            file(), key_path, message + "; to set one element of the array give its index, as " + k + "[0]",
            k);
      throw OverrideInputError(file(), key_path, message, k);
    }
  throw InputError(file(), line > 0 ? line : line_, key_path, message);
}

void TomlTable::fail(std::string_view key, const std::string& message) const {
  raise(line_of(key), key_path(key), message);
}

void TomlTable::fail_at(int line, std::string_view key, const std::string& message) const {
  raise(line, key_path(key), message);
}

void TomlTable::fail_type(std::string_view key, const char* expected) const {
  const auto* n = as_node(node(key));
  fail(key, std::string("expected ") + expected + ", found " + (n ? toml_type_name(*n) : "nothing"));
}

bool TomlTable::has(std::string_view key) const { return node(key) != nullptr; }

std::vector<std::string> TomlTable::keys() const {
  std::vector<std::string> out;
  for (auto&& [k, v] : *as_tbl(table_)) out.emplace_back(k.str());
  return out;
}

bool TomlTable::is_table(std::string_view key) const {
  const auto* n = as_node(node(key));
  return n && n->is_table();
}
bool TomlTable::is_array(std::string_view key) const {
  const auto* n = as_node(node(key));
  return n && n->is_array();
}
bool TomlTable::is_string(std::string_view key) const {
  const auto* n = as_node(node(key));
  return n && n->is_string();
}
bool TomlTable::is_number(std::string_view key) const {
  const auto* n = as_node(node(key));
  return n && n->is_number();
}

void TomlTable::expect_only(const std::vector<std::string>& known) const {
  for (auto&& [k, v] : *as_tbl(table_)) {
    bool ok = false;
    for (const auto& kn : known) ok = ok || (k.str() == kn);
    if (ok) continue;
    std::string list;
    for (const auto& kn : known) list += (list.empty() ? "" : ", ") + kn;
    raise(line_of_node(v, line_), key_path(k.str()), "unknown key (a typo?); expected one of: " + list);
  }
}

void TomlTable::expect_only(std::initializer_list<std::string_view> known) const {
  std::vector<std::string> v;
  for (auto k : known) v.emplace_back(k);
  expect_only(v);
}

// --- scalars ------------------------------------------------------------------------------

namespace {
void check_finite_and_bounds(const TomlTable& t, std::string_view key, int line, double v,
                             const Bounds& b) {
  if (!std::isfinite(v)) t.fail_at(line, key, "must be a finite number");
  if (std::fpclassify(v) == FP_SUBNORMAL)
    t.fail_at(line, key,
              "value " + format_number(v) + " is a denormal number (magnitude below " +
                  format_number(kSmallestNormal) + "): too small to compute with");
  if (!b.contains(v)) {
    // A bound the key does not state is the cap of every number key, +-1e300 (Bounds):
    // a value beyond it (1e308 for a key that must be >= 0) is told the cap, not only ">= 0".
    const bool beyond_cap = (v > b.max && b.max >= 1e300) || (v < b.min && b.min <= -1e300);
    std::string rule = b.describe();
    if (beyond_cap)
      rule = (rule == "any number" ? std::string("a number") : rule + ", a number") +
             " of magnitude at most 1e300 (the largest a number key accepts)";
    t.fail_at(line, key, "value " + format_number(v) + " out of range: must be " + rule);
  }
}

/// The value of a number node as a double. An integer is accepted only if the double
/// holds it exactly (|n| <= 2^53): -9223372036854775808 is not silently read as -9.2e18.
double exact_number(const TomlTable& t, std::string_view key, int line, const toml::node& n) {
  if (n.is_integer()) {
    const int64_t i = *n.value<int64_t>();
    if (i > kMaxExactInteger || i < -kMaxExactInteger)
      t.fail_at(line, key,
                "integer " + std::to_string(i) + " cannot be represented exactly as a number (|value| <= 2^53 = " +
                    std::to_string(kMaxExactInteger) + "); write it as a floating-point number if meant");
    return static_cast<double>(i);
  }
  return *n.value<double>();
}
}  // namespace

std::optional<double> TomlTable::find_double(std::string_view key, const Bounds& bounds) const {
  const auto* n = as_node(node(key));
  if (!n) return std::nullopt;
  if (!n->is_number()) fail_type(key, "a number");
  const double v = exact_number(*this, key, line_of(key), *n);
  check_finite_and_bounds(*this, key, line_of(key), v, bounds);
  return v;
}

double TomlTable::get_double(std::string_view key, const Bounds& bounds) const {
  auto v = find_double(key, bounds);
  if (!v) fail(key, "missing required key (a number)");
  return *v;
}

double TomlTable::get_double(std::string_view key, double fallback, const Bounds& bounds) const {
  return find_double(key, bounds).value_or(fallback);
}

int TomlTable::get_int(std::string_view key, const Bounds& bounds) const {
  const auto* n = as_node(node(key));
  if (!n) fail(key, "missing required key (an integer)");
  if (!n->is_integer()) fail_type(key, "an integer");
  const auto v = *n->value<int64_t>();
  if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
    fail(key, "integer " + std::to_string(v) + " out of range: must be " + bounds.describe());
  if (!bounds.contains(static_cast<double>(v)))
    fail(key, "value " + std::to_string(v) + " out of range: must be " + bounds.describe());
  return static_cast<int>(v);
}

int64_t TomlTable::get_int64(std::string_view key, int64_t min, int64_t max) const {
  const auto* n = as_node(node(key));
  if (!n) fail(key, "missing required key (an integer)");
  if (!n->is_integer()) fail_type(key, "an integer");
  const int64_t v = *n->value<int64_t>();
  if (v < min || v > max)
    fail(key, "value " + std::to_string(v) + " out of range: must be in [" + std::to_string(min) + ", " +
                  std::to_string(max) + "]");
  return v;
}

int TomlTable::get_int(std::string_view key, int fallback, const Bounds& bounds) const {
  return has(key) ? get_int(key, bounds) : fallback;
}

std::string TomlTable::get_string(std::string_view key) const {
  const auto* n = as_node(node(key));
  if (!n) fail(key, "missing required key (a string)");
  if (!n->is_string()) fail_type(key, "a string");
  return *n->value<std::string>();
}

std::string TomlTable::get_string(std::string_view key, std::string_view fallback) const {
  return has(key) ? get_string(key) : std::string(fallback);
}

std::string TomlTable::get_choice(std::string_view key, std::span<const std::string_view> choices,
                                  std::string_view fallback) const {
  std::string list;
  for (auto c : choices) list += (list.empty() ? "\"" : ", \"") + std::string(c) + "\"";
  if (!has(key)) {
    if (!fallback.empty()) return std::string(fallback);
    fail(key, "missing required key (one of " + list + ")");
  }
  const std::string v = get_string(key);
  for (auto c : choices)
    if (v == c) return v;
  fail(key, "unknown value \"" + v + "\"; expected one of " + list);
}

bool TomlTable::get_bool(std::string_view key) const {
  const auto* n = as_node(node(key));
  if (!n) fail(key, "missing required key (true or false)");
  if (!n->is_boolean()) fail_type(key, "a boolean (true or false)");
  return *n->value<bool>();
}

bool TomlTable::get_bool(std::string_view key, bool fallback) const {
  return has(key) ? get_bool(key) : fallback;
}

std::string TomlTable::get_path(std::string_view key) const {
  const std::string p = get_string(key);
  if (p.empty()) fail(key, "empty path");
  std::filesystem::path fp(p);
  if (fp.is_absolute()) return fp.lexically_normal().string();
  return (std::filesystem::path(directory()) / fp).lexically_normal().string();
}

// --- arrays ------------------------------------------------------------------------------

int TomlTable::line_of_element(std::string_view key, std::size_t i) const {
  const auto* n = as_node(node(key));
  if (!n || !n->is_array() || i >= n->as_array()->size()) return line_of(key);
  return line_of_node(*n->as_array()->get(i), line_of(key));
}

std::vector<double> TomlTable::find_doubles(std::string_view key, const Bounds& bounds) const {
  std::vector<double> out;
  const auto* n = as_node(node(key));
  if (!n) return out;
  if (!n->is_array()) fail_type(key, "an array of numbers");
  const auto& arr = *n->as_array();
  out.reserve(arr.size());
  for (std::size_t i = 0; i < arr.size(); ++i) {
    const auto& e = *arr.get(i);
    const int line = line_of_node(e, line_of(key));
    const std::string ek = std::string(key) + "[" + std::to_string(i) + "]";
    if (!e.is_number())
      fail_at(line, ek, std::string("expected a number, found ") + toml_type_name(e));
    const double v = exact_number(*this, ek, line, e);
    check_finite_and_bounds(*this, ek, line, v, bounds);
    out.push_back(v);
  }
  return out;
}

std::vector<double> TomlTable::get_doubles(std::string_view key, const Bounds& bounds,
                                           std::size_t min_size) const {
  if (!has(key)) fail(key, "missing required key (an array of numbers)");
  auto out = find_doubles(key, bounds);
  if (out.size() < min_size)
    fail(key, "needs at least " + std::to_string(min_size) + " numbers, found " +
                  std::to_string(out.size()));
  return out;
}

std::vector<std::vector<double>> TomlTable::get_number_rows(std::string_view key,
                                                            std::size_t columns,
                                                            std::size_t min_rows) const {
  const auto* n = as_node(node(key));
  const std::string what = "an array of [" + std::to_string(columns) + " numbers] arrays";
  if (!n) fail(key, "missing required key (" + what + ")");
  if (!n->is_array()) fail_type(key, what.c_str());
  const auto& arr = *n->as_array();
  std::vector<std::vector<double>> rows;
  rows.reserve(arr.size());
  for (std::size_t i = 0; i < arr.size(); ++i) {
    const auto& e = *arr.get(i);
    const int line = line_of_node(e, line_of(key));
    const std::string ek = std::string(key) + "[" + std::to_string(i) + "]";
    if (!e.is_array() || e.as_array()->size() != columns)
      fail_at(line, ek, "expected an array of " + std::to_string(columns) + " numbers");
    std::vector<double> row;
    for (const auto& x : *e.as_array()) {
      if (!x.is_number())
        fail_at(line_of_node(x, line), ek, std::string("expected a number, found ") + toml_type_name(x));
      const double v = exact_number(*this, ek, line, x);
      check_finite_and_bounds(*this, ek, line, v, Bounds::any());
      row.push_back(v);
    }
    rows.push_back(std::move(row));
  }
  if (rows.size() < min_rows)
    fail(key, "needs at least " + std::to_string(min_rows) + " entries, found " +
                  std::to_string(rows.size()));
  return rows;
}

// --- lengths -------------------------------------------------------------------------------

void TomlTable::read_length_unit(std::string_view key, std::string_view fallback) const {
  const std::string unit = get_string(key, fallback);
  const auto scale = length_unit_in_metres(unit);
  if (!scale) fail(key, "unknown length unit \"" + unit + "\"; expected one of \"m\", \"cm\", \"mm\", \"um\"");
  doc_->length_scale = *scale;
  doc_->length_unit = unit;
}

double TomlTable::length_scale() const { return doc_->length_scale; }
const std::string& TomlTable::length_unit() const { return doc_->length_unit; }

std::optional<double> TomlTable::find_length(std::string_view key, const Bounds& bounds) const {
  auto v = find_double(key, bounds);
  if (!v) return std::nullopt;
  const double metres = *v * doc_->length_scale;
  if (*v != 0.0 && std::fpclassify(metres) != FP_NORMAL)
    fail(key, "value " + format_number(*v) + " " + doc_->length_unit + " is too small to compute with in metres");
  return metres;
}

double TomlTable::get_length(std::string_view key, const Bounds& bounds) const {
  if (!has(key)) fail(key, "missing required key (a length in " + doc_->length_unit + ")");
  return *find_length(key, bounds);
}

double TomlTable::get_length(std::string_view key, double fallback_m, const Bounds& bounds) const {
  return find_length(key, bounds).value_or(fallback_m);
}

std::vector<double> TomlTable::get_lengths(std::string_view key, const Bounds& bounds,
                                           std::size_t min_size) const {
  auto v = get_doubles(key, bounds, min_size);
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double metres = v[i] * doc_->length_scale;
    if (v[i] != 0.0 && std::fpclassify(metres) != FP_NORMAL)
      fail_at(line_of_element(key, i), std::string(key) + "[" + std::to_string(i) + "]",
              "value " + format_number(v[i]) + " " + doc_->length_unit + " is too small to compute with in metres");
    v[i] = metres;
  }
  return v;
}

Eigen::Vector3d TomlTable::get_length_vector3(std::string_view key) const {
  const auto v = get_lengths(key);
  if (v.size() != 3) fail(key, "expected 3 numbers [x, y, z], found " + std::to_string(v.size()));
  return {v[0], v[1], v[2]};
}

Eigen::Vector3d TomlTable::get_length_vector3(std::string_view key,
                                              const Eigen::Vector3d& fallback_m) const {
  return has(key) ? get_length_vector3(key) : fallback_m;
}

// --- tables --------------------------------------------------------------------------------

std::optional<TomlTable> TomlTable::find_table(std::string_view key) const {
  const auto* n = as_node(node(key));
  if (!n) return std::nullopt;
  if (!n->is_table()) fail_type(key, "a table");
  return TomlTable(doc_, n->as_table(), key_path(key), line_of_node(*n, line_));
}

TomlTable TomlTable::get_table(std::string_view key) const {
  auto t = find_table(key);
  if (!t) fail(key, "missing required table");
  return *t;
}

std::vector<TomlTable> TomlTable::get_tables(std::string_view key, std::size_t min_size) const {
  std::vector<TomlTable> out;
  const auto* n = as_node(node(key));
  if (n) {
    if (!n->is_array()) fail_type(key, "an array of tables");
    const auto& arr = *n->as_array();
    for (std::size_t i = 0; i < arr.size(); ++i) {
      const auto& e = *arr.get(i);
      const std::string ek = std::string(key) + "[" + std::to_string(i) + "]";
      const int line = line_of_node(e, line_of(key));
      if (!e.is_table()) fail_at(line, ek, std::string("expected a table, found ") + toml_type_name(e));
      out.push_back(TomlTable(doc_, e.as_table(), key_path(ek), line));
    }
  }
  if (out.size() < min_size)
    fail(key, "needs at least " + std::to_string(min_size) + " entries, found " +
                  std::to_string(out.size()));
  return out;
}

}  // namespace flapsim::wings
