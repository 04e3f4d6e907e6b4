#pragma once
/// \file wing_modes_stage.hpp
/// \brief What `flapsim modes` computes, without its files: the wing's FEM, its lowest
/// modes, the four static tip load cases and the modes' names from the stations of the
/// N-body chain; with the wall time of each stage (bench/bench_fem.cpp reports them,
/// docs/performance.md "FEM stage").

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "fem/wing_fem.hpp"
#include "pipeline/io/fem_vtk.hpp"
#include "wings/loader/wing_model.hpp"

namespace flapsim::app {

struct WingModesStage {
  fem::WingFem fem;
  fem::WingModes modes;
  std::vector<io::StaticResult> statics;  ///< the four tip load cases (fem/load_cases.hpp)
  std::vector<io::ModeLabel> labels;      ///< one per mode
  /// Wall time of each stage [s]: "mesh", "assembly", the eigen-solve and the static side
  /// together (wall), then each part of them ("eigen-solve", "factorisation", "static load
  /// cases", "reduction chain"), and "mode names".
  std::vector<std::pair<std::string, double>> stage_seconds;
};

/// \brief The FEM stage of a wing. With \p threads ≥ 2 the eigen-solve runs beside the
/// static side (the clamped stiffness factorised once for the four tip load cases and the
/// reduction's load cases, and the chain that names the modes); the results are the same
/// bits as with one thread. \p stage is called with the name of each stage the
/// command's progress line shows as it begins ("mesh and FEM matrices", "FEM modes",
/// "static load cases", "mode names"). Failures of the numerics throw
/// flapsim::NumericalFailure naming the stage (exit 3), bad input InputError (exit 2).
WingModesStage compute_wing_modes(const wings::Wing& wing, int num_modes, int bodies, int threads,
                                  const std::function<void(const std::string&)>& stage = {});

}  // namespace flapsim::app
