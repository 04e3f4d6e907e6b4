// FEM of the hawkmoth wing (wings/hawkmoth.toml): mesh (gmsh), assembly of K and
// M, and the 20 lowest modes of the root-clamped wing (CHOLMOD + Spectra).
// Target: the whole chain under 2 s wall time.
#include <benchmark/benchmark.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <string>
#include <unistd.h>

#include "fem/assembly.hpp"
#include "fem/modal_solver.hpp"
#include "fem/static_solver.hpp"
#include "fem/structural_model.hpp"
#include "fem/wing_mesher.hpp"
#include "pipeline/app/wing_modes_stage.hpp"
#include "pipeline/io/fem_vtk.hpp"
#include "wings/loader/wing_file.hpp"

namespace {

using namespace flapsim;

const wings::Wing& hawkmoth() {
  static const wings::Wing w = wings::load_wing_file(FLAPSIM_SOURCE_DIR "/wings/hawkmoth.toml");
  return w;
}

void BM_HawkmothMesh(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(fem::mesh_wing(hawkmoth()));
}

void BM_HawkmothAssembly(benchmark::State& state) {
  const fem::StructuralModel model = fem::wing_structural_model(hawkmoth(), fem::mesh_wing(hawkmoth()));
  for (auto _ : state) benchmark::DoNotOptimize(fem::assemble(model));
  state.counters["dofs"] = model.mesh.num_dofs();
}

void BM_HawkmothStaticFactorisation(benchmark::State& state) {
  const fem::StructuralModel model = fem::wing_structural_model(hawkmoth(), fem::mesh_wing(hawkmoth()));
  const fem::AssembledSystem sys = fem::assemble(model);
  const fem::Constraints c = fem::root_clamp(model.mesh, hawkmoth().clamp_y);
  for (auto _ : state) fem::StaticSolver s(sys.stiffness, c);
}

void BM_HawkmothModes(benchmark::State& state) {
  const fem::StructuralModel model = fem::wing_structural_model(hawkmoth(), fem::mesh_wing(hawkmoth()));
  const fem::AssembledSystem sys = fem::assemble(model);
  const fem::Constraints c = fem::root_clamp(model.mesh, hawkmoth().clamp_y);
  fem::ModalOptions opt;
  opt.num_modes = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(fem::solve_modes(sys.stiffness, sys.mass, c, opt));
}

// The whole chain, as `flapsim modes` runs it (without output files).
void BM_HawkmothMeshAssemblyAnd20Modes(benchmark::State& state) {
  fem::ModalOptions opt;
  opt.num_modes = 20;
  for (auto _ : state) {
    const fem::StructuralModel model = fem::wing_structural_model(hawkmoth(), fem::mesh_wing(hawkmoth()));
    const fem::AssembledSystem sys = fem::assemble(model);
    const fem::Constraints c = fem::root_clamp(model.mesh, hawkmoth().clamp_y);
    benchmark::DoNotOptimize(fem::solve_modes(sys.stiffness, sys.mass, c, opt));
  }
}

// `flapsim modes wings/hawkmoth.toml` in process, stage by stage (app::compute_wing_modes
// and the two output files): one counter per stage, its mean wall time [ms]; the total is
// the benchmark's real time. Argument: the threads (flapsim modes --threads).
void BM_HawkmothModesCommandStages(benchmark::State& state) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("flapsim_bench_modes." + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::map<std::string, double> total;
  std::vector<std::string> order;
  for (auto _ : state) {
    const app::WingModesStage r = app::compute_wing_modes(hawkmoth(), 20, 10, static_cast<int>(state.range(0)));
    const auto t0 = std::chrono::steady_clock::now();
    io::write_modes_csv(dir / "modes.csv", r.modes.modes, r.labels);
    io::write_fem_vtu(dir / "fem.vtu", r.fem.model.mesh, hawkmoth().clamp_y, r.modes.modes, r.labels, r.statics);
    auto stages = r.stage_seconds;
    stages.emplace_back("outputs", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    for (const auto& [name, sec] : stages) {
      if (!total.count(name)) order.push_back(name);
      total[name] += sec;
    }
  }
  std::filesystem::remove_all(dir);
  for (const auto& name : order)
    state.counters[name + "_ms"] = benchmark::Counter(1e3 * total[name] / static_cast<double>(state.iterations()));
}

BENCHMARK(BM_HawkmothModesCommandStages)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
BENCHMARK(BM_HawkmothMesh)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HawkmothAssembly)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HawkmothStaticFactorisation)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HawkmothModes)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HawkmothMeshAssemblyAnd20Modes)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
