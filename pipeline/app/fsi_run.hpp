#pragma once
/// \file fsi_run.hpp
/// \brief A whole coupled run of a case with its outputs (docs/fsi.md, "Outputs"):
///  1. setup (fsi_setup.hpp): the coupled model of the case;
///  2. the time loop: fsi::coupled_step, the recorder, fsi::shed_wake, the progress line;
///  3. the recorder (run_recorder.hpp): history.csv every step, the ParaView series
///     wing.pvd, wake.pvd, chain.pvd every `output.vtk_every` steps, and at the end the
///     run's results (run_results.hpp) as summary.json.
/// A run that fails numerically writes summary.json with status "failed" and the error,
/// keeps history.csv and the series up to the last good step, and rethrows; a run
/// interrupted by SIGINT/SIGTERM finishes its step and does the same with "interrupted".

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/app/progress.hpp"
#include "pipeline/app/run_results.hpp"
#include "pipeline/io/case_model.hpp"

namespace flapsim::app {

struct RunOptions {
  std::filesystem::path output_dir;  ///< created if missing
  std::string chain_file;            ///< overrides the case's chain file ("" = none)
  double spring_scale = 1.0;         ///< joint-spring factor of a flexible chain (SetupOptions)
  std::optional<int> vtk_every;      ///< overrides output.vtk_every (0 = no VTK)
  /// Values set in the wing file before it is read (SetupOptions::wing_overrides).
  std::vector<std::pair<std::string, std::string>> wing_overrides;
  ProgressLine::Mode progress = ProgressLine::Mode::automatic;
  /// Called after each step with the steps done and the run's total (a sweep's progress).
  std::function<void(long step, long total)> on_step;
  /// Called with the setup before the recorder creates any file (the resource estimate
  /// of flapsim run); may throw to refuse the run.
  std::function<void(const FsiSetup&)> before_start;
  /// Called after before_start: the case's warnings in a few words, '; '-separated (a
  /// sweep's message column), recorded in summary.json as "warnings" when not empty.
  std::function<std::string(const FsiSetup&)> warnings;
};

/// \brief Runs a case and writes its outputs into options.output_dir.
/// \return the run's results (also in summary.json)
/// \throws flapsim::InputError on bad input (before anything is written),
///         flapsim::NumericalFailure when the run diverges (outputs so far stay valid),
///         Interrupted after SIGINT/SIGTERM (interruption.hpp; summary.json says
///         "interrupted", outputs up to the last step stay valid), io::OutputError
RunResults run_case(const io::Case& c, const RunOptions& options);

}  // namespace flapsim::app
