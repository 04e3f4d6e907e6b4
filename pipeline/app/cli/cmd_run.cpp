// flapsim run CASE.toml -o DIR [--chain FILE] [--vtk-every N]
#include "pipeline/app/cli/commands.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "pipeline/io/case_file.hpp"
#include "pipeline/app/fsi_run.hpp"
#include "pipeline/app/run_results.hpp"

namespace flapsim::cli {

namespace {

struct RunArgs {
  std::string case_file;
  std::string output_dir;
  std::string chain_file;
  int vtk_every = -1;
  double spring_scale = 1.0;
  bool quiet = false;
};

void run_command(const RunArgs& a) {
  const io::Case c = io::load_case_file(a.case_file);
  check_chain_option(a.chain_file);
  app::RunOptions options;
  options.output_dir = a.output_dir.empty() ? std::filesystem::path("out") / c.name
                                          : std::filesystem::path(a.output_dir);
  options.chain_file = a.chain_file;
  options.spring_scale = a.spring_scale;
  if (a.vtk_every >= 0) options.vtk_every = a.vtk_every;
  if (a.quiet) options.progress = app::ProgressLine::Mode::quiet;
  const app::RunResults results = app::run_case(c, options);
  if (!a.quiet) {
    std::fputs(app::run_report(results).c_str(), stdout);
    std::printf("outputs in %s (history.csv, summary.json, wing.pvd, wake.pvd, chain.pvd, run.pvsm)\n",
                options.output_dir.string().c_str());
  }
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  auto* cmd = app.add_subcommand(
      "run",
      "Simulate a case: the wing's bar chain (or a rigid wing) flapping in air, strongly coupled "
      "with the unsteady vortex lattice, or in vacuum (air = \"none\").\n"
      "Writes into DIR: history.csv (t, base and tip Euler angles, aerodynamic force, lift, CL,\n"
      "coupling iterations, joint angles, markers), summary.json (last-cycle mean lift and CL,\n"
      "rotation phases of base and tip, coupling statistics, wall time) and the ParaView series\n"
      "wing.pvd (deformed surface: pressure jump, circulation), wake.pvd, chain.pvd.\n"
      "A flexible case takes its chain from --chain, else from the case's 'chain' key, else it\n"
      "reduces the case's wing in process to structure.bodies bodies (as 'flapsim reduce').\n"
      "Also writes run.pvsm, a ParaView state of the series and the lift (docs/fsi.md).\n"
      "Exit status: 0 ok, 2 bad input, 3 numerical failure (outputs so far stay valid).");
  cmd->add_option("case", args->case_file, "case file (TOML, docs/case_file.md)")->required();
  cmd->add_option("-o,--output", args->output_dir, "output folder (default out/<case name>)");
  cmd->add_option("--chain", args->chain_file,
                  "chain file (chain.toml from 'flapsim reduce'), overrides the case's 'chain'");
  cmd->add_option("--vtk-every", args->vtk_every,
                  "write the ParaView series every N steps, 0 = none (default: the case's output.vtk_every)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--spring-scale", args->spring_scale,
                  "multiply every joint spring of a flexible chain by S (stiffness calibration; "
                  "frequencies scale by sqrt(S)); default 1")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("-q,--quiet", args->quiet, "no progress line and no report on stdout");
  cmd->callback([args] { run_command(*args); });
}

}  // namespace flapsim::cli
