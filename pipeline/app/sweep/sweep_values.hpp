#pragma once
/// \file sweep_values.hpp
/// \brief The `--vary KEY=VALUES` arguments of `flapsim sweep` and their Cartesian grid.
/// VALUES is `start:step:stop` (inclusive, step may be negative) or a comma list
/// `v1,v2,...`. KEY is one of (docs/sweeps.md, "What can be varied"):
///  - a dotted case-file key whose value is a number (`kinematics.rotation_phase`,
///    `kinematics.frequency_hz`, `air.density`, `numerics.steps_per_cycle`, ...);
///  - `wing.` and a dotted key of the case's wing file (`wing.membrane.thickness`, in the
///    wing file's length unit; `wing.materials.vein.youngs_modulus`, ...);
///  - `spring_scale`, the factor on every joint spring (flapsim run --spring-scale).
/// Each value is written into the parsed file (case or wing) and the file is read and
/// checked again, so every case of a sweep is checked as strictly as a file.

#include <string>
#include <vector>

#include "pipeline/io/case_model.hpp"

namespace flapsim::sweep {

struct Variation {
  std::string key;              ///< dotted key, e.g. "kinematics.rotation_phase"
  std::vector<double> values;   ///< in the order given
};

/// One varied key's value in one case of a sweep.
struct Assignment {
  std::string key;
  double value = 0.0;
};

/// The values of the varied keys that make one case (in the order of the keys).
using CasePoint = std::vector<Assignment>;

/// \brief Parses `KEY=start:step:stop` or `KEY=v1,v2,...`.
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

/// \brief A short, file-system-safe label of a value, e.g. "-0.1", "0.05", "26.1".
std::string value_label(double value);

/// \brief The value as TOML text that reads back as the same double ("0.05", "7", "1e+20").
std::string value_text(double value);

}  // namespace flapsim::sweep
