#pragma once
/// \file omp_environment.hpp
/// \brief Whether the user set OpenMP's thread count in the environment: then it is the
/// threads of each process, for a sweep's or an optimisation's cases too (docs/performance.md,
/// docs/sweeps.md), where otherwise the machine's cores are shared by the MPI ranks on it.

#include <cstdlib>

namespace flapsim::app {

/// OMP_NUM_THREADS is set and not empty.
inline bool omp_num_threads_set() {
  const char* value = std::getenv("OMP_NUM_THREADS");
  return value != nullptr && *value != '\0';
}

}  // namespace flapsim::app
