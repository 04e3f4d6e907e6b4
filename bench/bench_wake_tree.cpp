// Cost of the wake's induced velocity: the direct sum (O(N²) per step) against the tree
// code (uvlm/segment_tree.hpp, O(N log N)).
// BM_WakeVelocity: a hover-like wake of 5, 10 and 20 cycles (100 rows per cycle, 10
//   spanwise panels: about 2100 segments and 1100 nodes per cycle), the wake's velocity at
//   all its nodes. The wake is synthetic (uvlm/synthetic_hover_wake.hpp, the same as the
//   tree's 20-cycle test; short segments) so that the big wakes need no simulation first.
// BM_BenchHoverWake: the computed free wake of cases/bench_hover.toml after its 3 cycles
//   (6289 segments, 3300 nodes, stretched: median segment 28 mm against a 48 mm span),
//   rebuilt deterministically by running the case's coupled loop once (about 3 CPU s), the
//   wake's velocity at all its nodes: direct sum in double and single precision (what
//   the run uses) and the tree at tolerance 1e-3, 1e-4, 1e-5.
// BM_PeriodicFarWake: cases/hover_periodic.toml after its 20 cycles (run once, about
//   15 CPU s): the far wake's velocity at the free (young) wake's nodes, the sum the tree
//   does every step of that case, by the direct sum and by the tree (1e-3, the case's).
// BM_TreeAccuracy: the tree's relative error against the direct sum on both computed
//   wakes for p = 3, 4 and θ = 0.2 … 0.5 (the measurement behind tree_parameters).
// Counters: segments, targets, and for the tree the pieces, multipole evaluations, direct
// point–piece pairs and core corrections per evaluation. CPU column: the measuring
// thread's CPU time; FLAPSIM_KERNEL=avx2 measures the AVX2 kernels on an AVX-512 machine.
#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/fsi/coupled_step.hpp"
#include "pipeline/io/case_file.hpp"
#include "uvlm/biot_savart.hpp"
#include "uvlm/segment_tree.hpp"
#include "uvlm/synthetic_hover_wake.hpp"
#include "uvlm/vortex_lattice.hpp"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

using namespace flapsim;
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

/// A case's segments and targets at the end of its run.
struct ComputedWake {
  SegmentSet segments;
  PointSet targets;
  VortexCore core;
  double tolerance = 1e-3;
};

/// Run the case's coupled loop (as flapsim run, without output) and keep its wake:
/// `far` false: all wake segments (bench_hover sums them all), targets all wake nodes;
/// `far` true: the far wake's segments at the free wake's nodes (moved back by the far
/// wake's displacement since the tree was built, as uvlm/wake.cpp does).
ComputedWake run_case_wake(const std::string& name, bool far) {
  const io::Case c = io::load_case_file(std::string(FLAPSIM_SOURCE_DIR) + "/cases/" + name + ".toml");
  const app::FsiSetup s = app::build_fsi_setup(c, {});
  fsi::FsiData data(s.model);
  fsi::initialize(s.model, data, 0.0);
  for (std::int64_t k = 0; k < s.steps; ++k) {
    fsi::coupled_step(s.model, data, s.dt);
    fsi::shed_wake(s.model, data);
  }
  const VortexLatticeData& d = *data.lattice;
  const VortexLatticeModel& m = s.model.lattice;
  ComputedWake w;
  w.core = m.core;
  w.tolerance = m.tree_tolerance;
  const SegmentSet& from = far ? d.far_wake_segments : d.wake_segments;
  w.segments.reserve(from.size());
  for (std::size_t k = 0; k < from.size(); ++k)
    w.segments.push(from.ax()[k], from.ay()[k], from.az()[k], from.bx()[k], from.by()[k], from.bz()[k],
                    from.gamma()[k], from.core_ratio2()[k]);
  const std::size_t n1 = static_cast<std::size_t>(m.spanwise + 1);
  const std::size_t first = far ? static_cast<std::size_t>(d.far_tree_rows) * n1 : 0;
  const std::size_t n = d.wake_nodes.size - first;
  w.targets.reserve(n);
  w.targets.size = n;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d p = d.wake_nodes.position(first + i) - (far ? d.far_tree_shift : Eigen::Vector3d::Zero());
    w.targets.set(i, p);
  }
  return w;
}

const ComputedWake& bench_hover_wake() {
  static const ComputedWake w = run_case_wake("bench_hover", false);
  return w;
}

const ComputedWake& periodic_far_wake() {
  static const ComputedWake w = run_case_wake("hover_periodic", true);
  return w;
}

