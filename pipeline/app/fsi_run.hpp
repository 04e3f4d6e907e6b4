#pragma once
/// \file fsi_run.hpp
/// \brief A whole coupled run of a case with its outputs (docs/fsi.md, "Outputs"):
///  - history.csv   per step: t, base φ θ α, tip φ θ α (degrees, stroke-plane frame),
///                  aerodynamic force Fx Fy Fz, lift, CL, coupling iterations and the
///                  final structure change, the outer body's φ θ α (the body at 5/6 of the
///                  chain length), joint angles, marker positions;
///  - summary.json  last-cycle means (lift, CL, force), rotation phases of base and tip
///                  and their difference, coupling statistics, wall time, status;
///  - wing.pvd, wake.pvd, chain.pvd  ParaView series (every `output.vtk_every` steps).
/// A run that fails numerically writes summary.json with status "failed" and the step,
/// keeps history.csv and the series up to the last good step, and rethrows.

#include <filesystem>
#include <optional>
#include <string>

#include "pipeline/io/case_model.hpp"
#include "pipeline/app/progress.hpp"

namespace flapsim::app {

struct RunOptions {
  std::filesystem::path output_dir;  ///< created if missing
  std::string chain_file;            ///< overrides the case's chain file ("" = none)
  double spring_scale = 1.0;         ///< joint-spring factor of a flexible chain (SetupOptions)
  std::optional<int> vtk_every;      ///< overrides output.vtk_every (0 = no VTK)
  app::ProgressLine::Mode progress = app::ProgressLine::Mode::automatic;
};

/// What a run reports (also in summary.json).
struct RunSummary {
  long steps = 0;                  ///< steps completed
  double mean_lift = 0.0;          ///< last-cycle mean lift [N]
  double mean_cl = 0.0;            ///< last-cycle mean CL [-]
  double base_rotation_phase = 0.0;  ///< base δψ measured from the angles [-]
  double tip_rotation_phase = 0.0;   ///< tip δψ (tip α = 90° vs tip sweep reversal) [-]
  double tip_rotation_lag = 0.0;     ///< tip α = 90° crossings minus base's, fraction of T [-]
  double tip_sweep_lag = 0.0;        ///< tip φ zero-mean crossings minus base's [-]
  /// The same for the outer body (holding 5/6 of the chain length, fsi_run.cpp) [-].
  double outer_rotation_phase = 0.0;
  double outer_rotation_lag = 0.0;
  double mean_coupling_iterations = 0.0;
  int max_coupling_iterations = 0;
  double wall_time_s = 0.0;
  std::string structure;           ///< where the structure came from
};

/// \brief Runs a case and writes its outputs into options.output_dir.
/// \throws flapsim::InputError on bad input (before anything is written),
///         flapsim::NumericalFailure when the run diverges (outputs so far stay valid)
RunSummary run_case(const io::Case& c, const RunOptions& options);

}  // namespace flapsim::app
