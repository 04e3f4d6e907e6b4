#pragma once
/// \file sweep_values.hpp
/// \brief The `--vary KEY=VALUES` argument of `flapsim sweep` and the case it makes for
/// each value: VALUES is `start:step:stop` (inclusive, step may be negative) or a comma
/// list `v1,v2,...`; KEY is a dotted case-file key whose value is a number
/// (`kinematics.rotation_phase`, `kinematics.frequency_hz`, `air.density`,
/// `numerics.steps_per_cycle`, ...). Each value is written into the parsed case file
/// and the case is read and checked again, so every case of a sweep is checked as
/// strictly as a case file.

#include <string>
#include <vector>

#include "pipeline/io/case_model.hpp"

namespace flapsim::sweep {

struct Variation {
  std::string key;              ///< dotted key, e.g. "kinematics.rotation_phase"
  std::vector<double> values;   ///< in the order given
};

/// \brief Parses `KEY=start:step:stop` or `KEY=v1,v2,...`.
/// \throws flapsim::InputError (key "--vary") on bad syntax, a zero step, a step of the
///         wrong sign, more than 10000 values or an empty list
Variation parse_variation(const std::string& text);

/// \brief Reads the case file with `key` set to `value`.
/// Integer keys (the original value is an integer) take the value rounded; a value that
/// is not an integer there is an error.
/// \throws flapsim::InputError when the key's table does not exist in the file, the key
///         names a table or text, or the resulting case is invalid
io::Case load_case_with(const std::string& case_file, const std::string& key, double value);

/// \brief A short, file-system-safe label of a value, e.g. "-0.1", "0.05", "26.1".
std::string value_label(double value);

}  // namespace flapsim::sweep
