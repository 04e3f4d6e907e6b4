#include "pipeline/app/watched_setup.hpp"

#include <csignal>
#include <cstdio>
#include <cstdlib>

namespace flapsim::app {

bool reduces_wing_in_process(const io::Case& c, const std::string& chain_file) {
  return c.structure.kind == io::Case::Structure::Kind::Flexible && c.chain_file.empty() && chain_file.empty();
}

std::string setup_stage_name(const io::Case& c, const std::string& chain_file) {
  if (c.structure.kind == io::Case::Structure::Kind::Fem) return "setup (the wing's FEM)";
  return reduces_wing_in_process(c, chain_file) ? "setup (the wing's FEM, reduction and modes)" : "setup";
}

FsiSetup build_fsi_setup_watched(const io::Case& c, const SetupOptions& options, const std::string& command,
                                 const std::function<void()>& first, const StageMonitor::Options& watch) {
  StageMonitor monitor(command, 1, watch);
  monitor.stage(setup_stage_name(c, options.chain_file));
  if (first) first();
  FsiSetup setup = build_fsi_setup(c, options);
  // A signal after the watcher stopped (the setup had just ended): the command ends as the
  // watcher would have ended it; nothing was written.
  if (const int late = monitor.done(); late != 0) {
    std::fprintf(stderr, "flapsim: %s interrupted by %s after its setup; nothing was written\n", command.c_str(),
                 late == SIGINT ? "SIGINT" : "SIGTERM");
    std::fflush(stdout);
    std::_Exit(128 + late);
  }
  return setup;
}

}  // namespace flapsim::app
