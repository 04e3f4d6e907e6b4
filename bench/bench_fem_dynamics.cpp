// The wing's geometrically nonlinear FEM as the structure of a coupled run
// (pipeline/fsi/fem_structure.hpp, fem/nonlinear_dynamics.hpp), on the default meshes of
// wings/hawkmoth.toml and wings/mav_film_wing_25um.toml, flapped by the kinematics of
// cases/hover_flexible.toml (26.1 Hz, 100 steps per cycle; the coupled hawkmoth runs
// cases/hover_flexible_fem.toml, the same with its coupling keys) and
// cases/mav_film_wing_25um_fem.toml (12 Hz, 100 steps per cycle since 2 Dec; 80 before).
//  * *StructureStep: one structure step in vacuum (solve + accept), each benchmark
//    iteration the next step of the flapping cycle.
//  * *CoupledCycle: one whole cycle of the coupled run in air (the vortex lattice of the case,
//    strongly coupled): the issue-28 target is a hawkmoth cycle under 20 s with 2 threads.
// Counters: Newton iterations, factorisations and structure solves per step. A run whose
// structure fails is reported as an error (the 25 um film wing, docs/fem.md).
// Targets and the measured numbers: docs/fem.md, "Geometrically nonlinear FEM".
#include <benchmark/benchmark.h>

#include <Eigen/CholmodSupport>

#include <chrono>
#include <exception>
#include <memory>
#include <string>

#include "fem/constraints.hpp"
#include "fem/dense_kernels.hpp"
#include "fem/separated_cholesky.hpp"
#include "fem/serial_openmp_regions.hpp"
#include "fem/wing_fem.hpp"
#include "mbd/wing_kinematics.hpp"
#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/fsi/coupled_step.hpp"
#include "pipeline/fsi/fem_structure.hpp"
#include "pipeline/io/case_file.hpp"
#include "uvlm/planform_grid.hpp"
#include "wings/loader/planform_geometry.hpp"
#include "wings/loader/wing_file.hpp"

