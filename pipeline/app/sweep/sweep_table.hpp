#pragma once
/// \file sweep_table.hpp
/// \brief The rows of a sweep and its table, sweep.csv: one column per varied key, the
/// results with a sweep label (app::sweep_results()), then the sweep-only columns
/// (app::kSweepColumns: folder, status, message, rank, host); one row per finished case,
/// in the order of the cases. Written whole and atomically, so an interrupted sweep
/// leaves a valid table of the cases finished so far.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "pipeline/app/run_results.hpp"
#include "pipeline/app/sweep/sweep_values.hpp"

namespace flapsim::sweep {

/// How one case of a sweep ended, and where it ran.
struct CaseOutcome {
  std::string status;       ///< "ok", "failed" (numerical failure), "error" (could not run)
  std::string message;      ///< the error, or "kept" (kept_message); then the case's warnings
  int rank = 0;             ///< MPI rank that ran it (0 without MPI)
  std::string host;         ///< machine that ran it
  app::RunResults results;  ///< the run's results (what summary.json holds)
  double overhead_s = 0.0;  ///< time its worker spent on it outside the run itself [s]
};

struct SweepRow {
  CasePoint point;     ///< the values of the varied keys
  std::string folder;  ///< the case's sub-folder
  bool done = false;   ///< finished (or kept): has an outcome
  CaseOutcome outcome;
};

/// \brief \p message followed by each note, "; "-separated: with_notes("", {"a", "b"}) is "a; b".
std::string with_notes(std::string message, const std::vector<std::string>& notes);

/// \brief The message of a case kept from an earlier run: "kept", then the warnings of that
/// run as its row gave them (its summary.json's "warnings", a large deflection of its tip),
/// e.g. "kept; numerics.far_wake_cycles: far_wake_cycles = 1 in hover is outside ...".
std::string kept_message(const app::RunResults& earlier);

/// Where a case of an earlier table ran: its rank and host.
struct RanOn {
  int rank = 0;
  std::string host;
};

/// \brief The rank and host of each case folder in an earlier sweep.csv at \p path (empty if
/// it is missing or unreadable): a case kept from it keeps where it ran, where its row said
/// the rank that found it kept (under MPI, rank 0 and its host for every case).
std::map<std::string, RanOn> earlier_ran_on(const std::filesystem::path& path);

/// \brief Whether the outcome is that of a case kept from an earlier run (kept_message).
bool kept_from_earlier_run(const CaseOutcome& outcome);

/// \brief The header of sweep.csv for the varied \p keys.
std::vector<std::string> sweep_table_header(const std::vector<std::string>& keys);

/// \brief Writes sweep.csv: the header and one row per done case.
/// \throws io::OutputError
void write_sweep_table(const std::filesystem::path& path, const std::vector<std::string>& keys,
                       const std::vector<SweepRow>& rows);

/// \brief An outcome as bytes (to send it between ranks) and back.
std::string encode_outcome(std::size_t index, const CaseOutcome& outcome);
/// \throws std::runtime_error on bytes encode_outcome did not make
CaseOutcome decode_outcome(const std::string& bytes, std::size_t& index);

/// \brief The name of this machine (gethostname), "unknown" if it has none.
std::string host_name();

}  // namespace flapsim::sweep
