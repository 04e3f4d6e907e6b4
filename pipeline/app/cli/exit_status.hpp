#pragma once
/// \file exit_status.hpp
/// \brief The one exit-status contract of every flapsim command (README.md, "Exit status").

namespace flapsim::cli {

enum ExitStatus : int {
  kExitOk = 0,         ///< success
  kExitUsage = 1,      ///< command-line usage error (unknown option, missing argument)
  kExitInput = 2,      ///< bad input: the message names file, line and key; nothing written
  kExitNumerical = 3,  ///< numerical failure (divergence, no convergence): names the step;
                       ///< every file written so far stays valid
  kExitOutput = 4,     ///< output or system error: a file cannot be written (no permission,
                       ///< disk full, file-size limit), out of memory; no truncated file is
                       ///< left under a final name
};

/// Interrupted by a signal (SIGINT: 130, SIGTERM: 143): 128 + the signal number, as a shell
/// reports a process a signal ended. The step under way is finished and the outputs flushed.
constexpr int exit_status_of_signal(int signal_number) { return 128 + signal_number; }

}  // namespace flapsim::cli
