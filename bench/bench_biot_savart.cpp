// Throughput of the Biot–Savart kernel: point–segment interactions per second, on a
// wake-sized problem (6000 segments, 3300 target points), one and two threads, in double
// precision and in the single precision the free-wake convection uses, for each kernel
// variant this CPU runs (uvlm/kernel_dispatch.hpp: scalar, avx2, avx512).
// BM_WakeLattice: a 3-cycle hover-like wake (uvlm/synthetic_hover_wake.hpp: 301 node rows ×
// 11 nodes, 6311 segments, cores grown with age; about the size of cases/bench_hover.toml's
// wake after its 300 steps) at its own 3311 nodes, by the segment kernel (biot_savart.hpp)
// and by the lattice kernel (lattice_segments.hpp), one thread; interactions = target
// nodes × segments.
// Counters: interactions/s and per_core/s by wall time; per_cpu_s by the process's CPU
// time (all threads), the figure to read on a shared machine, where wall time includes
// waiting for a core.
#include "uvlm/biot_savart.hpp"
#include "uvlm/kernel_dispatch.hpp"
#include "uvlm/lattice_segments.hpp"
#include "uvlm/synthetic_hover_wake.hpp"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <ctime>
#include <random>
#include <string>

using namespace flapsim::uvlm;

namespace {

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void BM_BiotSavart(benchmark::State& state, CoreModel model, bool single) {
  const int threads = static_cast<int>(state.range(0));
  const auto isa = static_cast<KernelIsa>(state.range(1));
  if (!kernel_isa_supported(isa)) {
    state.SkipWithError("kernel variant not supported by this CPU");
    return;
  }
  set_kernel_isa(isa);
  state.SetLabel(std::string(kernel_isa_name(isa)));
  const std::size_t n_seg = 6000, n_pts = 3300;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0.0, 0.05);
  SegmentSet s;
  s.reserve(n_seg);
  for (std::size_t k = 0; k < n_seg; ++k) s.push(u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), 1e-3);
  PointSet p;
  p.reserve(n_pts);
  p.size = n_pts;
  for (std::size_t i = 0; i < n_pts; ++i) p.set(i, {u(rng), u(rng), u(rng)});
  const VortexCore core{model, 1e-3};
  s.update_single_precision();
  omp_set_num_threads(threads);
  const double cpu0 = process_cpu_seconds();
  for (auto _ : state) {
    p.zero_velocity();
    if (single)
      add_induced_velocity_single(s, p, core);  // the free-wake convection's kernel
    else
      add_induced_velocity(s, p, core);
    benchmark::DoNotOptimize(p.u.data());
    benchmark::ClobberMemory();
  }
  const double cpu = process_cpu_seconds() - cpu0;
  const double interactions = static_cast<double>(n_seg) * n_pts;
  state.counters["per_cpu_s"] = interactions * static_cast<double>(state.iterations()) / cpu;
  state.counters["interactions/s"] =
      benchmark::Counter(interactions * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["per_core/s"] =
      benchmark::Counter(interactions * state.iterations() / threads, benchmark::Counter::kIsRate);
}

/// The wake's velocity at its own nodes; range(0): 0 segment kernel, 1 lattice kernel.
void BM_WakeLattice(benchmark::State& state, bool single) {
  const bool lattice = state.range(0) == 1;
  const auto isa = static_cast<KernelIsa>(state.range(1));
  if (!kernel_isa_supported(isa)) {
    state.SkipWithError("kernel variant not supported by this CPU");
    return;
  }
  set_kernel_isa(isa);
  state.SetLabel(std::string(lattice ? "lattice " : "segments ") + std::string(kernel_isa_name(isa)));
  static const SyntheticHoverWake wake(3);
  PointSet p = wake.nodes;
  omp_set_num_threads(1);
  const double cpu0 = process_cpu_seconds();
  for (auto _ : state) {
    p.zero_velocity();
    const double *x = p.x.data(), *y = p.y.data(), *z = p.z.data();
    double *u = p.u.data(), *v = p.v.data(), *w = p.w.data();
    if (lattice && single)
      add_induced_velocity_single(wake.lattice, x, y, z, p.size, u, v, w, wake.core);
    else if (lattice)
      add_induced_velocity(wake.lattice, x, y, z, p.size, u, v, w, wake.core);
    else if (single)
      add_induced_velocity_single(wake.segments, x, y, z, p.size, u, v, w, wake.core);
    else
      add_induced_velocity(wake.segments, x, y, z, p.size, u, v, w, wake.core);
    benchmark::DoNotOptimize(p.u.data());
    benchmark::ClobberMemory();
  }
  const double cpu = process_cpu_seconds() - cpu0;
  const double interactions = static_cast<double>(wake.segments.size()) * static_cast<double>(p.size);
  state.counters["per_cpu_s"] = interactions * static_cast<double>(state.iterations()) / cpu;
}

}  // namespace

void LatticeArgs(benchmark::internal::Benchmark* b) {
  for (KernelIsa isa : {KernelIsa::Scalar, KernelIsa::Avx2, KernelIsa::Avx512})
    for (int lattice : {0, 1}) b->Args({lattice, static_cast<int>(isa)});
  b->ArgNames({"lattice", "isa"})->Unit(benchmark::kMillisecond);
}

void Args(benchmark::internal::Benchmark* b) {
  for (int threads : {1, 2})
    for (KernelIsa isa : {KernelIsa::Scalar, KernelIsa::Avx2, KernelIsa::Avx512})
      b->Args({threads, static_cast<int>(isa)});
  b->ArgNames({"threads", "isa"})->UseRealTime()->Unit(benchmark::kMillisecond);
}

BENCHMARK_CAPTURE(BM_BiotSavart, LambOseen, CoreModel::LambOseen, false)->Apply(Args);
BENCHMARK_CAPTURE(BM_BiotSavart, CutOff, CoreModel::CutOff, false)->Apply(Args);
BENCHMARK_CAPTURE(BM_BiotSavart, Vatistas, CoreModel::Vatistas, false)->Apply(Args);
BENCHMARK_CAPTURE(BM_BiotSavart, LambOseenSingle, CoreModel::LambOseen, true)->Apply(Args);
BENCHMARK_CAPTURE(BM_BiotSavart, CutOffSingle, CoreModel::CutOff, true)->Apply(Args);

BENCHMARK_CAPTURE(BM_WakeLattice, LambOseen, false)->Apply(LatticeArgs);
BENCHMARK_CAPTURE(BM_WakeLattice, LambOseenSingle, true)->Apply(LatticeArgs);

BENCHMARK_MAIN();
