// FEM of the hawkmoth wing (wings/hawkmoth.toml): mesh (gmsh), assembly of K and
// M, and the 20 lowest modes of the root-clamped wing (CHOLMOD + Spectra).
// Target: the whole chain under 2 s wall time.
#include <benchmark/benchmark.h>

#include "fem/assembly.hpp"
#include "fem/modal_solver.hpp"
#include "fem/static_solver.hpp"
#include "fem/structural_model.hpp"
#include "fem/wing_mesher.hpp"
#include "wings/wing_file.hpp"

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

BENCHMARK(BM_HawkmothMesh)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HawkmothAssembly)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HawkmothStaticFactorisation)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HawkmothModes)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HawkmothMeshAssemblyAnd20Modes)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
