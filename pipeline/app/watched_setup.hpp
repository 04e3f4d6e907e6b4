#pragma once
/// \file watched_setup.hpp
/// \brief The run's setup built by a command that writes no files (`flapsim check`), watched
/// as `run` watches its own (stage_monitor.hpp): a wing reduced in process takes its FEM's
/// time (seconds to a minute), so the stage is shown on stderr once it has lasted 2 s
/// ("check: setup (the wing's FEM, reduction and modes) (stage 1 of 1): 14 s, 14 s in all"), and
/// SIGINT/SIGTERM end the command at once (128 + signal; nothing was written).

#include <functional>
#include <string>

#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/app/stage_monitor.hpp"
#include "pipeline/io/case_model.hpp"

namespace flapsim::app {

/// \brief Whether the setup reduces the case's wing in process: a flexible case without a
/// chain file (neither the case's `chain` nor \p chain_file, the command's `--chain`).
bool reduces_wing_in_process(const io::Case& c, const std::string& chain_file);

/// \brief The setup's name in the progress line: "setup (the wing's FEM, reduction and modes)" when
/// the wing is reduced in process, else "setup".
std::string setup_stage_name(const io::Case& c, const std::string& chain_file);

/// \brief build_fsi_setup(c, options) watched by a StageMonitor named \p command, after
/// \p first (checks of the same stage, e.g. `check`'s dry run of the mesher), if given.
FsiSetup build_fsi_setup_watched(const io::Case& c, const SetupOptions& options, const std::string& command,
                                 const std::function<void()>& first = {}, const StageMonitor::Options& watch = {});

}  // namespace flapsim::app
