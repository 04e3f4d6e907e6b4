#pragma once
/// \file interruption.hpp
/// \brief SIGINT and SIGTERM during a run: the handler only records the signal; the time
/// loop looks at it after each step, and the step itself between its solves
/// (pipeline/fsi/stop_request.hpp: a step that is dropped), flushes history.csv and the
/// series, writes summary.json with status "interrupted" and throws Interrupted, which the
/// command line turns into exit status 128 + signal (130 for SIGINT, 143 for SIGTERM).

#include <stdexcept>
#include <string>

namespace flapsim::app {

/// A run stopped by a signal, after a completed step or within one (the step dropped).
class Interrupted : public std::runtime_error {
 public:
  Interrupted(int signal_number, const std::string& what)
      : std::runtime_error(what), signal_(signal_number) {}
  int signal_number() const { return signal_; }

 private:
  int signal_;
};

/// Installs the recording handler for SIGINT and SIGTERM (idempotent).
void install_interrupt_handlers();

/// The signal received since the handlers were installed (0 = none).
int pending_interrupt();

/// Records \p signal_number as received (a signal a StageMonitor took off after its stages).
void record_interrupt(int signal_number);

/// Throws Interrupted if a signal is pending (between two steps of a long computation).
/// \param where  what was interrupted, for the message (e.g. "after step 12")
void throw_if_interrupted(const std::string& where);

}  // namespace flapsim::app
