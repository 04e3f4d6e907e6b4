// Cost of the wake's self-induced velocity against the wake's size: the direct sum
// (O(N²) per step) and the tree code (uvlm/segment_tree.hpp, O(N log N)) on a hover-like
// wake of 5, 10 and 20 cycles (100 rows per cycle, 10 spanwise panels: about 2100
// segments and 1100 nodes per cycle). The wake is synthetic — rows swept back and forth
// at 26.1 Hz, ±60°, sinking at 0.5 m/s, cores grown with age — so that the big wakes
// need no 20-cycle simulation first; the tree's accuracy on a computed hover wake is
// tests/uvlm/test_segment_tree.cpp.
#include "uvlm/biot_savart.hpp"
#include "uvlm/core_growth.hpp"
#include "uvlm/segment_tree.hpp"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>
#include <vector>

using namespace flapsim::uvlm;

namespace {

struct SyntheticWake {
  SegmentSet segments;
  PointSet nodes;
  VortexCore core{CoreModel::LambOseen, 0.2 * 0.0169};
  explicit SyntheticWake(int cycles) {
    const int rows = 100 * cycles, ns = 10, n1 = ns + 1;
    const double f = 26.1, dt = 1.0 / (100 * f);
    nodes.reserve(static_cast<std::size_t>(rows + 1) * n1);
    nodes.size = static_cast<std::size_t>(rows + 1) * n1;
    for (int r = 0; r <= rows; ++r) {
      const double age = (rows - r) * dt, psi = (60 * M_PI / 180) * std::cos(2 * M_PI * f * r * dt);
      for (int j = 0; j < n1; ++j) {
        const double rad = 0.005 + 0.0433 * j / ns;
        nodes.set(static_cast<std::size_t>(r) * n1 + j,
                  {rad * std::cos(psi), rad * std::sin(psi), -0.5 * age - 0.002 * std::sin(0.3 * j + r)});
      }
    }
    CoreGrowth growth;
    growth.enabled = true;
    segments.reserve(static_cast<std::size_t>(rows + 1) * ns + static_cast<std::size_t>(rows) * n1);
    auto gamma = [&](int r, int j) {
      if (r < 0 || r >= rows || j < 0 || j >= ns) return 0.0;
      return 0.02 * std::sin(M_PI * (j + 0.5) / ns) * std::sin(2 * M_PI * f * r * dt + 0.3);
    };
    auto push = [&](std::size_t a, std::size_t b, double g, double age) {
      const double rc2 = grown_core_radius2(growth, core.radius, age, g);
      segments.push(nodes.x[a], nodes.y[a], nodes.z[a], nodes.x[b], nodes.y[b], nodes.z[b], g,
                    core.radius * core.radius / rc2);
    };
    for (int q = 0; q <= rows; ++q)
      for (int j = 0; j < ns; ++j)
        push(static_cast<std::size_t>(q) * n1 + j, static_cast<std::size_t>(q) * n1 + j + 1,
             gamma(q, j) - gamma(q - 1, j), (rows - q) * dt);
    for (int r = 0; r < rows; ++r)
      for (int j = 0; j <= ns; ++j)
        push(static_cast<std::size_t>(r + 1) * n1 + j, static_cast<std::size_t>(r) * n1 + j,
             gamma(r, j) - gamma(r, j - 1), (rows - r - 0.5) * dt);
  }
};

void BM_WakeVelocity(benchmark::State& state, bool tree) {
  const int cycles = static_cast<int>(state.range(0));
  omp_set_num_threads(static_cast<int>(state.range(1)));
  SyntheticWake w(cycles);
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