/// kind: 0 direct (double), 1 direct (single precision), 2 the tree's evaluation at
/// tolerance range(1) (1e-3, 1e-4, 1e-5 for 3, 4, 5; 0: the case's), built once before,
/// 3 the tree's build alone (serial); range(2) = 1: segments cut into pieces (the
/// default), 0: not cut. A step of a free wake summed by the tree costs build +
/// evaluation; the far wake's tree is built every 10th step only (uvlm/wake.cpp).
void wake_sum(benchmark::State& state, const ComputedWake& cw, int kind) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  ComputedWake w = cw;  // own copy (the single-precision arrays)
  const double tolerance = state.range(1) > 0 ? std::pow(10.0, -static_cast<double>(state.range(1))) : w.tolerance;
  TreeParameters parameters = tree_parameters(tolerance);
  if (state.range(2) == 0) parameters.piece_length = 1e9;  // no pieces: the segments as they are
  SegmentTree t;
  t.reserve(w.segments.size());
  if (kind == 1) w.segments.update_single_precision();
  PointSet& p = w.targets;
  if (kind == 2) t.build(w.segments, w.core, parameters);
  for (auto _ : state) {
    p.zero_velocity();
    if (kind == 0) {
      add_induced_velocity(w.segments, p, w.core);
    } else if (kind == 1) {
      add_induced_velocity_single(w.segments, p, w.core);
    } else if (kind == 2) {
      t.add_induced_velocity(p.x.data(), p.y.data(), p.z.data(), p.size, p.u.data(), p.v.data(), p.w.data());
    } else {
      t.build(w.segments, w.core, parameters);
    }
    benchmark::DoNotOptimize(p.u.data());
  }
  state.counters["segments"] = static_cast<double>(w.segments.size());
  state.counters["targets"] = static_cast<double>(p.size);
  if (kind >= 2) {
    state.counters["pieces"] = static_cast<double>(t.pieces());
    state.counters["piece_mm"] = 1e3 * t.piece_length();
    state.counters["multipoles"] = static_cast<double>(t.last_multipole_evaluations());
    state.counters["direct_pairs"] = static_cast<double>(t.last_direct_interactions());
    state.counters["corrections"] = static_cast<double>(t.last_core_corrections());
  }
}

void BM_BenchHoverWake(benchmark::State& state, int kind) { wake_sum(state, bench_hover_wake(), kind); }
void BM_PeriodicFarWake(benchmark::State& state, int kind) { wake_sum(state, periodic_far_wake(), kind); }

BENCHMARK_CAPTURE(BM_WakeVelocity, Direct, false)
    ->ArgsProduct({{5, 10, 20}, {1, 2}})->ArgNames({"cycles", "threads"})->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_WakeVelocity, Tree, true)
    ->ArgsProduct({{5, 10, 20}, {1, 2}})->ArgNames({"cycles", "threads"})->UseRealTime()->Unit(benchmark::kMillisecond);

BENCHMARK_CAPTURE(BM_BenchHoverWake, Direct, 0)
    ->ArgsProduct({{1, 2}, {0}, {1}})->ArgNames({"threads", "tol", "pieces"})->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_BenchHoverWake, DirectSingle, 1)
    ->ArgsProduct({{1, 2}, {0}, {1}})->ArgNames({"threads", "tol", "pieces"})->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_BenchHoverWake, Tree, 2)
    ->ArgsProduct({{1, 2}, {3, 4, 5}, {0, 1}})->ArgNames({"threads", "tol", "pieces"})->UseRealTime()->Unit(benchmark::kMillisecond);

BENCHMARK_CAPTURE(BM_BenchHoverWake, TreeBuild, 3)
    ->ArgsProduct({{1}, {3, 4, 5}, {0, 1}})->ArgNames({"threads", "tol", "pieces"})->UseRealTime()->Unit(benchmark::kMillisecond);

BENCHMARK_CAPTURE(BM_PeriodicFarWake, Direct, 0)
    ->ArgsProduct({{1, 2}, {0}, {1}})->ArgNames({"threads", "tol", "pieces"})->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PeriodicFarWake, Tree, 2)
    ->ArgsProduct({{1, 2}, {3, 4, 5}, {0, 1}})->ArgNames({"threads", "tol", "pieces"})->UseRealTime()->Unit(benchmark::kMillisecond);

BENCHMARK_CAPTURE(BM_PeriodicFarWake, TreeBuild, 3)
    ->ArgsProduct({{1}, {3, 4, 5}, {0, 1}})->ArgNames({"threads", "tol", "pieces"})->UseRealTime()->Unit(benchmark::kMillisecond);

/// The tree's accuracy against (p, θ) (how tree_parameters' table was measured): relative
/// L2 error of the velocities against the direct sum (double), segments cut into pieces.
/// range(0): 0 the bench_hover wake, 1 the 20-cycle far wake; range(1) p; range(2) 100 θ.
void BM_TreeAccuracy(benchmark::State& state) {
  const ComputedWake& cw = state.range(0) ? periodic_far_wake() : bench_hover_wake();
  ComputedWake w = cw;
  PointSet& p = w.targets;
  p.zero_velocity();
  add_induced_velocity(w.segments, p, w.core);
  const std::vector<double> ru = p.u, rv = p.v, rw = p.w;
  SegmentTree t;
  t.reserve(w.segments.size());
  TreeParameters tp{static_cast<int>(state.range(1)), 0.01 * static_cast<double>(state.range(2)), 1e-4, 0.0};
  for (auto _ : state) {
    p.zero_velocity();
    t.build(w.segments, w.core, tp);
    t.add_induced_velocity(p.x.data(), p.y.data(), p.z.data(), p.size, p.u.data(), p.v.data(), p.w.data());
  }
  double e = 0, r = 0;
  for (std::size_t i = 0; i < p.size; ++i) {
    e += std::pow(p.u[i] - ru[i], 2) + std::pow(p.v[i] - rv[i], 2) + std::pow(p.w[i] - rw[i], 2);
    r += ru[i] * ru[i] + rv[i] * rv[i] + rw[i] * rw[i];
  }
  state.counters["error"] = std::sqrt(e / r);
  state.counters["multipoles"] = static_cast<double>(t.last_multipole_evaluations());
  state.counters["direct_pairs"] = static_cast<double>(t.last_direct_interactions());
}

}  // namespace

BENCHMARK(BM_TreeAccuracy)
    ->ArgsProduct({{0, 1}, {3, 4}, {20, 30, 35, 40, 45, 50}})->ArgNames({"far_wake", "p", "theta_pct"})
    ->Iterations(1)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
