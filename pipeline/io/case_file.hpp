#pragma once
/// \file case_file.hpp
/// \brief Reading case files (docs/case_file.md) and periodic signals from TOML.

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "mbd/periodic_signal.hpp"
#include "pipeline/io/case_model.hpp"
#include "wings/loader/toml_reader.hpp"

namespace flapsim::io {

/// Reads and checks a case file.
/// \param path case file (TOML); wing and chain paths inside resolve against its folder
/// \throws flapsim::InputError naming file, line and key for any bad input
Case load_case_file(const std::string& path);

/// Reads a case from an already parsed TOML document (top-level table); paths resolve
/// against the document's folder.
/// \throws flapsim::InputError
Case read_case(wings::TomlTable root);

/// Reads a case file with some keys overridden (parameter sweeps), e.g.
/// {{"kinematics.rotation_phase", "-0.1"}}; values are TOML text (quote strings).
/// \throws flapsim::InputError (errors on an overridden key say so)
Case load_case_file(const std::string& path,
                    const std::vector<std::pair<std::string, std::string>>& overrides);

/// True if the top-level table looks like a case file (it has a [kinematics] table).
bool is_case_document(const wings::TomlTable& root);

/// The most harmonics of a signal's series (`cos…`, `sin…`): every time step evaluates
/// each one, and a million made a run's setup hang; 1000 is far beyond what a time step
/// of steps_per_cycle resolves (harmonic n needs more than 2n steps per cycle).
inline constexpr std::size_t kMaxSignalHarmonics = 1000;

/// A periodic signal from `table[key]`: a number (constant), a harmonic table
/// { mean<suffix> = m, cos<suffix> = [a1, a2, ...], sin<suffix> = [b1, ...] } or a
/// tabulated one { phase = [s0, s1, ...], <values_key> = [v0, v1, ...] } (periodic cubic
/// spline, phases strictly increasing in [0, 1), at least 3 points). Values are multiplied
/// by `scale` (e.g. π/180 for degrees).
/// \param suffix     key suffix of the harmonic coefficients, e.g. "_deg" or ""
/// \param values_key key of the tabulated values, e.g. "deg" or "value"
/// \param fallback   returned when the key is absent
/// \param frequency_hz the wingbeat's (0: unknown): a table whose points leave more than half
///                   the cycle without one is refused, and named as times in seconds when it
///                   spans most of a period at this frequency
/// \param warnings   where a table whose spline accelerates with its points' scatter is warned
///                   (pipeline/io/table_scatter_warning.hpp); nullptr: not checked
/// A table may also be a column of a CSV file, { file = "...", column = "..." }
/// (pipeline/io/kinematics_csv.hpp), and either kind a fitted series with harmonics = N.
/// At most kMaxSignalHarmonics cosine and as many sine coefficients.
/// \throws flapsim::InputError
mbd::PeriodicSignal read_periodic_signal(const wings::TomlTable& table, std::string_view key,
                                         std::string_view suffix, std::string_view values_key, double scale,
                                         const mbd::PeriodicSignal& fallback, double frequency_hz = 0.0,
                                         std::vector<InputWarning>* warnings = nullptr);

/// \brief A flapping wing in air whose whole wake is free: a sweep that swings, a fixed pivot,
/// no revolution, a free wake not steady, frozen, capped or convected (far_wake_cycles 0).
/// The case the hover's far-wake default serves in still air (kHoverFarWakeCycles) and that
/// a slow free stream is warned of (pipeline/app/slow_stream_hover_warning.hpp).
bool flaps_with_whole_free_wake(const Case& c);

/// \brief A case name made safe as one folder name (flapsim run's default output folder
/// out/<name>): letters, digits, '-', '_' and '.' kept, anything else (a '/', a space)
/// replaced by '_'; a leading '.' becomes '_' ("..", ".hidden"); empty gives "case".
/// A case name is never used as a path.
std::string folder_name_of(const std::string& name);

}  // namespace flapsim::io
