#pragma once
/// \file sweep_values.hpp
/// \brief The `--vary KEY=VALUES` arguments of `flapsim sweep` and their Cartesian grid.
/// VALUES is `start:step:stop` (inclusive, step may be negative) or a comma list
/// `v1,v2,...` of numbers or words (`none,separated,shed`: a text key's values, written
/// into the file as TOML strings; `true,false` as booleans). KEY is one of (docs/sweeps.md,
/// "What can be varied"):
///  - a dotted case-file key whose value is a number (`kinematics.rotation_phase`,
///    `kinematics.frequency_hz`, `air.density`, `numerics.steps_per_cycle`, ...);
///  - `wing.` and a dotted key of the case's wing file (`wing.membrane.thickness`, in the
///    wing file's length unit; `wing.materials.vein.youngs_modulus`, ...);
///  - `spring_scale`, the factor on every joint spring (flapsim run --spring-scale);
///  - `wing`, the wing file each case flies: a comma list of paths from the current folder
///    (as flapsim run --wing), `wing=wings/a.toml,wings/b.toml`.
/// Each value is written into the parsed file (case or wing) and the file is read and
/// checked again, so every case of a sweep is checked as strictly as a file.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "pipeline/io/case_model.hpp"

namespace flapsim::sweep {

/// One varied key's value in one case of a sweep: a number, or a word (a text or boolean
/// key's value, e.g. numerics.leading_edge = shed).
struct Assignment {
  std::string key;
  double value = 0.0;  ///< the number (0 for a word)
  std::string word;    ///< the word ("shed", "true"); "" for a number

  Assignment() = default;
  /// A key and its number, or its word (then `number` is 0).
  Assignment(std::string k, double number, std::string w = "")
      : key(std::move(k)), value(number), word(std::move(w)) {}
};

struct Variation {
  std::string key;                 ///< dotted key, e.g. "kinematics.rotation_phase"
  std::vector<Assignment> values;  ///< in the order given, each with `key`

  Variation() = default;
  /// A key and its numbers.
  Variation(std::string k, const std::vector<double>& numbers) : key(std::move(k)) {
    for (double x : numbers) values.push_back({key, x});
  }
};

/// \brief Whether \p s is a word value of --vary or a case table: a letter, then letters,
/// digits, '_' or '-' (`shed`, `iqn_ils`, `true`); not inf or nan, which are refused as numbers.
bool is_word_value(const std::string& s);

/// \brief A case-table cell or --vary item that is a word (is_word_value) as an Assignment.
Assignment word_assignment(const std::string& key, const std::string& word);

/// \brief Whether \p key takes paths (the `wing` of each case) instead of numbers or words: its
/// values are kept as written (Assignment::word), a path from the current folder.
bool takes_paths(const std::string& key);

/// The values of the varied keys that make one case (in the order of the keys).
using CasePoint = std::vector<Assignment>;

/// The most values one --vary may give (a range's or a list's).
inline constexpr std::size_t kMaxVaryValues = 10000;

/// \brief Parses `KEY=start:step:stop` (stop included) or `KEY=v1,v2,...`.
/// \throws flapsim::InputError (key "--vary") on bad syntax, a zero step, a step of the
///         wrong sign, more than 10000 values or an empty list
Variation parse_variation(const std::string& text);

/// \brief The Cartesian product of the variations: every combination of their values,
/// the first key varying slowest (row-major), e.g. 2 × 3 values give 6 points.
/// \throws flapsim::InputError (key "--vary") when a key is varied twice or the grid has
///         more than 1000000 points
std::vector<CasePoint> cartesian_grid(const std::vector<Variation>& variations);

/// \brief Reads the case file with `key` (a case-file key) set to `value`.
/// Integer keys (read as integers) take integral values only.
/// \throws flapsim::InputError when the key names a table or text, or the resulting
///         case is invalid
io::Case load_case_with(const std::string& case_file, const std::string& key, double value);

/// \brief The same with the assignment's value (a number or a word, value_text).
io::Case load_case_with(const std::string& case_file, const Assignment& a);

/// \brief A short, file-system-safe label of a value, e.g. "-0.1", "0.05", "26.1".
std::string value_label(double value);

/// \brief The value as TOML text that reads back as the same double ("0.05", "7", "1e+20").
std::string value_text(double value);

/// \brief The label of an assignment: its word (of a path, the file's name without its
/// extension: wings/a.toml is "a"), else value_label of its number.
std::string value_label(const Assignment& a);

/// \brief The assignment as TOML text: a word as a string ("\"shed\""), `true` and `false` as
/// booleans, a number as value_text.
std::string value_text(const Assignment& a);

/// \brief The assignment's value for ordering and comparing (the number, then the word).
std::pair<double, std::string> value_key(const Assignment& a);

}  // namespace flapsim::sweep
