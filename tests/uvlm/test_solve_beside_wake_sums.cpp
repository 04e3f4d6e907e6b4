// The circulations solved while the other threads sum the wake at the loads' points
// (uvlm/lattice_internal.hpp alongside_target_chunks, vortex_lattice.cpp solve). Reference:
// the same run on one thread, where the solve and the sums run one after the other; each
// point's sums are the same operations in the same order, so the loads must agree bit for bit.
#include "hover_wake.hpp"

#include "uvlm/lattice_internal.hpp"
#include "uvlm/planform_grid.hpp"
#include "uvlm/vortex_lattice.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <atomic>
#include <stdexcept>
#include <vector>

using namespace flapsim::uvlm;

namespace {

/// omp_set_num_threads for one scope.
struct BesideThreads {
  explicit BesideThreads(int n) : before(omp_get_max_threads()) { omp_set_num_threads(n); }
  ~BesideThreads() { omp_set_num_threads(before); }
  int before;
};

/// Every step's force and the last step's panel forces of the hover wing at 12 × 20 panels
/// (the wake's sums at the 240 midpoints, 4 000 segments after 100 steps, are enough work
/// for threads), on `threads` threads.
struct BesideRun {
  std::vector<Eigen::Vector3d> total;
  Eigen::Matrix3Xd panel_force;
  LatticeSolverCounts counts;
};

BesideRun beside_run(int threads, LoadMethod loads) {
  const BesideThreads scope(threads);
  const flapsim::uvlm::testing::HoverWing wing;
  VortexLatticeModel m = wing.model(2);
  m.chordwise = 12;
  m.spanwise = 20;
  m.load_method = loads;
  PlanformGridOptions o;
  o.chordwise = 12;
  o.spanwise = 20;
  const PlanformGrid g = make_rectangular_grid(wing.chord, 4 * wing.chord, o);
  VortexLatticeData d(m);
  Eigen::Matrix3Xd x(3, m.nodes()), v(3, m.nodes());
  BesideRun r;
  for (int k = 0; k < 2 * wing.steps_per_cycle; ++k) {
    wing.pose(g, k * wing.dt(), x, v);
    solve(m, d, x, v, Eigen::Vector3d::Zero(), wing.dt(), 1.225);
    r.total.push_back(d.loads.total_force);
    advance(m, d);
  }
  r.panel_force = d.loads.force;
  r.counts = d.solver_counts;
  return r;
}

}  // namespace

TEST(AlongsideTargetChunks, RunsTheSoloOnceEveryTargetOnceAndRethrowsTheSolosException) {
  const std::size_t n = 1001;  // odd: a last chunk shorter than the others
  for (int threads : {1, 2}) {
    const BesideThreads scope(threads);
    std::vector<std::atomic<int>> seen(n);
    int solos = 0;
    auto count = [&](std::size_t i0, std::size_t c) {
      for (std::size_t i = i0; i < i0 + c; ++i) ++seen[i];
    };
    const bool team = detail::alongside_target_chunks(n, 10 * detail::kTargetChunkThreshold, [&] { ++solos; }, count);
    EXPECT_EQ(team, threads > 1);
    EXPECT_EQ(solos, 1);
    for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(seen[i].load(), 1) << "target " << i << ", " << threads << " threads";
    // A failing solo: its exception after the region, every target still summed once more.
    EXPECT_THROW(detail::alongside_target_chunks(n, 10 * detail::kTargetChunkThreshold,
                                                 [] { throw std::runtime_error("solo failed"); }, count),
                 std::runtime_error);
    for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(seen[i].load(), 2) << "target " << i << ", " << threads << " threads";
  }
}

TEST(SolveBesideWakeSums, TheLoadsAreTheOneThreadRunsBitForBitOnBothLoadRoutes) {
  for (LoadMethod loads : {LoadMethod::Bernoulli, LoadMethod::KuttaJoukowski}) {
    const BesideRun one = beside_run(1, loads), two = beside_run(2, loads);
    EXPECT_EQ(one.counts.beside_wake_sums, 0);
    // Every solve once the wake is long enough for threads (about 420 segments × 240 points).
    EXPECT_GT(two.counts.beside_wake_sums, 80);
    ASSERT_EQ(one.total.size(), two.total.size());
    for (std::size_t k = 0; k < one.total.size(); ++k)
      for (int c = 0; c < 3; ++c) ASSERT_EQ(one.total[k](c), two.total[k](c)) << "step " << k << ", component " << c;
    EXPECT_TRUE(one.panel_force == two.panel_force);
  }
}
