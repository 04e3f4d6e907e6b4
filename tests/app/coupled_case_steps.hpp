#pragma once
// A case run through the coupled step itself (fsi::coupled_step, fsi::shed_wake) instead of
// `flapsim run`, so that a test can set what the case file cannot (CouplingSettings, the
// lattice's solver) and read what the summary does not hold (solver counts, every step's
// lift), shared by the app tests that compare two coupling paths.
#include <functional>
#include <string>

#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/fsi/coupled_step.hpp"
#include "pipeline/io/case_model.hpp"

namespace flapsim::test {

/// The case `c` with the chain file `chain`: its FSI model changed by `adjust`, then its
/// first `steps` coupled steps (at most c.numerics.cycles × steps_per_cycle), calling
/// `each_step(k, setup, data)` after step k's coupled step (before its wake is shed).
/// Exceptions (NumericalFailure) pass on.
inline void run_coupled_steps(const io::Case& c, const std::string& chain, int steps,
                              const std::function<void(fsi::FsiModel&)>& adjust,
                              const std::function<void(int, const app::FsiSetup&, const fsi::FsiData&)>& each_step) {
  app::SetupOptions options;
  options.chain_file = chain;
  app::FsiSetup setup = app::build_fsi_setup(c, options);
  adjust(setup.model);
  fsi::FsiData data(setup.model);
  fsi::initialize(setup.model, data, 0.0);
  for (int k = 0; k < steps; ++k) {
    fsi::coupled_step(setup.model, data, setup.dt);
    each_step(k, setup, data);
    fsi::shed_wake(setup.model, data);
  }
}

/// The lattice's lift [N] of the last solve, along the case's lift direction.
inline double lattice_lift(const app::FsiSetup& setup, const fsi::FsiData& data) {
  return data.lattice->loads.total_force.dot(setup.reference.lift_direction);
}

}  // namespace flapsim::test
