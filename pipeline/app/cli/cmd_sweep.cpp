// flapsim sweep CASE.toml --vary KEY=VALUES -o DIR [--chain FILE] [--jobs N] [--vtk-every N]
#include "pipeline/app/cli/commands.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "pipeline/app/cli/thread_options.hpp"
#include "pipeline/app/run_results.hpp"
#include "pipeline/app/sweep/sweep_runner.hpp"
#include "pipeline/app/sweep/sweep_values.hpp"

namespace flapsim::cli {

namespace {

struct SweepArgs {
  std::string case_file, vary, output_dir, chain_file;
  int jobs = 0;
  int vtk_every = 0;
  double spring_scale = 1.0;
  bool quiet = false;
};

void sweep_command(const SweepArgs& a) {
  const sweep::Variation variation = sweep::parse_variation(a.vary);
  check_chain_option(a.chain_file);
  sweep::SweepOptions options;
  options.output_dir = a.output_dir;
  options.chain_file = a.chain_file;
  options.spring_scale = a.spring_scale;
  options.threads = a.jobs > 0 ? a.jobs : command_threads();  // one OpenMP thread per case
  options.vtk_every = a.vtk_every;
  options.quiet = a.quiet;
  const auto rows = sweep::run_sweep(a.case_file, variation, options);
  if (a.quiet) return;
  // The table of sweep.csv's result columns (run_results.hpp), one row per value.
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
  std::printf("%-16s", variation.key.substr(variation.key.rfind('.') + 1).c_str());
  for (const Column& col : columns) std::printf(" %*s", col.width, col.title.c_str());
  std::printf("  status\n");
  for (const auto& r : rows) {
    std::printf("%-16s", sweep::value_label(r.value).c_str());
    for (const Column& col : columns) {
      const std::string cell = r.results.at(col.result) ? app::format_result(r.results, col.result) : "nan";
      std::printf(" %*s", col.width, cell.c_str());
    }
    std::printf("  %s\n", r.status.c_str());
  }
  std::printf("table: %s\n", (std::filesystem::path(a.output_dir) / "sweep.csv").string().c_str());
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto args = std::make_shared<SweepArgs>();
  auto* cmd = app.add_subcommand(
      "sweep",
      "Run a case for several values of one case-file key, in parallel over the cores.\n"
      "VALUES: start:step:stop (inclusive) or a comma list, e.g.\n"
      "  flapsim sweep cases/rotation_phase_rigid.toml --vary kinematics.rotation_phase=-0.20:0.05:0.10 -o out/rigid\n"
      "Each value runs in DIR/<index>_<value>/ (history.csv, summary.json; VTK with --vtk-every);\n"
      "DIR/sweep.csv lists value, mean lift, mean CL, tip rotation phase and lag, coupling\n"
      "iterations, wall time and status of each case (a failed case does not stop the others).");
  cmd->add_option("case", args->case_file, "case file (TOML)")->required();
  cmd->add_option("--vary", args->vary, "KEY=VALUES, e.g. kinematics.rotation_phase=-0.10:0.05:0.10")
      ->required();
  cmd->add_option("-o,--output", args->output_dir, "output folder")->required();
  cmd->add_option("--chain", args->chain_file, "chain file for every case (as flapsim run --chain)");
  cmd->add_option("-j,--jobs", args->jobs, "cases run at the same time (default: --threads)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--vtk-every", args->vtk_every, "ParaView series per case every N steps (default 0: none)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--spring-scale", args->spring_scale,
                  "joint-spring factor for every case (as flapsim run --spring-scale)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("-q,--quiet", args->quiet, "no progress lines and no table on stdout");
  cmd->callback([args] { sweep_command(*args); });
}

}  // namespace flapsim::cli
