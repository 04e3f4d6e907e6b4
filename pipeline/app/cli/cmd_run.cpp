// flapsim run CASE.toml -o DIR [--chain FILE] [--wing FILE] [--vtk-every N]
#include "pipeline/app/cli/commands.hpp"
#include "pipeline/app/cli/option_checks.hpp"
#include "pipeline/app/cli/wing_option.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "pipeline/app/flexibility_warnings.hpp"
#include "pipeline/app/frames_size.hpp"
#include "pipeline/app/fsi_run.hpp"
#include "pipeline/app/interruption.hpp"
#include "pipeline/app/resource_estimate.hpp"
#include "pipeline/app/run_results.hpp"
#include "pipeline/app/setup_warnings.hpp"
#include "pipeline/app/stage_monitor.hpp"
#include "pipeline/app/watched_setup.hpp"
#include "pipeline/io/case_file.hpp"
#include "pipeline/io/free_space.hpp"
#include "pipeline/io/output_manifest.hpp"

namespace flapsim::cli {

namespace {

struct RunArgs {
  std::string case_file;
  std::string output_dir;
  std::string chain_file;
  std::string wing_file;
  int vtk_every = -1;
  double spring_scale = 1.0;
  bool quiet = false;
  bool force = false;
};

void run_command(const RunArgs& a) {
  check_chain_option(a.chain_file);
  wings::TomlTable case_root = wings::parse_toml_file(a.case_file);
  apply_wing_option(case_root, a.wing_file, a.chain_file);
  const io::Case c = print_case_warnings(io::read_case(case_root));
  warn_unused_structure_options(c, a.chain_file, a.spring_scale);
  app::RunOptions options;
  // The case name is never a path: the default folder is out/ plus the name made safe.
  options.output_dir =
      a.output_dir.empty() ? default_run_folder(c.name, a.wing_file) : std::filesystem::path(a.output_dir);
  options.chain_file = a.chain_file;
  options.spring_scale = a.spring_scale;
  if (a.vtk_every >= 0) options.vtk_every = a.vtk_every;
  if (a.quiet) options.progress = app::ProgressLine::Mode::quiet;
  // Before any file is written: the size of the run (printed before a long one, refused
  // if its memory cannot fit), then the folder claimed for this run (output_manifest.hpp).
  io::OutputFolderClaim claim(options.output_dir, "run");  // "failed" if the run ends by an exception
  app::install_interrupt_handlers();  // SIGINT/SIGTERM in the time loop: finish the step, exit 130/143
  // The setup (a wing reduced in process takes seconds to a minute) cannot stop between
  // steps: a signal during it ends the command at once, before anything is written; the
  // setup's progress is shown if it lasts (stage_monitor.hpp).
  app::StageMonitor::Options watch;
  if (a.quiet) watch.display = app::StageMonitor::Options::Display::quiet;
  app::StageMonitor setup_watch(claim, 1, watch);
  setup_watch.stage(app::setup_stage_name(c, a.chain_file));
  std::vector<std::string> setup_notes;  // the setup's warnings' headlines
  options.before_start = [&](const app::FsiSetup& setup) {
    app::record_interrupt(setup_watch.done());
    app::throw_if_interrupted("during the run's setup; nothing was written");
    io::Case sized = c;  // with --vtk-every's interval, for the frames' size
    sized.output.vtk_every = options.vtk_every.value_or(c.output.vtk_every);
    const int fem_dofs = setup.fem_structure ? setup.fem_structure->num_dofs() : 0;
    const app::RunEstimate estimate = app::estimate_run(sized, setup.chain().num_bodies(), fem_dofs);
    // A run estimated over an hour says so even with -q (a 170-day run once started silently).
    if ((!a.quiet && (estimate.seconds > app::kLongRunSeconds || estimate.memory_bytes > 1e9)) ||
        estimate.seconds > app::kVeryLongRunSeconds)
      std::fprintf(stderr, "%s\n", app::describe(estimate).c_str());
    app::refuse_if_it_cannot_fit(estimate, c);
    for (const std::string& w : app::setup_warnings(c, setup)) {
      std::fprintf(stderr, "flapsim: warning: %s\n", w.c_str());
      setup_notes.push_back(app::warning_headline(w));
    }
    if (const std::string w =
            app::frames_size_warning(sized, fem_dofs, io::free_bytes_where(options.output_dir));
        !w.empty()) {
      std::fprintf(stderr, "flapsim: warning: %s\n", w.c_str());
      setup_notes.push_back(app::warning_headline(w));
    }
    if (const std::string w = app::frames_interval_warning(sized); !w.empty()) {
      std::fprintf(stderr, "flapsim: warning: %s\n", w.c_str());
      setup_notes.push_back(app::warning_headline(w));
    }
    claim.claim(a.force);
  };
  // summary.json's "warnings": the files' and the setup's, as a sweep's row gives them.
  options.warnings = [&](const app::FsiSetup& setup) {
    std::vector<std::string> notes = app::file_warning_notes(c, setup.wing ? &*setup.wing : nullptr);
    notes.insert(notes.end(), setup_notes.begin(), setup_notes.end());
    return app::join_notes(notes);
  };
  app::RunResults results;
  try {
    results = app::run_case(c, options);
  } catch (const app::Interrupted&) {
    claim.finish("interrupted");
    throw;
  }
  claim.finish("complete");
  if (const std::string w = app::large_deflection_warning(results); !w.empty())
    std::fprintf(stderr, "flapsim: warning: %s\n", w.c_str());
  if (!a.quiet) {
    std::fputs(app::run_report(results).c_str(), stdout);
    // The files this run wrote (with vtk_every = 0 no series and no ParaView state; in
    // vacuum no wake): the line used to name all six whatever was written.
    std::string written;
    for (const char* f : {"history.csv", "summary.json", "span_loads.csv", "wing.pvd", "wake.pvd",
                          "chain.pvd", "fem.pvd", "run.pvsm", "tip_path.vtp"})
      if (std::filesystem::exists(options.output_dir / f)) written += (written.empty() ? "" : ", ") + std::string(f);
    // The markers' paths (marker_<k>_path.vtp, k from 1), one a marker the case declares.
    const std::size_t markers =
        std::filesystem::exists(options.output_dir / "marker_1_path.vtp") ? c.markers.size() : 0;
    if (markers == 1)
      written += ", marker_1_path.vtp";
    else if (markers > 1)
      written += ", marker_1_path.vtp ... marker_" + std::to_string(markers) + "_path.vtp";
    std::printf("outputs in %s (%s)\n", options.output_dir.string().c_str(), written.c_str());
  }
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  auto* cmd = app.add_subcommand(
      "run",
      "Simulate a case: the wing's bar chain (or a rigid wing, or the wing's own FEM with\n"
      "structure.kind = \"fem\") flapping in air, strongly coupled with the unsteady vortex\n"
      "lattice, or in vacuum (air = \"none\").\n"
      "Writes into DIR: history.csv (t, base and tip Euler angles, aerodynamic force, lift, CL,\n"
      "coupling iterations, joint angles, markers), summary.json (last-cycle mean lift and CL,\n"
      "rotation phases of base and tip, coupling statistics, wall time), span_loads.csv (in air:\n"
      "each spanwise strip's mean lift over the last cycle, root to tip) and the ParaView series\n"
      "wing.pvd (deformed surface: pressure jump, circulation), wake.pvd, chain.pvd (fem.pvd:\n"
      "the FEM's deformed mesh, displacement and membrane strain).\n"
      "A flexible case takes its chain from --chain, else from the case's 'chain' key, else it\n"
      "reduces the case's wing in process to structure.bodies bodies (as 'flapsim reduce').\n"
      "--wing flies another wing in the case (its kinematics, air, structure and numerics\n"
      "kept), into out/<case name>_<wing file name> by default.\n"
      "Also writes run.pvsm, a ParaView state of the series and the lift (docs/fsi.md).\n"
      "One run per folder: a rerun replaces the previous run's files (DIR/flapsim_outputs.toml);\n"
      "another command's files that would be replaced need --force. A long run prints its\n"
      "estimate (memory, ParaView frames on disk, interactions, time) first; a run that cannot fit in memory "
      "is refused.\n"
      "SIGINT/SIGTERM finish the step, flush the outputs and write summary.json (status\n"
      "\"interrupted\").\n"
      "Exit status: 0 ok, 1 usage, 2 bad input, 3 numerical failure (outputs so far stay valid),\n"
      "4 output or system error, 130/143 interrupted by SIGINT/SIGTERM.");
  cmd->add_option("case", args->case_file, "case file (TOML, docs/case_file.md)")->required();
  cmd->add_option("-o,--output", args->output_dir,
                  "output folder (default out/<case name>, with --wing out/<case name>_<wing file name>)")
      ->check(non_empty_option());
  cmd->add_option("--chain", args->chain_file,
                  "chain file (chain.toml from 'flapsim reduce'), overrides the case's 'chain'")
      ->check(non_empty_option());
  cmd->add_option(
         "--wing", args->wing_file,
         "wing file (TOML) flown instead of the case's 'wing' (a flexible case reduces it as it runs, "
         "unless --chain)")
      ->check(non_empty_option());
  cmd->add_option("--vtk-every", args->vtk_every,
                  "write the ParaView series every N steps, 0 = none (default: the case's output.vtk_every)")
      ->check(whole_number(0, 100000000));
  cmd->add_option("--spring-scale", args->spring_scale,
                  "multiply every joint spring of a flexible chain by S (stiffness calibration; "
                  "frequencies scale by sqrt(S)); default 1")
      ->check(positive_number());
  cmd->add_flag("-q,--quiet", args->quiet, "no progress line and no report on stdout (a run estimated over an hour still prints its estimate)");
  cmd->add_flag("--force", args->force,
                "replace another command's outputs in DIR (e.g. the summary.json of 'flapsim reduce')");
  cmd->callback([args] { run_command(*args); });
}

}  // namespace flapsim::cli
