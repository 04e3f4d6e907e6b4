#pragma once
/// \file wake_age.hpp
/// \brief When a wake row has reached an age: the far wake's, the frozen wake's.
///
/// A row's age is the sum of the time steps since it was shed, and the ages a case sets are
/// often a whole number of steps (far_wake_cycles = 0.5 at 40 steps a wingbeat: 20 steps).
/// Compared plainly, the sum of 20 steps against half the period fell on either side by
/// round-off, with the frequency's last bits: at 13.986 Hz the row joined the far wake a step
/// later than at 13.988 Hz, and a film wing's lift per power jumped by 1.1 % between
/// frequencies 0.002 Hz apart, in a pattern an optimiser converged on (6 Dec). A row within
/// round-off of the age has reached it: the rule the shipped cases' steps (26.1 Hz at 100 a
/// wingbeat, 12 and 20 Hz at 80) already fell on, so their runs are unchanged.

namespace flapsim::uvlm {

/// Relative tolerance of an age comparison: sums of a few thousand steps are within 1e-12
/// of their exact value; a step is more than 1e-6 of any age a case sets.
inline constexpr double kWakeAgeTolerance = 1e-9;

/// \brief Whether a row of age \p age [s] has reached \p threshold [s] (> 0): at or beyond it,
/// to round-off.
inline bool reached_age(double age, double threshold) { return age >= threshold * (1.0 - kWakeAgeTolerance); }

}  // namespace flapsim::uvlm
