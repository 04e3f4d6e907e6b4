#pragma once
/// \file numerical_failure.hpp
/// \brief A run that cannot go on (NaN, no convergence of the Newton or coupling
/// loop). The CLI turns it into exit status 3; outputs written so far stay valid.

#include <stdexcept>
#include <string>

namespace flapsim {

class NumericalFailure : public std::runtime_error {
 public:
  /// \param step  time-step index (0-based) where it failed, -1 if not in a time loop
  /// \param time  simulated time of that step [s]
  /// \param in_structure  the structure's own solve failed (a StructureFailure: the FEM's
  ///        Newton iterations, the chain's integrator), not the coupling or the lattice
  NumericalFailure(const std::string& what, long step = -1, double time = 0.0, bool in_structure = false)
      : std::runtime_error(format(what, step, time)),
        reason_(what),
        step_(step),
        time_(time),
        in_structure_(in_structure) {}
  /// What went wrong, without the step and time.
  const std::string& reason() const { return reason_; }
  long step() const { return step_; }
  double time() const { return time_; }
  /// Whether the structure's own solve failed (the FEM's or the chain's), not the coupling.
  bool in_structure() const { return in_structure_; }

 private:
  static std::string format(const std::string& what, long step, double time) {
    if (step < 0) return what;
    // Numbered from 1 as the progress line and history.csv count steps: after "step 51/80"
    // the step that fails is step 52, the one that ends at `time`.
    return "step " + std::to_string(step + 1) + " (to t = " + std::to_string(time) + " s): " + what;
  }
  std::string reason_;
  long step_;
  double time_;
  bool in_structure_;
};

}  // namespace flapsim
