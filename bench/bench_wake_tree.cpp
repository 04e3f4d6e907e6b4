// Cost of the wake's self-induced velocity against the wake's size: the direct sum
// (O(N²) per step) and the tree code (uvlm/segment_tree.hpp, O(N log N)) on a hover-like
// wake of 5, 10 and 20 cycles (100 rows per cycle, 10 spanwise panels: about 2100
// segments and 1100 nodes per cycle). The wake is synthetic (uvlm/synthetic_hover_wake.hpp,
// the same as the tree's 20-cycle test) so that the big wakes need no 20-cycle simulation
// first; the tree's accuracy on a computed hover wake is tests/uvlm/test_segment_tree.cpp.
#include "uvlm/biot_savart.hpp"
#include "uvlm/segment_tree.hpp"
#include "uvlm/synthetic_hover_wake.hpp"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>
#include <vector>

using namespace flapsim::uvlm;

namespace {

void BM_WakeVelocity(benchmark::State& state, bool tree) {
  const int cycles = static_cast<int>(state.range(0));
  omp_set_num_threads(static_cast<int>(state.range(1)));
  SyntheticHoverWake w(cycles);
  SegmentTree t;
  t.reserve(w.segments.size());
  for (auto _ : state) {
    w.nodes.zero_velocity();
    if (tree) {
      t.build(w.segments, w.core, tree_parameters(1e-4));
      t.add_induced_velocity(w.nodes.x.data(), w.nodes.y.data(), w.nodes.z.data(), w.nodes.size,
                             w.nodes.u.data(), w.nodes.v.data(), w.nodes.w.data());
    } else {
      add_induced_velocity(w.segments, w.nodes, w.core);
    }
    benchmark::DoNotOptimize(w.nodes.u.data());
  }
  state.counters["segments"] = static_cast<double>(w.segments.size());
  state.counters["nodes"] = static_cast<double>(w.nodes.size);
  if (tree) {
    state.counters["multipoles"] = static_cast<double>(t.last_multipole_evaluations());
    state.counters["direct_pairs"] = static_cast<double>(t.last_direct_interactions());
  }
}

}  // namespace

BENCHMARK_CAPTURE(BM_WakeVelocity, Direct, false)
    ->ArgsProduct({{5, 10, 20}, {1, 2}})->ArgNames({"cycles", "threads"})->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_WakeVelocity, Tree, true)
    ->ArgsProduct({{5, 10, 20}, {1, 2}})->ArgNames({"cycles", "threads"})->UseRealTime()->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
