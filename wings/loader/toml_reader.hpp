#pragma once
/// \file toml_reader.hpp
/// \brief Checked, typed access to TOML input files (wing, case and chain files).
///
/// Every accessor knows the file, the dotted key path ("veins[2].points") and the
/// source line of what it reads, so each problem becomes one flapsim::InputError
/// "FILE:LINE: key 'KEY': MESSAGE": missing keys, wrong types, values out of range,
/// unknown choices, unknown units and unexpected keys (typos).
///
/// Lengths: a file declares its length unit once, at the top level, with
/// `length_unit = "mm"` (one of "m", "cm", "mm", "um"; default "m"). Every key that
/// is a length is then read in that unit and returned in metres. Quantities other
/// than lengths are SI unless the key name says otherwise (`*_deg` in degrees).
///
/// Typical use:
/// \code
///   TomlTable root = parse_toml_file(path);
///   root.expect_only({"length_unit", "name", "span", "membrane"});
///   root.read_length_unit();
///   double span = root.get_length("span", Bounds::positive());         // [m]
///   TomlTable membrane = root.get_table("membrane");
///   double h = membrane.get_length("thickness", Bounds::positive());  // [m]
/// \endcode
/// toml++ stays inside toml_reader.cpp; this header is cheap to include.

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace flapsim::wings {

/// The name of `value` in a table of (name, value) choices ("?" if it has none): the
/// inverse of TomlTable::get_choice with such a table.
template <typename E, std::size_t N>
std::string_view choice_name(const std::array<std::pair<std::string_view, E>, N>& names, E value) {
  for (const auto& [name, v] : names)
    if (v == value) return name;
  return "?";
}

/// The largest integer every number key accepts: a double holds every integer up to
/// 2^53 exactly; larger integers in a number key are rejected, not rounded.
inline constexpr std::int64_t kMaxExactInteger = std::int64_t{1} << 53;
/// The smallest positive normal double (about 2.2e-308); non-zero values of smaller
/// magnitude (denormals) are rejected by every number key.
inline constexpr double kSmallestNormal = 2.2250738585072014e-308;

/// Allowed interval of a number; open or closed at each end.
struct Bounds {
  double min = -1e300;
  double max = 1e300;
  bool min_open = false;  ///< true: value must be > min (else >= min)
  bool max_open = false;  ///< true: value must be < max (else <= max)

  static Bounds any() { return {}; }
  static Bounds positive() { return {0.0, 1e300, true, false}; }      ///< > 0
  static Bounds non_negative() { return {0.0, 1e300, false, false}; } ///< >= 0
  static Bounds closed(double lo, double hi) { return {lo, hi, false, false}; }  ///< [lo, hi]
  static Bounds open(double lo, double hi) { return {lo, hi, true, true}; }      ///< (lo, hi)
  static Bounds at_least(double lo) { return {lo, 1e300, false, false}; }        ///< >= lo

  bool contains(double v) const;
  /// Human-readable statement of the bounds, e.g. "> 0" or "in [0, 1]".
  std::string describe() const;
};

/// Metres per unit for a length-unit name ("m", "cm", "mm", "um"); nullopt if unknown.
std::optional<double> length_unit_in_metres(std::string_view unit);

/// A read-only view of one TOML table of a parsed file. Cheap to copy; keeps the
/// parsed document alive. All getters throw flapsim::InputError.
class TomlTable {
 public:
  // --- where we are -------------------------------------------------------------
  const std::string& file() const;  ///< the file name given to the parser
  /// Folder of the file ("" if none); relative paths in the file are resolved against it.
  std::string directory() const;
  const std::string& path() const { return path_; }  ///< dotted path ("" = top level)
  int line() const { return line_; }                 ///< line where the table starts (>= 1)

  /// Dotted path of a key of this table, e.g. "membrane.thickness".
  std::string key_path(std::string_view key) const;
  /// Line of the key's value, or the table's own line if the key is absent.
  int line_of(std::string_view key) const;
  /// Throws InputError at the key's line with its dotted path.
  [[noreturn]] void fail(std::string_view key, const std::string& message) const;
  /// Throws InputError at a given line (e.g. of an array element).
  [[noreturn]] void fail_at(int line, std::string_view key, const std::string& message) const;

  bool has(std::string_view key) const;
  std::vector<std::string> keys() const;  ///< in file order where toml++ keeps it
  bool is_table(std::string_view key) const;
  bool is_array(std::string_view key) const;
  bool is_string(std::string_view key) const;
  bool is_number(std::string_view key) const;  ///< integer or floating point

  /// Rejects keys not in `known` ("unknown key 'spam'; expected one of: ...").
  void expect_only(std::initializer_list<std::string_view> known) const;
  void expect_only(const std::vector<std::string>& known) const;

  // --- scalars ----------------------------------------------------------------------
  /// Number (integers are accepted as numbers if |n| <= 2^53, exactly representable).
  /// Missing, infinite, NaN, denormal or out of bounds: error.
  double get_double(std::string_view key, const Bounds& bounds = {}) const;
  double get_double(std::string_view key, double fallback, const Bounds& bounds) const;
  std::optional<double> find_double(std::string_view key, const Bounds& bounds = {}) const;

  /// Integer (a float such as 3.0 is rejected, as TOML keeps the two apart).
  int get_int(std::string_view key, const Bounds& bounds = {}) const;
  int get_int(std::string_view key, int fallback, const Bounds& bounds) const;
  /// A 64-bit integer in [min, max] (counts that may exceed an int).
  std::int64_t get_int64(std::string_view key, std::int64_t min, std::int64_t max) const;

  std::string get_string(std::string_view key) const;
  std::string get_string(std::string_view key, std::string_view fallback) const;
  /// String that must be one of `choices`; missing: `fallback` (if non-empty) else error.
  std::string get_choice(std::string_view key, std::span<const std::string_view> choices,
                         std::string_view fallback = {}) const;
  std::string get_choice(std::string_view key, std::initializer_list<std::string_view> choices,
                         std::string_view fallback = {}) const {
    return get_choice(key, std::span<const std::string_view>(choices.begin(), choices.size()), fallback);
  }
  /// A choice as an enum value: `names` pairs each accepted string with its value;
  /// missing: `fallback` if given, else an error.
  template <typename E, std::size_t N>
  E get_choice(std::string_view key, const std::array<std::pair<std::string_view, E>, N>& names,
               std::optional<E> fallback = std::nullopt) const {
    std::array<std::string_view, N> choices;
    std::string_view fallback_name;
    for (std::size_t i = 0; i < N; ++i) {
      choices[i] = names[i].first;
      if (fallback && names[i].second == *fallback) fallback_name = names[i].first;
    }
    const std::string v = get_choice(key, std::span<const std::string_view>(choices), fallback_name);
    for (const auto& [name, value] : names)
      if (name == v) return value;
    return names[0].second;  // not reached: get_choice accepts only the names
  }

  bool get_bool(std::string_view key) const;
  bool get_bool(std::string_view key, bool fallback) const;

  /// A file path, resolved against the folder of this file (absolute paths kept).
  std::string get_path(std::string_view key) const;

  // --- arrays of numbers -----------------------------------------------------------
  /// Array of numbers, each within bounds; at least `min_size` entries.
  std::vector<double> get_doubles(std::string_view key, const Bounds& bounds = {},
                                  std::size_t min_size = 0) const;
  /// Missing key: empty vector.
  std::vector<double> find_doubles(std::string_view key, const Bounds& bounds = {}) const;
  /// Array of arrays of exactly `columns` numbers, e.g. points = [[0, 1], [2, 3]].
  std::vector<std::vector<double>> get_number_rows(std::string_view key, std::size_t columns,
                                                   std::size_t min_rows = 0) const;
  /// Line of element i of an array (the array's line if unknown).
  int line_of_element(std::string_view key, std::size_t i) const;

  // --- lengths (file unit in, metres out) --------------------------------------------
  /// Reads the top-level `length_unit` key ("m" if absent) and applies it to every
  /// table of this file. Unknown unit: error at that key.
  /// (const: the unit is state of the whole parsed file, shared by all its tables.)
  void read_length_unit(std::string_view key = "length_unit",
                        std::string_view fallback = "m") const;
  double length_scale() const;        ///< metres per file length unit
  const std::string& length_unit() const;
  /// A length [m]; bounds apply to the value as written in the file's unit.
  double get_length(std::string_view key, const Bounds& bounds = {}) const;
  /// Missing key: `fallback_m` (already in metres).
  double get_length(std::string_view key, double fallback_m, const Bounds& bounds) const;
  std::optional<double> find_length(std::string_view key, const Bounds& bounds = {}) const;
  std::vector<double> get_lengths(std::string_view key, const Bounds& bounds = {},
                                  std::size_t min_size = 0) const;
  /// Three lengths [x, y, z] as a vector [m]; missing: `fallback_m`.
  Eigen::Vector3d get_length_vector3(std::string_view key,
                                     const Eigen::Vector3d& fallback_m) const;
  Eigen::Vector3d get_length_vector3(std::string_view key) const;

  // --- overrides (parameter sweeps) -------------------------------------------------------
  /// Sets values before reading, e.g. {"kinematics.rotation_phase", "-0.1"},
  /// {"numerics.spacing", "\"cosine\""} or {"kinematics.rotation.sin_deg[0]", "-50"}: each
  /// value is TOML text; missing tables on the way are created; KEY[i] (0-based) replaces
  /// an existing number of an array with a number (wings/loader/toml_key_path.hpp). Errors about
  /// an overridden key name the key and say it came from an override (there is no file
  /// line). Call on the top-level table of a freshly parsed file, before any reading.
  /// \throws flapsim::InputError for a value that is not TOML, a path through a non-table,
  ///         an index out of range, of a non-array or of an element that is not a number
  void apply_overrides(const std::vector<std::pair<std::string, std::string>>& overrides);

  /// Removes the key `table.key` (one level of table, then the key) if the file has it, as if
  /// it had not been written (a sweep that changes what a key means: io::load_case_file).
  /// Call before any reading.
  void remove_key(std::string_view table, std::string_view key);

  // --- sub-tables -------------------------------------------------------------------
  /// Sub-table (a [section] or an inline { ... } table).
  TomlTable get_table(std::string_view key) const;
  std::optional<TomlTable> find_table(std::string_view key) const;
  /// Array of tables ([[key]] sections or [{...}, {...}]); missing: empty.
  std::vector<TomlTable> get_tables(std::string_view key, std::size_t min_size = 0) const;

  /// Opaque shared state of one parsed file (defined in toml_reader.cpp).
  struct Document;

 private:
  friend TomlTable parse_toml_file(const std::string& path);
  friend TomlTable parse_toml_string(std::string_view text, const std::string& name);
  TomlTable(std::shared_ptr<Document> doc, const void* table, std::string path, int line);
  const void* node(std::string_view key) const;  // const toml::node*, nullptr if absent
  [[noreturn]] void fail_type(std::string_view key, const char* expected) const;
  [[noreturn]] void raise(int line, const std::string& key_path, const std::string& message) const;

  std::shared_ptr<Document> doc_;
  const void* table_ = nullptr;  // const toml::table*, owned by doc_
  std::string path_;
  int line_ = 1;
};

/// The largest TOML input file read (wing, case, chain): 16 MiB (a wing with a 100,000-point
/// inline outline is about 3 MiB).
inline constexpr std::uintmax_t kMaxTomlFileBytes = 16u << 20;

/// Parses a TOML file. Unreadable file or syntax error: InputError with the line
/// toml++ reports. The file must be a regular file (not a device, FIFO or folder, which
/// would be read without end or make no sense) of at most kMaxTomlFileBytes.
/// \param path file to read; kept verbatim in error messages
TomlTable parse_toml_file(const std::string& path);

/// Parses TOML text (tests, generated input).
/// \param name used as the file name in error messages; relative paths resolve
///             against its folder
TomlTable parse_toml_string(std::string_view text, const std::string& name);

}  // namespace flapsim::wings
