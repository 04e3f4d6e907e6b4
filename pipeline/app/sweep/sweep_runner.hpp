#pragma once
/// \file sweep_runner.hpp
/// \brief Runs the cases of a sweep and tabulates them in sweep.csv (docs/sweeps.md).
///
/// 1. Every case is resolved and checked (case file, wing file, chain file) before the
///    first one starts: a bad value, or a varied key that changes nothing in the runs
///    (keys_that_change_nothing.hpp), stops the sweep with nothing run.
/// 2. Resuming: a case whose folder holds a summary.json with status "ok" and the hash
///    of the case's inputs (io::input_hash) is kept, not run again (unless `force`); its
///    row repeats the warnings its run had (kept_message).
/// 3. The other cases are scheduled dynamically (case_scheduler.hpp) over worker threads
///    — and over MPI ranks when launched by mpirun/srun — one case per thread at a time,
///    with OpenMP limited to one thread inside a case. Each case writes its own
///    sub-folder `DIR/<index>_<values>/` (history.csv, summary.json; VTK if asked).
///    A case that fails (numerically, or cannot run) is recorded with its status and
///    message, and the others go on.
/// 4. sweep.csv (sweep_table.hpp) is rewritten atomically as cases finish (after every
///    case for tables up to 1000 rows, then at most every 5 s) and at the end.

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "pipeline/app/sweep/case_scheduler.hpp"
#include "pipeline/app/sweep/sweep_case.hpp"
#include "pipeline/app/sweep/sweep_table.hpp"
#include "pipeline/app/sweep/sweep_values.hpp"

namespace flapsim::sweep {

struct SweepOptions {
  std::filesystem::path output_dir;
  std::string chain_file;        ///< passed to every case (flapsim run --chain)
  std::string wing_file;         ///< flown by every case instead of the case's 'wing' (flapsim run --wing)
  double spring_scale = 1.0;     ///< passed to every case (flapsim run --spring-scale)
  int threads = 0;               ///< per rank; 0 = the machine's cores / the ranks on it
  int vtk_every = 0;             ///< VTK series per case (0 = none, the default for sweeps)
  bool force = false;            ///< run every case, also those an earlier run completed
  bool quiet = false;            ///< no progress lines
  /// Stderr not a terminal: a line on the cases under way when this long has passed since
  /// the sweep's last line (sweep_progress.hpp; --log-every).
  std::chrono::milliseconds log_interval{std::chrono::seconds(30)};
};

/// The cases of a sweep: the varied keys and one point (their values) per case.
struct SweepPlan {
  std::vector<std::string> keys;
  std::vector<CasePoint> points;
  std::string table_file;   ///< the --cases table the points come from ("" for --vary)
  int header_line = 0;      ///< its header's line
  std::vector<int> lines;   ///< the line of each point's row

  /// Where point \p i was written (for messages; an empty file for --vary).
  PointSource source(std::size_t i) const {
    if (table_file.empty()) return {};
    return {table_file, header_line, i < lines.size() ? lines[i] : 0};
  }
};

struct SweepReport {
  bool root = true;            ///< this process holds the table (rank 0, or no MPI)
  std::vector<SweepRow> rows;  ///< one per case, in order (rank 0 only)
  int ranks = 1;
  int threads = 1;       ///< worker threads per rank
  std::size_t kept = 0;  ///< cases kept from an earlier run
  ScheduleStats stats;   ///< the cases run (rank 0: over all ranks)
  double wall_s = 0.0;   ///< wall time of the sweep [s]
};

/// \brief The plan of `--vary` arguments (their Cartesian grid).
SweepPlan grid_plan(const std::vector<Variation>& variations);

/// \brief Runs the sweep.
/// \throws flapsim::InputError before anything runs if a case is invalid
SweepReport run_sweep(const std::string& case_file, const SweepPlan& plan, const SweepOptions& options);

}  // namespace flapsim::sweep
