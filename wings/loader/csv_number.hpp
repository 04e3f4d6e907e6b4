#pragma once
// A number in a cell of a CSV file the loaders read (outline files, kinematics tables): the
// whole cell, finite and not denormal, as every number of an input file (toml_reader.hpp).

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

#include "wings/loader/text_trim.hpp"

namespace flapsim::wings {

/// \brief Whether \p cell (spaces around it ignored) is one number, stored in \p out:
/// "1.5e-3" is, "1.5mm" and "" are not.
inline bool parse_csv_number(const std::string& cell, double& out) {
  const std::string f = trim(cell);
  if (f.empty()) return false;
  char* end = nullptr;
  errno = 0;
  out = std::strtod(f.c_str(), &end);
  return errno == 0 && end == f.c_str() + f.size() && std::isfinite(out) &&
         (out == 0.0 || std::fpclassify(out) == FP_NORMAL);
}

}  // namespace flapsim::wings
