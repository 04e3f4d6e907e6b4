// fem/serial_openmp_regions.hpp: while the guard lives, a parallel region that asks for a
// team of 4 (as Debian's CHOLMOD does, CHOLMOD_OMP_NUM_THREADS) runs on the calling thread;
// other threads keep their teams, and the thread's own setting comes back afterwards.
// Source: the OpenMP 5.1 specification, max-active-levels-var (a region is active only below
// that many active levels; the ICV belongs to the thread's data environment).
#include "fem/serial_openmp_regions.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <thread>

namespace {

int team_asked_of_four() {
  int size = 0;
#pragma omp parallel num_threads(4)
  {
#pragma omp single
    size = omp_get_num_threads();
  }
  return size;
}

TEST(SerialOpenMpRegions, ATeamOfFourRunsOnTheCallingThreadWhileOtherThreadsKeepTheirs) {
  ASSERT_EQ(team_asked_of_four(), 4) << "OMP_THREAD_LIMIT or OMP_DYNAMIC set? (a team of 4 is expected)";
  {
    const flapsim::fem::SerialOpenMpRegions serial;
    EXPECT_EQ(team_asked_of_four(), 1);
    int other_thread = 0;
    std::thread t([&] { other_thread = team_asked_of_four(); });
    t.join();
    EXPECT_EQ(other_thread, 4);
  }
  EXPECT_EQ(team_asked_of_four(), 4);
}

}  // namespace
