// flapsim sweep CASE.toml (--vary KEY=VALUES ... | --cases TABLE.csv) -o DIR [--chain FILE]
//   [--spring-scale S] [--jobs N] [--vtk-every N] [--log-every S] [--force] [--quiet]
#include "pipeline/app/cli/commands.hpp"
#include "pipeline/app/cli/option_checks.hpp"
#include "pipeline/app/cli/wing_option.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "pipeline/app/cli/thread_options.hpp"
#include "pipeline/app/interruption.hpp"
#include "pipeline/app/run_results.hpp"
#include "pipeline/app/sweep/case_table.hpp"
#include "pipeline/app/sweep/mixed_reference_speeds.hpp"
#include "pipeline/app/sweep/sweep_runner.hpp"
#include "pipeline/app/sweep/sweep_values.hpp"
#include "pipeline/io/case_file.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/toml_reader.hpp"

namespace flapsim::cli {

namespace {

struct SweepArgs {
  std::string case_file, cases_table, output_dir, chain_file, wing_file;
  std::vector<std::string> vary;
  int jobs = 0;
  int vtk_every = 0;
  double spring_scale = 1.0;
  double log_every = 30.0;  // [s]
  bool force = false;
  bool quiet = false;
};

// The table of sweep.csv's columns on stdout: the varied keys, the results with a sweep
// label (run_results.hpp) titled by it, the status.
void print_table(const sweep::SweepPlan& plan, const sweep::SweepReport& report) {
  struct Column {
    std::size_t result;
    std::string title;
    int width;
  };
  std::vector<Column> columns;
  for (std::size_t i : app::sweep_results()) {
    const app::ResultDefinition& d = app::kRunResults[i];
    std::string title(d.sweep_label);
    if (!d.unit.empty()) title += " [" + std::string(d.unit) + "]";
    columns.push_back({i, title, std::max(static_cast<int>(title.size()) + 1, 10)});
  }
  // The keys' columns: 16 wide, or one more than their longest title or value (a title as
  // long as 16, chordwise_panels, ran into the next one's).
  std::vector<std::string> key_titles;
  std::vector<int> key_widths;
  for (std::size_t k = 0; k < plan.keys.size(); ++k) {
    key_titles.push_back(plan.keys[k].substr(plan.keys[k].rfind('.') + 1));
    std::size_t longest = key_titles.back().size();
    for (const auto& r : report.rows)
      if (k < r.point.size()) longest = std::max(longest, sweep::value_label(r.point[k]).size());
    key_widths.push_back(std::max(16, static_cast<int>(longest) + 1));
  }
  for (std::size_t k = 0; k < key_titles.size(); ++k) std::printf("%-*s", key_widths[k], key_titles[k].c_str());
  for (const Column& col : columns) std::printf(" %*s", col.width, col.title.c_str());
  std::printf("  status\n");
  for (const auto& r : report.rows) {
    for (std::size_t k = 0; k < r.point.size(); ++k)
      std::printf("%-*s", k < key_widths.size() ? key_widths[k] : 16, sweep::value_label(r.point[k]).c_str());
    for (const Column& col : columns) {
      const std::string cell =
          r.outcome.results.at(col.result) ? app::format_result(r.outcome.results, col.result) : "nan";
      std::printf(" %*s", col.width, cell.c_str());
    }
    std::printf("  %s%s\n", r.done ? r.outcome.status.c_str() : "not run",
                sweep::kept_from_earlier_run(r.outcome) ? " (kept)" : "");
  }
}

void sweep_command(const SweepArgs& a) {
  if (a.vary.empty() == a.cases_table.empty())
    throw InputError("", 0, "--vary",
                     "give the values either with --vary KEY=VALUES (one or more) or with --cases TABLE.csv");
  sweep::SweepPlan plan;
  if (!a.cases_table.empty()) {
    const sweep::CaseTable table = sweep::read_case_table(a.cases_table);
    plan.keys = table.keys;
    plan.points = table.points;
    plan.table_file = a.cases_table;
    plan.header_line = table.header_line;
    plan.lines = table.lines;
  } else {
    std::vector<sweep::Variation> variations;
    for (const std::string& v : a.vary) variations.push_back(sweep::parse_variation(v));
    plan = sweep::grid_plan(variations);
  }
  check_chain_option(a.chain_file);
  const bool wing_varied = std::find(plan.keys.begin(), plan.keys.end(), "wing") != plan.keys.end();
  if (!a.wing_file.empty() && wing_varied)
    throw InputError("", 0, "--wing",
                     "the sweep varies 'wing' too: give the wings one way, --wing or the varied key");
  wings::TomlTable case_root = wings::parse_toml_file(a.case_file);
  // A chain file is one wing's: with varied wings each case reduces its own.
  const std::string chained_wings =
      "the sweep varies 'wing', and a chain file is reduced from one wing: leave it out, and each case "
      "reduces "
      "its own wing as it runs";
  if (wing_varied && !a.chain_file.empty()) throw InputError(a.chain_file, 0, "--chain", chained_wings);
  if (wing_varied && case_root.has("chain"))
    throw InputError(case_root.file(), case_root.line_of("chain"), "chain", chained_wings);
  apply_wing_option(case_root, a.wing_file, a.chain_file);
  const io::Case base = print_case_warnings(io::read_case(case_root));  // each case is checked again
  warn_unused_structure_options(base, a.chain_file, a.spring_scale);
  sweep::SweepOptions options;
  options.output_dir = a.output_dir;
  options.chain_file = a.chain_file;
  options.wing_file = a.wing_file;
  options.spring_scale = a.spring_scale;
  options.threads = a.jobs > 0 ? a.jobs : requested_threads();  // 0: the runner's default
  options.vtk_every = a.vtk_every;
  options.force = a.force;
  options.quiet = a.quiet;
  options.log_interval = std::chrono::milliseconds(static_cast<long long>(std::llround(a.log_every * 1e3)));
  app::install_interrupt_handlers();  // SIGINT/SIGTERM: the running cases finish their step, exit 130/143
  const sweep::SweepReport report = sweep::run_sweep(a.case_file, plan, options);
  if (!report.root || a.quiet) return;
  print_table(plan, report);
  if (const std::string note = sweep::mixed_reference_speeds_note(report.rows); !note.empty())
    std::printf("%s\n", note.c_str());
  const std::size_t ran = report.stats.cases;
  std::printf("%zu cases: %zu run, %zu kept from an earlier run; %d rank%s x %d thread%s; %.1f s wall",
              report.rows.size(), ran, report.kept, report.ranks, report.ranks == 1 ? "" : "s",
              report.threads, report.threads == 1 ? "" : "s", report.wall_s);
  if (ran > 0)
    std::printf("; scheduling overhead %.1f ms per case (max %.1f ms)", 1e3 * report.stats.overhead_s / ran,
                1e3 * report.stats.max_overhead_s);
  std::printf("\ntable: %s\n", (std::filesystem::path(a.output_dir) / "sweep.csv").string().c_str());
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto args = std::make_shared<SweepArgs>();
  auto* cmd = app.add_subcommand(
      "sweep",
      "Run a case for many values of its keys: a grid (--vary, several make a Cartesian product)\n"
      "or a table (--cases), in parallel over the cores, and over MPI ranks under mpirun/srun.\n"
      "VALUES: start:step:stop (inclusive) or a comma list of numbers or words (a text key's values:\n"
      "numerics.leading_edge=none,separated,shed; true,false). KEY: a case-file key, wing.<key>\n"
      "of the wing file (e.g. wing.membrane.thickness) or spring_scale; KEY[i], element i (from 0) of\n"
      "an array of numbers (e.g. 'kinematics.sweep.cos_deg[0]', the stroke amplitude), e.g.\n"
      "  flapsim sweep cases/rotation_phase_rigid.toml --vary kinematics.rotation_phase=-0.20:0.05:0.10 -o "
      "out/rigid\n"
      "  mpirun -np 4 flapsim sweep CASE.toml --vary kinematics.rotation_phase=-0.1:0.05:0.1 --vary "
      "spring_scale=1,2 -o DIR\n"
      "Each case runs in DIR/<index>_<values>/ (history.csv, summary.json; VTK with --vtk-every);\n"
      "DIR/sweep.csv lists the values, mean lift, mean CL, tip rotation phase and lag, coupling\n"
      "iterations, wall time, folder, status, message, rank and host of each case (a failed case\n"
      "does not stop the others; every case is checked as run checks it before any runs: bad input\n"
      "exits 2, nothing run; each case's folder is locked while it runs). Run again, it keeps the\n"
      "cases whose summary.json matches their inputs and runs the rest (--force: all). While\n"
      "cases run, stderr shows their steps (a line redrawn on a terminal; in a log a line every\n"
      "30 s, --log-every). SIGINT/SIGTERM: the cases\n"
      "under way finish their step and write summary.json (\"interrupted\"), no other case starts;\n"
      "exit 130/143.\n"
      "See docs/sweeps.md.");
  cmd->add_option("case", args->case_file, "case file (TOML)")->required();
  cmd->add_option("--vary", args->vary,
                  "KEY=VALUES, e.g. kinematics.rotation_phase=-0.10:0.05:0.10; repeat for a grid")
      ->allow_extra_args(false)  // one value per --vary: `--vary K=V CASE.toml` leaves CASE.toml alone
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("--cases", args->cases_table,
                  "CSV table, one case per row; the header names the keys (instead of --vary)");
  cmd->add_option("-o,--output", args->output_dir, "output folder")->required()->check(non_empty_option());
  cmd->add_option("--chain", args->chain_file, "chain file for every case (as flapsim run --chain)")->check(non_empty_option());
  cmd->add_option("--wing", args->wing_file,
                  "wing file every case flies instead of the case's 'wing' (as flapsim run --wing)")
      ->check(non_empty_option());
  cmd->add_option(
         "-j,--jobs", args->jobs,
         "cases run at the same time per process/rank (default: --threads if given, else the cores, shared by the ranks on a machine)")
      ->check(whole_number(0, kMaxThreads));
  cmd->add_option("--vtk-every", args->vtk_every, "ParaView series per case every N steps (default 0: none)")
      ->check(whole_number(0, 100000000));
  cmd->add_option("--spring-scale", args->spring_scale,
                  "joint-spring factor for every case (as flapsim run --spring-scale)")
      ->check(positive_number());
  cmd->add_flag("--force", args->force, "run every case, also those an earlier run of the sweep completed");
  cmd->add_option("--log-every", args->log_every,
                  "stderr not a terminal (a log): a line on the cases under way every SECONDS without other "
                  "output (default 30)")
      ->check(CLI::Range(0.1, 86400.0));
  cmd->add_flag("-q,--quiet", args->quiet, "no progress lines and no table on stdout");
  cmd->callback([args] { sweep_command(*args); });
}

}  // namespace flapsim::cli
