// flapsim optimize CASE.toml --vary KEY=LO:HI [--vary ...] --maximize RESULT
//   [--constraint RESULT>=X ...] -o DIR [--algorithm bobyqa|cobyla] [--max-evaluations N]
//   [--x-tolerance F] [--initial-step F] [--chain FILE] [--spring-scale S] [--vtk-every N]
//   [--force] [--quiet]
#include "pipeline/app/cli/commands.hpp"
#include "pipeline/app/cli/option_checks.hpp"
#include "pipeline/app/cli/wing_option.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "pipeline/app/interruption.hpp"
#include "pipeline/app/optimize/evaluation_table.hpp"
#include "pipeline/app/optimize/optimize_report.hpp"
#include "pipeline/app/optimize/optimizer.hpp"
#include "pipeline/app/run_results.hpp"
#include "pipeline/app/sweep/sweep_case.hpp"
#include "pipeline/io/case_file.hpp"
#include "pipeline/io/csv_writer.hpp"
#include "wings/loader/input_error.hpp"

namespace flapsim::cli {

namespace {

struct OptimizeArgs {
  std::string case_file, output_dir, chain_file, wing_file, maximize, algorithm;
  std::vector<std::string> vary, constraints;
  int max_evaluations = 50;
  int starts = 1;
  int vtk_every = 0;
  double x_tolerance = 1e-3;
  double initial_step = 0.25;
  double spring_scale = 1.0;
  bool force = false;
  bool quiet = false;
};

void optimize_command(const OptimizeArgs& a) {
  optimize::Problem problem;
  if (a.vary.empty()) throw InputError("", 0, "--vary", "give at least one key with its bounds, KEY=LO:HI");
  for (const std::string& v : a.vary) problem.bounds.push_back(optimize::parse_bound(v));
  problem.objective = optimize::parse_result(a.maximize, "--maximize");
  for (const std::string& c : a.constraints) problem.constraints.push_back(optimize::parse_constraint(c));
  check_chain_option(a.chain_file);
  wings::TomlTable case_root = wings::parse_toml_file(a.case_file);
  apply_wing_option(case_root, a.wing_file, a.chain_file);
  const io::Case base = print_case_warnings(io::read_case(case_root));
  warn_unused_structure_options(base, a.chain_file, a.spring_scale);

  optimize::OptimizeOptions options;
  options.output_dir = a.output_dir;
  options.chain_file = a.chain_file;
  options.wing_file = a.wing_file;
  options.spring_scale = a.spring_scale;
  options.vtk_every = a.vtk_every;
  options.force = a.force;
  options.quiet = a.quiet;
  if (a.algorithm == "bobyqa") options.algorithm = optimize::Algorithm::bobyqa;
  if (a.algorithm == "cobyla") options.algorithm = optimize::Algorithm::cobyla;
  options.starts = a.starts;
  options.search.max_evaluations = a.max_evaluations;
  options.search.x_tolerance = a.x_tolerance;
  options.search.initial_step = a.initial_step;
  app::install_interrupt_handlers();  // SIGINT/SIGTERM: the run under way finishes its step, exit 130/143
  const optimize::OptimizeReport report = optimize::run_optimization(a.case_file, problem, options);
  if (a.quiet || !report.root) return;
  const optimize::Evaluation& best = report.evaluations.at(*report.best);
  const std::string objective(app::kRunResults[problem.objective].key);
  std::printf("optimum: %s  %s = %.6g\n", sweep::describe(best.point).c_str(), objective.c_str(),
              optimize::result_value(best, problem.objective));
  if (const std::string notes = optimize::evaluation_notes(best); !notes.empty())
    std::fprintf(stderr, "flapsim: warning: the optimum's run was warned: %s. %s\n", notes.c_str(),
                 optimize::optimum_warning_advice(best).c_str());
  std::printf("%zu evaluations (%zu run, %zu kept), NLopt %s: %s; %d rank%s, %.1f s wall\n",
              report.evaluations.size(), report.runs, report.evaluations.size() - report.runs,
              optimize::algorithm_name(report.algorithm).c_str(), report.stop_reason.c_str(), report.ranks,
              report.ranks == 1 ? "" : "s", report.wall_s);
  const std::filesystem::path dir(a.output_dir);
  std::printf("case at the optimum: %s%s\nreport: %s\nevaluations: %s\n", report.optimum_case.string().c_str(),
              report.optimum_spring_scale != 1.0
                  ? (" (run with --spring-scale " + io::format_number(report.optimum_spring_scale) + ")").c_str()
                  : "",
              (dir / "report.md").string().c_str(), (dir / "evaluations.csv").string().c_str());
}

}  // namespace

void add_optimize_command(CLI::App& app) {
  auto args = std::make_shared<OptimizeArgs>();
  auto* cmd = app.add_subcommand(
      "optimize",
      "Find the values of a case's keys, within bounds, that maximise a result of the run, e.g.\n"
      "  flapsim optimize cases/rotation_phase_rigid.toml --vary kinematics.rotation_phase=-0.25:0.15 \\\n"
      "    --maximize mean_lift_N -o out/opt_phase\n"
      "KEY: as flapsim sweep --vary (a numeric case key, wing.<key>, spring_scale, KEY[i] an element\n"
      "of an array of numbers, from 0: 'kinematics.sweep.cos_deg[0]'); RESULT: a number\n"
      "of summary.json (run_results.hpp). NLopt searches from the case's own values: BOBYQA, or\n"
      "COBYLA with --constraint. Every evaluation is a run in DIR/runs/<inputs hash>/ and a row of\n"
      "DIR/evaluations.csv; run again, the points already evaluated are not run again. Writes\n"
      "DIR/optimum.toml (the case at the optimum, for flapsim run) and DIR/report.md. Bad input\n"
      "exits 2 before any run; no evaluated point meeting the constraints exits 2 after the search\n"
      "(report.md says so). See docs/optimize.md.");
  cmd->add_option("case", args->case_file, "case file (TOML)")->required();
  cmd->add_option("--vary", args->vary, "KEY=LO:HI, e.g. kinematics.rotation_phase=-0.25:0.15; repeat for more keys")
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("--maximize", args->maximize, "the result to maximise, e.g. mean_lift_N, lift_per_power_N_W")
      ->required();
  cmd->add_option("--constraint", args->constraints, "RESULT>=X or RESULT<=X, e.g. mean_lift_N>=0.0125; repeat")
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("-o,--output", args->output_dir, "output folder")->required()->check(non_empty_option());
  cmd->add_option("--algorithm", args->algorithm, "bobyqa (bounds only) or cobyla (constraints); default: "
                                                  "bobyqa, cobyla with --constraint")
      ->check(CLI::IsMember({"bobyqa", "cobyla"}));
  cmd->add_option("--max-evaluations", args->max_evaluations,
                  "points run at most, per start (default 50; a point asked for again is not run again)")
      ->check(whole_number(1, 100000));
  cmd->add_option("--starts", args->starts,
                  "independent searches: from the case's values, then from Halton points of the bounds (default 1); "
                  "spread over MPI ranks under mpirun/srun")
      ->check(whole_number(1, 1000));
  cmd->add_option("--x-tolerance", args->x_tolerance,
                  "converged when a step moves every key by less than this fraction of its range (default 0.001)")
      ->check(CLI::Range(1e-9, 0.5));
  cmd->add_option("--initial-step", args->initial_step,
                  "first step, as a fraction of each key's range (default 0.25)")
      ->check(CLI::Range(1e-6, 0.5));
  cmd->add_option("--chain", args->chain_file, "chain file for every run (as flapsim run --chain)")->check(non_empty_option());
  cmd->add_option("--wing", args->wing_file,
                  "wing file every run flies instead of the case's 'wing' (as flapsim run --wing)")
      ->check(non_empty_option());
  cmd->add_option("--spring-scale", args->spring_scale, "joint-spring factor for every run (as flapsim run)")
      ->check(positive_number());
  cmd->add_option("--vtk-every", args->vtk_every, "ParaView series of each run every N steps (default 0: none)")
      ->check(whole_number(0, 100000000));
  cmd->add_flag("--force", args->force, "run every point, also those an earlier run evaluated");
  cmd->add_flag("-q,--quiet", args->quiet, "no progress lines and no summary on stdout");
  cmd->callback([args] { optimize_command(*args); });
}

}  // namespace flapsim::cli
