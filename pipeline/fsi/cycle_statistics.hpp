#pragma once
/// \file cycle_statistics.hpp
/// \brief The mean of a run's series over many cycles and how well it is known, for flows
/// that do not repeat from cycle to cycle.
///
/// A periodic run settles to one cycle that repeats, and its last cycle's mean is the
/// result (summary.json's mean_ keys). A run whose flow does not repeat (the shed
/// leading-edge sheet the wing meets again after each reversal: docs/uvlm.md, "Lua et
/// al.'s hover over many cycles") has cycle means that scatter; its result is their mean
/// over many cycles, known to within the standard error of that mean, as any statistic of
/// a flow that is steady only in the mean.

#include <vector>

namespace flapsim::fsi {

/// Means of a series over whole cycles and their statistics.
struct CycleStatistics {
  std::vector<double> cycle_means;  ///< mean over each whole cycle used, in order
  double mean = 0.0;                ///< mean of cycle_means (= the mean over those cycles)
  double deviation = 0.0;           ///< sample standard deviation of cycle_means
  double standard_error = 0.0;      ///< deviation / √n: how well `mean` is known if the cycles are independent
  double lag_one_correlation = 0.0; ///< correlation of each cycle's mean with the next's (0 for independent cycles)
  /// The least-squares line through cycle_means against the cycle's index, from the first
  /// cycle used to the last: its slope × (n − 1). For independent cycles its rms is
  /// √12 √((n − 1)/(n + 1)) standard errors (the slope spreads by σ √(12/(n (n² − 1))));
  /// cycles still settling drift by more, in a monotone approach the lag-one correlation of a
  /// few cycles does not see (0.12 on 3.233, 3.206, 3.204, 3.198, 3.197; drift −0.032).
  double drift = 0.0;
};

/// \brief Whole cycles of period T [s] in [0, t_end]; a cycle that ends within a millionth of a
/// period of t_end counts (the step times are sums of Δt).
int whole_cycles(double period, double t_end);

/// \brief Statistics of x over the whole cycles [k T, (k+1) T] from cycle `first_cycle`
/// (1-based: 2 leaves out the first cycle, the start from rest) to the last that ends by
/// t_end; each cycle's mean by the trapezoidal rule on its samples (window_mean). t and x
/// start at t = 0. Needs at least two such cycles.
/// \param period  T [s]
/// \throws std::invalid_argument with fewer than two whole cycles from first_cycle on
CycleStatistics cycle_statistics(const std::vector<double>& t, const std::vector<double>& x, double period,
                                 double t_end, int first_cycle);

}  // namespace flapsim::fsi
