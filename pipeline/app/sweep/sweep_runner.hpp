#pragma once
/// \file sweep_runner.hpp
/// \brief Runs the cases of a sweep in parallel and tabulates them in sweep.csv.
///
/// Every case is read and checked before the first one starts (a bad value stops the
/// sweep with nothing run). Cases run in worker threads, one case per thread at a time,
/// as many threads as requested (default: the available cores); inside a case OpenMP is
/// limited to one thread, since the cases already fill the cores. Each case writes its
/// own sub-folder `DIR/<index>_<value>/` (history.csv, summary.json, VTK if asked); a
/// case that fails numerically is recorded with its status and the others go on.
/// sweep.csv is rewritten (atomically) after every finished case: the varied key, the
/// results with a sweep label (run_results.hpp; "nan" for a failed case), folder, status.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/app/run_results.hpp"
#include "pipeline/app/sweep/sweep_values.hpp"

namespace flapsim::sweep {

struct SweepOptions {
  std::filesystem::path output_dir;
  std::string chain_file;        ///< passed to every case (flapsim run --chain)
  double spring_scale = 1.0;     ///< passed to every case (flapsim run --spring-scale)
  int threads = 0;               ///< 0 = std::thread::hardware_concurrency()
  int vtk_every = 0;             ///< VTK series per case (0 = none, the default for sweeps)
  bool quiet = false;            ///< no progress lines
};

struct SweepRow {
  double value = 0.0;     ///< the value of the varied key
  std::string folder;     ///< the case's sub-folder, "<index>_<value>"
  std::string status;     ///< "ok", "failed: ..."
  app::RunResults results;  ///< the run's results (none for a failed case)
};

/// \brief Runs the sweep; returns one row per value, in the order of the values.
/// \throws flapsim::InputError before anything runs if a case is invalid
std::vector<SweepRow> run_sweep(const std::string& case_file, const Variation& variation,
                                const SweepOptions& options);

}  // namespace flapsim::sweep
