#pragma once
/// \file sweep_case.hpp
/// \brief One case of a sweep, resolved from the base case file and the values of its
/// varied keys: the checked case, the wing-file values to set, the spring factor, the
/// fingerprint of its inputs (io::input_hash) and its sub-folder name.

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/app/sweep/sweep_values.hpp"
#include "pipeline/io/case_model.hpp"

namespace flapsim::sweep {

/// Where a varied key goes.
enum class KeyTarget {
  case_file,     ///< a dotted key of the case file
  wing_file,     ///< "wing.<key>": a dotted key of the case's wing file
  spring_scale,  ///< "spring_scale": the factor on every joint spring
};

/// \brief The target of a varied key (by its name only; the value is checked when the
/// case is resolved).
KeyTarget key_target(const std::string& key);

/// What every case of a sweep shares (the command line's options).
struct SweepInputs {
  std::string case_file;
  std::string chain_file;     ///< flapsim sweep --chain ("" = the case's)
  double spring_scale = 1.0;  ///< flapsim sweep --spring-scale (a varied spring_scale replaces it)
  std::string wing_file;      ///< flapsim sweep --wing ("" = the case's 'wing')
};

struct ResolvedCase {
  io::Case c;
  std::vector<std::pair<std::string, std::string>> wing_overrides;  ///< (key in the wing file, TOML text)
  double spring_scale = 1.0;
  std::string inputs_hash;  ///< io::input_hash of the case, its wing, chain file and spring factor
  /// The warnings of the case file and of its wing file with the point's values, in a few
  /// words for sweep.csv's message: "numerics.far_wake_cycles: far_wake_cycles = 1 in hover is
  /// outside the measured range 0.5 to 0.625" (a wing key with its "wing." prefix).
  std::vector<std::string> file_warnings;
  /// The case's one-thread time as `flapsim run` estimates it (app::estimate_run) [s]; 0 when
  /// its setup fails in its numerics (the case meets it when it runs). A wing reduced in the
  /// case's setup counts as structure.bodies bodies.
  double estimated_seconds = 0.0;
};

/// \brief The case's warnings for app::RunOptions::warnings (summary.json's "warnings"), as a
/// sweep's case and an optimisation's point record them: the files' (r.file_warnings), then
/// the setup's (app::setup_warnings, their headlines), '; '-joined; each is also appended to
/// \p notes (which starts as r.file_warnings), for the case's row. \p r and \p notes must
/// outlive the run.
std::function<std::string(const app::FsiSetup&)> recorded_warnings(const ResolvedCase& r,
                                                                   std::vector<std::string>& notes);

/// Where a point's values were written: a row of a `--cases` table (its file, the line of
/// its header and of the row). An empty file: `--vary` values, from the command line.
struct PointSource {
  std::string file;
  int header_line = 0;
  int line = 0;
};

/// \brief Reads and checks the case (and its wing) with the point's values set, and checks
/// it as `flapsim check` and `flapsim run` do before a run: the chain file matched to the
/// case, loads and markers on existing bodies, the lattice and reference speed, the run's
/// size against the memory (a wing reduced in process: all but the reduction).
/// \throws flapsim::InputError naming the file and key. A problem of a varied key from a
///         case table names the table, the line (the header's for the key's name, an unknown
///         key; the row's for its value) and the column; otherwise the case or wing file,
///         and the message starts with the point's values, e.g. "with
///         kinematics.rotation_phase = 3: ..."
ResolvedCase resolve_case(const SweepInputs& inputs, const CasePoint& point, const PointSource& source = {});

/// \brief The sub-folder of case \p index of \p count: the index (at least two digits,
/// as many as the count needs) and the values, e.g. "03_-0.05" or "07_0.1_2".
std::string case_folder(std::size_t index, std::size_t count, const CasePoint& point);

/// \brief "key = value, key = value" of a point, for messages.
std::string describe(const CasePoint& point);

}  // namespace flapsim::sweep
