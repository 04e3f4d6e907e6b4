#pragma once
/// \file kinematics_csv.hpp
/// \brief A measured wingbeat from a CSV file: `sweep = { file = "wingbeat.csv", column = "phi" }`
/// (docs/case_file.md, "Measured kinematics"). Comment lines start with '#'; the first other
/// line is the header; the first column is the phase (`phase`, fractions of the wingbeat) or
/// the time (`t_s`, `time [s]`, `t_ms`, `time (ms)`, …: the phase is (t − t₀) f); values are
/// separated by commas, or by tabs on lines without a comma, or by spaces on lines without either. One
/// wingbeat: a last row at phase 1 (or one period after the first time) must repeat the first row's value and
/// is dropped, as an inline table's. A fitted table of times may hold several wingbeats; a last row a
/// whole number of periods after the first is the next wingbeat's start and is dropped too.

#include <cstddef>
#include <string>
#include <vector>

namespace flapsim::io {

inline constexpr std::size_t kMaxKinematicsCsvBytes = 16u << 20;  ///< 16 MiB (about 10⁵ rows of 8 columns)

/// One column of the table: phases in [0, 1), strictly increasing, values as written; for a
/// fitted table of times, the rows of every wingbeat folded onto one (phases in any order).
struct KinematicsCsvColumn {
  std::vector<double> phase;   ///< [cycles]
  std::vector<double> values;  ///< as written (degrees, metres)
  std::vector<int> lines;      ///< each kept row's line in the file (messages)
  bool from_times = false;     ///< the first column was a time
};

/// \param path          the CSV file (resolved, existing)
/// \param column        the header name of the values' column (spaces around it ignored)
/// \param frequency_hz  the wingbeat's frequency f, for a time column
/// \param key           the case's key naming the file (messages)
/// \param fitted        the table is fitted (harmonics = N): a closing row need not repeat the
///                      first's value (a measurement of the next wingbeat's start), it is dropped;
///                      times may span several wingbeats, folded onto one (their mean wingbeat's fit)
/// \throws flapsim::InputError naming the CSV file and line (0: the file as a whole)
KinematicsCsvColumn read_kinematics_csv(const std::string& path, const std::string& column,
                                        double frequency_hz, const std::string& key, bool fitted);

}  // namespace flapsim::io
