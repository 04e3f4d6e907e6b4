#pragma once
/// \file serial_openmp_regions.hpp
/// \brief While a SerialOpenMpRegions lives, the OpenMP parallel regions that the thread
/// which made it starts run on that thread alone (max-active-levels 0, an ICV of the
/// thread's own data environment: other threads keep theirs).
///
/// For CHOLMOD's calls (docs/fem.md, "CHOLMOD's own threads"): Debian's libcholmod3 opens
/// parallel regions with a team of 4 threads fixed when it was compiled
/// (CHOLMOD_OMP_NUM_THREADS) for loops of microseconds (clearing its map of the n rows at
/// every factorisation, zeroing supernodes), whatever OMP_NUM_THREADS or --threads says. On
/// a 2-core machine each wakes and parks threads that outnumber the cores. Those loops
/// give each row to one thread, so the factor is the same bits either way.

#include <omp.h>

namespace flapsim::fem {

class SerialOpenMpRegions {
 public:
  SerialOpenMpRegions() : saved_(omp_get_max_active_levels()) { omp_set_max_active_levels(0); }
  ~SerialOpenMpRegions() { omp_set_max_active_levels(saved_); }
  SerialOpenMpRegions(const SerialOpenMpRegions&) = delete;
  SerialOpenMpRegions& operator=(const SerialOpenMpRegions&) = delete;

 private:
  int saved_;
};

}  // namespace flapsim::fem