namespace {

using namespace flapsim;

struct Setup {
  wings::Wing wing;
  io::Case flight;
  std::shared_ptr<fsi::FemStructureModel> structure;
  fsi::FsiModel model;
};

// The wing's default FEM with its clamp driven by the case's kinematics, and (air) the
// case's lattice on it, as `flapsim run` sets up a case (pipeline/app/fsi_setup.cpp).
// legacy: the solver as it was before the speed work (docs/fem.md): a new consistent tangent
// and its sparse LU every iteration, Newton started at q_n.
std::unique_ptr<Setup> make_setup(const std::string& wing_file, const std::string& case_file, bool air,
                                  bool legacy = false, double refactor_rate = 0.25) {
  auto s = std::make_unique<Setup>();
  s->wing = wings::load_wing_file(FLAPSIM_SOURCE_DIR "/" + wing_file);
  s->flight = io::load_case_file(FLAPSIM_SOURCE_DIR "/" + case_file);
  const io::Case& c = s->flight;
  fem::WingFem wf = fem::build_wing_fem(s->wing);
  std::vector<int> clamp = fem::nodes_at_or_below_y(wf.model.mesh, s->wing.clamp_y);
  const wings::PlanformProperties p = wings::planform_properties(s->wing.outline);
  uvlm::PlanformGridOptions g;
  g.chordwise = c.numerics.chordwise_panels;
  g.spanwise = c.numerics.spanwise_panels;
  const uvlm::PlanformGrid grid = uvlm::make_planform_grid(s->wing.outline, g);
  fem::DynamicsOptions opt;
  // The case's ρ∞, 0.9 where it leaves the key out: these benchmarks' recorded figures
  // (docs/fem.md, "Cost") are 0.9's; a run's FEM takes 0.5 there since 5 Dec
  // (app::kFemRhoInfinity), which moved the hover's sub-iterations by −3 %.
  opt.rho_infinity = c.numerics.rho_infinity;
  opt.linearised_geometric_force = c.structure.fem_linearised_geometric_terms;
  opt.refactor_rate = refactor_rate;
  opt = fsi::coupled_dynamics_options(opt, c.numerics.coupling_tolerance, c.numerics.steps_per_cycle);
  if (legacy) {
    opt.tangent = fem::TangentForm::Consistent;
    opt.reuse_factorization = false;
    opt.rigid_predictor = false;
  }
  s->structure = std::make_shared<fsi::FemStructureModel>(
      std::move(wf.model), std::move(clamp), mbd::make_base_motion(c.kinematics), opt,
      air ? grid.nodes : Eigen::Matrix3Xd(3, 0), g.chordwise, g.spanwise, p.span);
  fsi::FsiModel& m = s->model;
  m.structure = s->structure;
  m.frequency = c.kinematics.frequency;
  m.coupling.max_iterations = c.numerics.max_coupling_iterations;
  m.coupling.tolerance = c.numerics.coupling_tolerance;
  m.coupling.method = c.numerics.coupling == io::CouplingMethod::InterfaceQuasiNewton
                          ? fsi::CouplingMethod::InterfaceQuasiNewton
                          : fsi::CouplingMethod::Aitken;
  m.coupling.reuse_steps = c.numerics.coupling_reuse_steps;
  m.coupling.added_mass = c.numerics.added_mass;
  m.air = air;
  m.density = c.air.density;
  if (air) {
    uvlm::VortexLatticeModel& l = m.lattice;
    l.chordwise = g.chordwise;
    l.spanwise = g.spanwise;
    l.core.model = c.numerics.core_model;
    l.core.radius = c.numerics.core_radius * p.mean_chord;
    l.wake_model = c.numerics.free_wake ? uvlm::WakeModel::Free : uvlm::WakeModel::Prescribed;
    l.load_method = c.numerics.load_method;
    l.leading_edge = c.numerics.leading_edge;
    l.wake_capacity = c.numerics.steps_per_cycle * c.numerics.cycles;
    l.far_wake_age = c.numerics.far_wake_cycles / c.kinematics.frequency;
    if (l.far_wake_age > 0.0) l.far_wake_disk_area = app::stroke_disk_area(c.kinematics, p.span);
    l.wake_sum = c.numerics.wake_sum;
    l.tree_tolerance = c.numerics.tree_tolerance;
  }
  return s;
}

void set_counters(benchmark::State& state, const fsi::FemStructureData& d, long steps, long solves) {
  const fem::SolverCounters& k = d.dynamics().counters();
  state.counters["newton_per_step"] = static_cast<double>(k.iterations) / static_cast<double>(steps);
  state.counters["factor_per_step"] = static_cast<double>(k.factorizations) / static_cast<double>(steps);
  state.counters["solves_per_step"] = static_cast<double>(solves) / static_cast<double>(steps);
  state.counters["dofs"] = d.dynamics().velocity.size();
}

void structure_step(benchmark::State& state, const std::string& wing, const std::string& flight,
                    bool legacy = false) {
  const double rate = state.range(0) > 0 ? 0.01 * static_cast<double>(state.range(0)) : 0.25;
  const auto s = make_setup(wing, flight, false, legacy, rate);
  const double dt = 1.0 / (s->flight.kinematics.frequency * s->flight.numerics.steps_per_cycle);
  auto d = s->structure->make_data();
  d->initialize(0.0);
  long steps = 0;
  for (auto _ : state) {
    d->set_external_loads(d->time() + dt);
    try {
      d->solve(dt);
    } catch (const fsi::StructureFailure& e) {
      state.SkipWithError(e.what());
      break;
    }
    d->accept();
    ++steps;
  }
  if (steps == 0) return;
  set_counters(state, static_cast<const fsi::FemStructureData&>(*d), steps, steps);
}

// steps: how many coupled steps from the start (0: one whole cycle); loose: the coupling's
// intermediate structure solves to 1 % of its change (CouplingSettings::loose_intermediate_solves).
void coupled_cycle(benchmark::State& state, const std::string& wing, const std::string& flight, int steps_run = 0,
                   bool loose = true, int untimed_cycles = 0) {
  const auto s = make_setup(wing, flight, true);
  s->model.coupling.loose_intermediate_solves = loose;
  const int n = steps_run > 0 ? steps_run : s->flight.numerics.steps_per_cycle;
  const double dt = 1.0 / (s->flight.kinematics.frequency * n);
  long steps = 0, solves = 0;
  std::unique_ptr<fsi::FsiData> d;
  for (auto _ : state) {
    d = std::make_unique<fsi::FsiData>(s->model);
    fsi::initialize(s->model, *d, 0.0);
    try {
      state.PauseTiming();  // the cycles before the one measured
      for (int k = 0; k < untimed_cycles * n; ++k) {
        fsi::coupled_step(s->model, *d, dt);
        fsi::shed_wake(s->model, *d);
      }
      state.ResumeTiming();
      for (int k = 0; k < n; ++k) {
        fsi::coupled_step(s->model, *d, dt);
        fsi::shed_wake(s->model, *d);
      }
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      return;
    }
    steps += n;
    solves += d->total_iterations;
  }
  // (Counters over every step run, the untimed cycles' too.)
  const int all = (untimed_cycles + 1) * n;
  set_counters(state, static_cast<const fsi::FemStructureData&>(*d->structure), all,
               d->total_iterations + d->accuracy_solves + all);
  state.counters["lattice_per_step"] = static_cast<double>(d->total_iterations) / all;
  state.counters["split_steps"] = static_cast<double>(d->structure->split_steps());
  state.counters["mean_s_per_step"] =
      benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// The Newton matrix c_M M + K_T of the hawkmoth's default FEM at rest in its reference state
// (100 steps per cycle), with the model it was assembled from.
struct HawkmothNewtonMatrix {
  std::unique_ptr<Setup> setup = make_setup("wings/hawkmoth.toml", "cases/hover_flexible.toml", false);
  fem::NonlinearAssembler assembler{setup->structure->corotational, setup->structure->dynamics.eliminated};
  HawkmothNewtonMatrix() {
    const fsi::FemStructureModel& m = *setup->structure;
    Eigen::VectorXd f(m.corotational.num_dofs());
    const double h = 1.0 / (setup->flight.kinematics.frequency * setup->flight.numerics.steps_per_cycle);
    fem::TangentExtras ex;
    ex.mass_scale = (1.0 - m.dynamics.alpha_m) / ((1.0 - m.dynamics.alpha_f) * m.dynamics.beta * h * h);
    assembler.evaluate(fem::reference_state(m.corotational), f, true, ex);
  }
  const fem::SparseMatrix& matrix() const { return assembler.tangent(); }
};

// The Newton matrix of the hawkmoth's default FEM (HawkmothNewtonMatrix): CHOLMOD's supernodal LLᵀ with the fill-reducing ordering
// range(0) (0: CHOLMOD's default choice, 1: AMD, 2: METIS, 3: NESDIS); each iteration one
// numeric factorisation and one solve. Counters: nonzeros of L and flops of a factorisation;
// label: the variant of the dense kernels under it (fem/dense_kernels.hpp; FLAPSIM_KERNEL=
// scalar measures SSE2 on an AVX2 machine).
void BM_HawkmothNewtonMatrixFactorisation(benchmark::State& state) {
  HawkmothNewtonMatrix newton;
  const fem::NonlinearAssembler& assembler = newton.assembler;
  Eigen::CholmodSupernodalLLT<fem::SparseMatrix, Eigen::Lower> llt;
  const int ordering[] = {0, CHOLMOD_AMD, CHOLMOD_METIS, CHOLMOD_NESDIS};
  if (state.range(0) > 0) {
    llt.cholmod().nmethods = 1;
    llt.cholmod().method[0].ordering = ordering[state.range(0)];
    llt.cholmod().postorder = 1;
  }
  llt.analyzePattern(assembler.tangent());
  const Eigen::VectorXd r = Eigen::VectorXd::Ones(assembler.tangent().rows());
  Eigen::VectorXd x;
  for (auto _ : state) {
    const fem::SerialOpenMpRegions serial;  // as fem/newton_matrix.cpp calls CHOLMOD
    llt.factorize(assembler.tangent());
    x = llt.solve(r);
    benchmark::DoNotOptimize(x.data());
  }
  state.counters["lnz"] = llt.cholmod().lnz;
  state.counters["flops"] = llt.cholmod().fl;
  state.counters["ordering"] = llt.cholmod().selected >= 0 ? llt.cholmod().method[llt.cholmod().selected].ordering : -1;
  state.SetLabel(std::string(fem::dense::variant_name()));
}

// The same Newton matrix factorised in two parts and their separator, one part a thread
// (fem/separated_cholesky.hpp): factorisation and one solve, then one solve alone.
void BM_HawkmothSeparatedNewtonMatrix(benchmark::State& state) {
  HawkmothNewtonMatrix newton;
  const fem::NonlinearAssembler& assembler = newton.assembler;
  fem::SeparatedCholesky split;
  const auto analysis_start = std::chrono::steady_clock::now();
  const bool analysed = split.analyse(assembler.tangent());
  state.counters["analysis_ms"] = 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - analysis_start).count();
  if (!analysed) {
    state.SkipWithError("no separator");
    return;
  }
  const Eigen::VectorXd r = Eigen::VectorXd::Ones(assembler.tangent().rows());
  Eigen::VectorXd x;
  struct Threads {  // range(0) threads while it lives; then the next benchmarks' as configured
    int saved = omp_get_max_threads();
    explicit Threads(int n) { omp_set_num_threads(n); }
    ~Threads() { omp_set_num_threads(saved); }
  } threads(static_cast<int>(state.range(0)));
  const bool solve_alone = state.range(1) == 1;
  if (solve_alone && !split.factorize(assembler.tangent())) {
    state.SkipWithError("not positive definite");
    return;
  }
  for (auto _ : state) {
    if (!solve_alone && !split.factorize(assembler.tangent())) {
      state.SkipWithError("not positive definite");
      return;
    }
    split.solve(r, x);
    benchmark::DoNotOptimize(x.data());
  }
  const fem::SparseMatrix& a = assembler.tangent();
  const Eigen::VectorXd ax = a.selfadjointView<Eigen::Lower>() * x;
  state.counters["residual"] = (ax - r).norm() / r.norm();
  {
    const fem::SerialOpenMpRegions serial;
    Eigen::CholmodSupernodalLLT<fem::SparseMatrix, Eigen::Lower> llt(a);
    const Eigen::VectorXd xw = llt.solve(r);
    state.counters["whole_residual"] = (a.selfadjointView<Eigen::Lower>() * xw - r).norm() / r.norm();
    state.counters["difference"] = (x - xw).norm() / xw.norm();
  }
  state.counters["separator"] = split.separator_rows();
  state.counters["part0"] = split.part_rows(0);
  state.counters["part1"] = split.part_rows(1);
  state.counters["flops0"] = split.part_flops(0);
  state.counters["flops1"] = split.part_flops(1);
  state.counters["lnz"] = split.factor_nonzeros();
}

void BM_HawkmothFemStructureStep(benchmark::State& state) {
  structure_step(state, "wings/hawkmoth.toml", "cases/hover_flexible.toml");
}
void BM_HawkmothFemStructureStepLegacy(benchmark::State& state) {
  structure_step(state, "wings/hawkmoth.toml", "cases/hover_flexible.toml", true);
}
// The MAV's 25 µm film wing as cases/mav_film_wing_25um_fem.toml flies it (ρ∞ = 0), on the
// wing file's 2.5 mm mesh (make_setup meshes the wing file; the case itself runs on 3.5 mm:
// BM_CaseRun in bench_uvlm_run.cpp measures it as shipped).
void BM_FilmWingFemStructureStep(benchmark::State& state) {
  structure_step(state, "wings/mav_film_wing_25um.toml", "cases/mav_film_wing_25um_fem.toml");
}
// Argument: 1 loose intermediate structure solves (the default), 0 all at full accuracy.
void BM_HawkmothFemCoupledCycle(benchmark::State& state) {
  coupled_cycle(state, "wings/hawkmoth.toml", "cases/hover_flexible_fem.toml", 0, state.range(0) != 0);
}
// The hover's second wingbeat (the first run untimed): a cycle of the periodic hover, the
// issue-28 target of 20 s with 2 threads (the first from rest costs more: its transient).
void BM_HawkmothFemCoupledSecondCycle(benchmark::State& state) {
  coupled_cycle(state, "wings/hawkmoth.toml", "cases/hover_flexible_fem.toml", 0, true, 1);
}
// The first state.range(0) coupled steps of the hawkmoth's hover (a short, representative
// part of the cycle for profiling: the start of the downstroke).
void BM_HawkmothFemCoupledSteps(benchmark::State& state) {
  coupled_cycle(state, "wings/hawkmoth.toml", "cases/hover_flexible.toml", static_cast<int>(state.range(0)));
}
// One wingbeat of the MAV film wing on the wing file's 2.5 mm mesh (above).
void BM_FilmWingFemCoupledCycle(benchmark::State& state) {
  coupled_cycle(state, "wings/mav_film_wing_25um.toml", "cases/mav_film_wing_25um_fem.toml");
}
// One wingbeat of the shipped 25 µm film wing case (ρ∞ = 0, steps split as they fail:
// docs/fsi.md, "Film wings"); the bound is 5 wingbeats in 3 minutes.
void BM_FilmWing75mmFemCoupledCycle(benchmark::State& state) {
  coupled_cycle(state, "wings/film_wing_75mm_25um.toml", "cases/film_wing_fem.toml");
}

BENCHMARK(BM_HawkmothNewtonMatrixFactorisation)->DenseRange(0, 3)->Iterations(3)->Unit(benchmark::kMillisecond);
// Arguments: threads; 0 factorisation and solve, 1 solve alone.
BENCHMARK(BM_HawkmothSeparatedNewtonMatrix)->Args({1, 0})->Args({2, 0})->Args({1, 1})->Args({2, 1})->Iterations(5)->Unit(benchmark::kMillisecond)->UseRealTime();
// 100 (hawkmoth) and 80 (film wing) structure steps: one cycle each.
// Argument: DynamicsOptions::refactor_rate in percent.
BENCHMARK(BM_HawkmothFemStructureStep)->Arg(25)->Arg(60)->Iterations(100)->Unit(benchmark::kMillisecond)->UseRealTime();
// The legacy solver: the first 3 steps only (seconds each).
BENCHMARK(BM_HawkmothFemStructureStepLegacy)->Arg(0)->Iterations(3)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_FilmWingFemStructureStep)->Arg(25)->Iterations(80)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_HawkmothFemCoupledCycle)->Arg(1)->Arg(0)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(BM_HawkmothFemCoupledSecondCycle)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(BM_HawkmothFemCoupledSteps)->Arg(10)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(BM_FilmWingFemCoupledCycle)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(BM_FilmWing75mmFemCoupledCycle)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
