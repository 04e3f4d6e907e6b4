#pragma once
/// \file sequential_vtk.hpp
/// \brief VTK's writers on the calling thread, not on threads of their own.
///
/// VTK's SMP tools (TBB in Debian's VTK 9.1) compute the value ranges every array of a frame
/// lists in its XML header, on a thread pool of their own that then spins beside the run's
/// OpenMP threads: 15 % of the CPU time of a 16-wingbeat rigid hover writing a frame each
/// step (2-core AMD EPYC, 4 Dec 2026; docs/output_files.md, "Writing cost"). The frames'
/// arrays are a few thousand values; one thread computes their ranges in microseconds.

namespace flapsim::cli {

/// \brief Sets VTK_SMP_BACKEND_IN_USE=Sequential, unless the environment has a value
/// (a user's own is kept), before VTK's SMP tools first read it. Call early in main().
void run_vtk_on_the_calling_thread();

}  // namespace flapsim::cli
