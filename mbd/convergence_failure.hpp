#pragma once
/// \file convergence_failure.hpp
/// \brief The error the chain integrator throws when a step cannot be solved
/// (quasi-Newton iteration does not converge, or the state turns NaN/Inf).
/// mbd depends on Eigen only, so this is its own type; the pipeline maps it to
/// flapsim::NumericalFailure (exit status 3), keeping step and time.

#include <stdexcept>
#include <string>

namespace flapsim::mbd {

class ConvergenceFailure : public std::runtime_error {
 public:
  /// \param what  what went wrong
  /// \param step  index of the step being solved (0-based: the step from state.step)
  /// \param time  time at the end of that step [s]
  ConvergenceFailure(const std::string& what, long step, double time)
      : std::runtime_error("multibody step " + std::to_string(step) +
                           " (t = " + std::to_string(time) + " s): " + what),
        reason_(what), step_(step), time_(time) {}
  /// What went wrong, without the step and time (for a caller that names them itself).
  const std::string& reason() const { return reason_; }
  long step() const { return step_; }
  double time() const { return time_; }

 private:
  std::string reason_;
  long step_;
  double time_;
};

}  // namespace flapsim::mbd
