// flapsim reduce WING.toml -o DIR --bodies N: the equivalent beam and the Hencky bar
// chain of a wing, with a report of how well the chain reproduces the FEM
// (docs/reduction.md). The reduction library returns data; pipeline/io writes the
// files, each atomically.
#include "pipeline/app/cli/commands.hpp"
#include "pipeline/app/cli/option_checks.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <utility>

#include "fem/wing_fem.hpp"
#include "pipeline/app/chain_fem_mismatch.hpp"
#include "pipeline/app/numerical_stage.hpp"
#include "pipeline/app/reduction_input_limit.hpp"
#include "pipeline/app/stage_monitor.hpp"
#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/chain_file.hpp"
#include "pipeline/io/output_manifest.hpp"
#include "pipeline/io/reduction_files.hpp"
#include "reduction/beam_properties.hpp"
#include "reduction/chain_lumping.hpp"
#include "reduction/reduction_report.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/wing_file.hpp"

namespace flapsim::cli {

namespace {

namespace fs = std::filesystem;

struct ReduceOptions {
  std::string wing_file;
  std::string out_dir;
  int bodies = 10;
  int stations = 40;
  int modes = 12;
  std::string axis = "fitted";
  std::string springs = "full";
  bool force = false;
};

void run_reduce(const ReduceOptions& o) {
  const wings::Wing wing = wings::load_wing_file(o.wing_file);  // InputError → exit 2
  print_wing_warnings(wing);
  reduction::AnalysisOptions ao;
  ao.axis = o.axis == "span"     ? reduction::AxisChoice::span
            : o.axis == "fitted" ? reduction::AxisChoice::fitted
                                 : reduction::AxisChoice::flexural;
  const fs::path dir(o.out_dir);
  io::preflight_output_folder(dir, "reduce", o.force);  // unwritable, busy, another's: exit 4 before any work
  io::OutputFolderClaim claim(dir, "reduce");
  // SIGINT/SIGTERM: "interrupted" in the manifest, exit 130/143 at once; progress of long stages.
  app::StageMonitor monitor(claim, 7);
  // A failing solve in the FEM or the reduction is a numerical failure (exit 3).
  monitor.stage("mesh and FEM matrices");
  const fem::WingFem fem = app::numerical_stage("FEM", [&] { return fem::build_wing_fem(wing); });
  print_mesh_warnings(fem.model.mesh, wing);
  // The clamped wing's load cases and beam before the folder is claimed: a clamp or a mesh
  // that leaves too little free to reduce is the wing file's error (exit 2, reported at
  // clamp_y or element_size), and a wing error leaves the folder as it was.
  monitor.stage("static load cases of the clamped wing");
  const reduction::ClampedWingAnalysis analysis = app::numerical_stage("reduction", [&] {
    return app::reduce_wing_input_checked(
        wing, [&] { return reduction::ClampedWingAnalysis(fem.model.mesh, fem.system, fem.root_clamp, ao); });
  });
  monitor.stage("beam properties");
  const reduction::BeamProperties beam = app::numerical_stage("reduction", [&] {
    return app::reduce_wing_input_checked(
        wing, [&] { return reduction::extract_beam_properties(analysis, o.stations); });
  });
  app::reduce_wing_input_checked(wing, [&] { reduction::check_bodies_outside_clamp(analysis, o.bodies); });
  claim.claim(o.force);
  io::write_beam_csv(dir / "beam.csv", beam);  // written even if the chain cannot be made
  monitor.stage("FEM modes");
  const fem::WingModes modes =
      app::numerical_stage("FEM modes", [&] { return fem::wing_modes(fem, o.modes); });
  const reduction::SpringModel springs =
      o.springs == "diagonal" ? reduction::SpringModel::diagonal : reduction::SpringModel::full;
  monitor.stage("bar chain");
  const reduction::LumpedChain lc = app::numerical_stage("cannot reduce " + o.wing_file + " to " +
                                                             std::to_string(o.bodies) + " bodies",
                                                         [&] { return reduction::lump_into_chain(analysis, o.bodies, springs); });
  monitor.stage("chain against the FEM");
  const reduction::ChainFemComparison cmp = app::numerical_stage(
      "reduction", [&] { return reduction::compare_chain_with_fem(analysis, lc, modes.modes, modes.kinds); });
  monitor.stage("writing the outputs");
  // The chain file keeps the first modes against the FEM: run and check of it repeat a miss.
  const io::ChainFemRecord record = io::chain_fem_record(o.wing_file, cmp);
  io::write_chain_file(dir / "chain.toml", lc.chain, &record);
  io::write_reduction_vtk(dir, beam, lc);
  io::write_text_atomically(dir / "report.md", io::reduction_report(o.wing_file, beam, lc, cmp));
  io::write_reduction_summary(dir / "summary.json", beam, lc, cmp);
  claim.finish("complete");
  monitor.done();
  if (beam.fitted_axis_rejected) std::cerr << "reduce: " << io::fitted_axis_note(beam) << "\n";
  // A kind the FEM's first modes do not show (too few --modes) is said, not printed as 0 Hz.
  auto match = [](const char* kind, const reduction::ModeMatch& m) {
    std::ostringstream t;
    if (m.found)
      t << "first " << kind << " " << m.chain_hz << " Hz (FEM " << m.fem_hz << " Hz, "
        << io::format_percent(m.relative_error) << ")";
    else
      t << "no " << kind << " mode among the FEM modes computed (--modes)";
    return t.str();
  };
  std::cerr << "reduce: " << o.bodies << " bodies; " << match("bending", cmp.bending) << ", "
            << match("torsion", cmp.torsion) << "; wrote " << dir.string() << "\n";
  // A chain that misses the FEM's first modes by more than 10 % is said plainly: the
  // numbers above are easy to read past (a wing of aspect ratio 0.2 gave -24 % / -26 %).
  for (const auto& [kind, m] : {std::pair{"bending", &cmp.bending}, std::pair{"torsion", &cmp.torsion}})
    if (app::misses_fem_mode(*m))
      std::cerr << "flapsim: warning: the chain's first " << kind << " mode differs from the FEM's by "
                << io::format_percent(m->relative_error) << " (MAC " << m->mac
                << "): the chain does not represent this wing well (" << app::more_bodies_advice(cmp)
                << "; or a beam "
                   "cannot: a low aspect ratio, a film that cambers; docs/reduction.md); see "
                << (dir / "report.md").string() << "\n";
  // Static rows beyond the same bound: said as well (the swept film wing of docs/reduction.md:
  // bending rotation of the tip body under a moment on it +143 % at 6 bodies while its first
  // bending is -2.3 %).
  if (const std::string short_bodies = app::short_bodies_warning(cmp); !short_bodies.empty())
    std::cerr << "flapsim: warning: " << short_bodies << "\n";
  const std::string statics = app::static_mismatch_warning(cmp, (dir / "report.md").string());
  if (!statics.empty()) std::cerr << "flapsim: warning: " << statics << "\n";
}

}  // namespace

void add_reduce_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "reduce",
      "Reduce a wing's FEM to an equivalent beam and an N-body Hencky bar chain.\n"
      "Writes DIR/beam.csv (stations: s, y, m', x_cg, x_ea, EI, GJ, I_alpha),\n"
      "DIR/chain.toml (bodies and the joint stiffness, for 'flapsim run'), DIR/reduction.vtm (stations, bodies,\n"
      "joints, centres of mass),\n"
      "DIR/report.md and DIR/summary.json (chain vs FEM: first bending and torsion\n"
      "frequencies, MAC, static tip deflection and twist). Method: docs/reduction.md.\n"
      "A stage over 2 s is shown on stderr. Exit status: 0 ok, 2 bad input, 3 numerical failure\n"
      "of the FEM or the reduction, 4 output error, 130/143 interrupted by SIGINT/SIGTERM\n"
      "(at once; flapsim_outputs.toml says \"interrupted\").");
  auto o = std::make_shared<ReduceOptions>();
  cmd->add_option("WING", o->wing_file, "wing file (TOML)")->required();
  cmd->add_option("-o,--output", o->out_dir, "output directory")->required()->check(non_empty_option());
  cmd->add_option("--bodies", o->bodies, "number of bodies N_b (default 10; at least 2, as a case's structure.bodies)")
      ->check(CLI::Range(2, 1000));
  cmd->add_option("--stations", o->stations, "number of beam stations (default 40)")
      ->check(CLI::Range(2, 10000));
  cmd->add_option("--modes", o->modes, "FEM modes to compute (default 12)")->check(CLI::Range(2, 200));
  cmd->add_option("--axis", o->axis,
                  "the chain's axis: fitted (line through the pivot and the cells' elastic axes, default), "
                  "flexural (least-squares line through the stations' flexural axes) or span (y_W)")
      ->check(CLI::IsMember({"flexural", "fitted", "span"}));
  cmd->add_option("--springs", o->springs,
                  "joint springs: full (the joint stiffness K by reciprocity, default) or diagonal "
                  "(the papers' independent springs, coupling dropped)")
      ->check(CLI::IsMember({"full", "diagonal"}));
  cmd->add_flag("--force", o->force, "replace another command's outputs in the folder that this command would overwrite");
  cmd->callback([o] { run_reduce(*o); });
}

}  // namespace flapsim::cli
