#pragma once
/// \file recorded_frequency_warning.hpp
/// \brief The warning for a CSV wingbeat of times recorded at another frequency than the
/// case's: its last row repeats the first row's value, as the closing row of a recorded
/// wingbeat does, but lies short of one period of the case's frequency. The row is then an
/// ordinary point, and the wing holds the first row's value from it to the cycle's end
/// (docs/case_file.md, "Measured kinematics"). A wingbeat recorded at 28 Hz and flown at
/// 26.1 Hz put its closing row at phase 0.932: the wing dwelt at the stroke's end for 7 % of
/// the cycle and lifted 6.7 % more than the same wingbeat written as harmonics.

#include <optional>
#include <string>
#include <vector>

#include "wings/loader/input_warning.hpp"

namespace flapsim::io {

/// \brief The warning for a table of times (phase = (t − t0) f, rows kept, at least 4) whose
/// last row lies between phase ½ and 1 and repeats the first row's value to 1e-9 of it,
/// naming the frequency the rows imply (f / phase of the last row); nullopt otherwise.
/// \param frequency_hz  the case's f [Hz]; `column` the column's name; `file`, `line`, `key` locate it
std::optional<InputWarning> recorded_frequency_warning(const std::vector<double>& phase,
                                                       const std::vector<double>& values, double frequency_hz,
                                                       const std::string& column, const std::string& file,
                                                       int line, const std::string& key);

}  // namespace flapsim::io
