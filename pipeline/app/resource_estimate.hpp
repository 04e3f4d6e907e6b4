#pragma once
/// \file resource_estimate.hpp
/// \brief What a run will cost, known from the case before it starts: memory (the wake,
/// the lattice's influence matrix, the per-step samples, the chain's matrices), Biot–Savart
/// interactions and an order-of-magnitude time. `flapsim check` prints it for a case;
/// `flapsim run` prints it before a long run and refuses a run whose memory cannot fit
/// (docs/case_file.md, "Size of a run").
///
/// The memory model counts the arrays a run allocates (uvlm/vortex_lattice.cpp: wake
/// nodes, wake circulations and AB2 velocities, wake segments; the dense influence matrix
/// and its LU; one StepSample per step for the end-of-run analysis; dense chain matrices).
/// Interactions: every wake node sees every bound and wake segment (free wake), and every
/// collocation point sees every wake segment per coupling iteration. The time divides them
/// by a nominal single-thread throughput; it is an order of magnitude, not a measurement.

#include <cstdint>
#include <string>

#include "pipeline/io/case_model.hpp"

namespace flapsim::app {

struct RunEstimate {
  std::int64_t steps = 0;          ///< time steps
  std::int64_t wake_panels = 0;    ///< largest wake [panels]
  double memory_bytes = 0.0;       ///< peak memory of the run's arrays [B]
  double interactions = 0.0;       ///< Biot–Savart segment-point evaluations of the whole run
  double structure_flops = 0.0;    ///< dense chain solves of the whole run [flop]
  double seconds = 0.0;            ///< order of magnitude of the wall time, one thread [s]
};

/// Nominal single-thread throughputs of the time estimate (orders of magnitude).
inline constexpr double kInteractionsPerSecond = 1e8;
inline constexpr double kFlopsPerSecond = 1e9;
/// Runs estimated above this are "long": flapsim run prints the estimate first [s].
inline constexpr double kLongRunSeconds = 10.0;

/// \param bodies  bodies of the chain the run will use (the case's structure.bodies)
RunEstimate estimate_run(const io::Case& c, int bodies);

/// One line: "estimate: N steps, up to W wake panels, memory ~X, ~Y interactions, ~T".
std::string describe(const RunEstimate& e);

/// Memory this process may use [B]: the physical memory, or less if an address-space
/// limit (ulimit -v) is set.
double usable_memory_bytes();

/// \throws flapsim::InputError (key numerics.cycles) if the run's memory exceeds
///         usable_memory_bytes(), naming both and the keys that shrink the run
void refuse_if_it_cannot_fit(const RunEstimate& e, const io::Case& c);

}  // namespace flapsim::app
