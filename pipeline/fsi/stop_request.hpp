#pragma once
/// \file stop_request.hpp
/// \brief A coupled step can last minutes (a film's FEM steps split into up to 256 pieces,
/// each solved again at every sub-iteration; docs/fsi.md, "Step halving of the FEM"), so
/// the loops inside it ask between their solves whether the program wants to stop: the
/// coupling before each lattice solve, the FEM before each piece. The program registers
/// the question (`flapsim run`: a check that throws app::Interrupted after SIGINT/SIGTERM,
/// pipeline/app/interruption.hpp); the coupling knows nothing of signals. Per thread: the
/// cases of a sweep run on threads of their own, each with its own check.

#include <functional>

namespace flapsim::fsi {

/// Asked between the solves of a step; it stops the step by throwing (anything it throws
/// leaves the step through coupled_step, as a numerical failure does).
using StopCheck = std::function<void()>;

/// Registers \p check for this thread's coupled steps while it lives; the check registered
/// before comes back at its end.
class ScopedStopCheck {
 public:
  explicit ScopedStopCheck(StopCheck check);
  ~ScopedStopCheck();
  ScopedStopCheck(const ScopedStopCheck&) = delete;
  ScopedStopCheck& operator=(const ScopedStopCheck&) = delete;

 private:
  StopCheck previous_;
};

/// Calls this thread's registered check (nothing if none).
void check_stop();

}  // namespace flapsim::fsi
