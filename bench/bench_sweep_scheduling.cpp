// What a sweep costs besides its cases (pipeline/app/sweep/): handing out cases to
// worker threads (case_scheduler.hpp, no MPI) and rewriting sweep.csv after a case
// (sweep_table.hpp), the two parts of the scheduling overhead per case on one machine.
// Over MPI a case adds one request/reply round trip to rank 0 (measured by the sweep
// itself: the last line `flapsim sweep` prints; docs/sweeps.md, "Measurements").
#include <benchmark/benchmark.h>

#include <filesystem>
#include <numeric>
#include <unistd.h>
#include <vector>

#include "pipeline/app/sweep/case_scheduler.hpp"
#include "pipeline/app/sweep/mpi_world.hpp"
#include "pipeline/app/sweep/sweep_table.hpp"

namespace {

using namespace flapsim;

// Cases that do nothing, over N threads: the cost of taking a case and reporting it.
void BM_ScheduleEmptyCases(benchmark::State& state) {
  const sweep::MpiWorld world;  // not launched by mpirun: one process, threads only
  std::vector<std::size_t> todo(1000);
  std::iota(todo.begin(), todo.end(), 0);
  std::size_t finished = 0;
  for (auto _ : state) {
    sweep::schedule_cases(
        world, todo, static_cast<int>(state.range(0)), [](std::size_t) {
          sweep::CaseOutcome outcome;
          outcome.status = "ok";
          return outcome;
        },
        [&](std::size_t, sweep::CaseOutcome&&) { ++finished; });
  }
  benchmark::DoNotOptimize(finished);
  state.SetItemsProcessed(state.iterations() * static_cast<long>(todo.size()));  // items = cases
}
BENCHMARK(BM_ScheduleEmptyCases)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMicrosecond);

// Rewriting sweep.csv (atomically) with N finished rows of one varied key.
void BM_RewriteSweepTable(benchmark::State& state) {
  const auto dir = std::filesystem::temp_directory_path() / ("flapsim_bench_sweep_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  std::vector<sweep::SweepRow> rows(static_cast<std::size_t>(state.range(0)));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    rows[i].point = {{"kinematics.rotation_phase", -0.2 + 1e-3 * static_cast<double>(i)}};
    rows[i].folder = "case_" + std::to_string(i);
    rows[i].done = true;
    rows[i].outcome.status = "ok";
    rows[i].outcome.host = "host";
    rows[i].outcome.results.set("mean_lift_N", 5.1e-3 + 1e-6 * static_cast<double>(i));
    rows[i].outcome.results.set("mean_CL", 1.8);
    rows[i].outcome.results.set("wall_time_s", 12.5);
  }
  for (auto _ : state) sweep::write_sweep_table(dir / "sweep.csv", {"kinematics.rotation_phase"}, rows);
  std::filesystem::remove_all(dir);
}
BENCHMARK(BM_RewriteSweepTable)->Arg(12)->Arg(100)->Arg(1000)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
