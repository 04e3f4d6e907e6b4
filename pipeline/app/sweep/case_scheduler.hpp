#pragma once
/// \file case_scheduler.hpp
/// \brief Dynamic scheduling of a sweep's cases: whoever is free takes the next case.
///  - One machine: `threads` worker threads take the cases in order from a shared list.
///  - MPI (master/worker): rank 0 holds the list. Every rank runs `threads` worker
///    threads; a worker thread of rank r > 0 sends rank 0 a request carrying the outcome
///    of its previous case (encode_outcome) and receives the index of its next case, or
///    −1 when none is left; rank 0's own worker threads take cases from the list
///    directly, while its main thread answers the requests (polling every millisecond,
///    so it does not take a core from the cases). Every outcome ends up on rank 0, which
///    hands it to `done` one at a time (it writes the table).
/// A case's scheduling overhead is the time its worker spends outside the run: from the
/// end of its previous case (reporting it, writing the table, asking for the next) to
/// the start of this one, and after the last case until the worker is told to stop.

#include <cstddef>
#include <functional>
#include <vector>

#include "pipeline/app/sweep/mpi_world.hpp"
#include "pipeline/app/sweep/sweep_table.hpp"

namespace flapsim::sweep {

/// Runs case `index` on the calling thread; never throws (failures are outcomes).
using RunCase = std::function<CaseOutcome(std::size_t index)>;
/// Takes a finished case's outcome (rank 0 only, one call at a time); may throw, which
/// stops handing out cases and is rethrown by schedule_cases.
using CaseDone = std::function<void(std::size_t index, CaseOutcome&& outcome)>;

struct ScheduleStats {
  std::size_t cases = 0;    ///< cases run, over all ranks
  double overhead_s = 0.0;  ///< their scheduling overhead, summed [s]
  double max_overhead_s = 0.0;
};

/// \brief Runs the cases \p todo (indices, in the order to start them) with \p threads
/// worker threads per rank over the ranks of \p world.
/// \return on rank 0: the statistics over all ranks (on other ranks: their own)
ScheduleStats schedule_cases(const MpiWorld& world, const std::vector<std::size_t>& todo, int threads,
                             const RunCase& run, const CaseDone& done);

}  // namespace flapsim::sweep
