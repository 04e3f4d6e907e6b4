// flapsim modes WING.toml -o DIR [--modes N]: FEM of the root-clamped wing;
// writes DIR/modes.csv (mode, frequency_hz, kind) and DIR/fem.vtu (mode shapes
// and the static tip load cases as point data).
#include "pipeline/app/cli/commands.hpp"
#include "pipeline/app/cli/option_checks.hpp"
#include "pipeline/app/cli/thread_options.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <filesystem>
#include <memory>
#include <string>

#include "fem/wing_fem.hpp"
#include "pipeline/app/wing_modes_stage.hpp"
#include "pipeline/app/stage_monitor.hpp"
#include "pipeline/fsi/numerical_failure.hpp"
#include "pipeline/io/fem_modes_state.hpp"
#include "pipeline/io/fem_vtk.hpp"
#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/output_manifest.hpp"
#include "wings/loader/wing_file.hpp"

namespace flapsim::cli {

namespace {

struct ModesArgs {
  std::string wing_file;
  std::string out_dir = "out";
  int modes = 20;
  int bodies = 10;
  int state_mode = 1;  ///< the mode fem_modes.pvsm animates (1-based)
  bool force = false;
};

void run_modes(const ModesArgs& args) {
  // Options out of their range are usage errors (exit status 1, README): --modes and
  // --state-mode alone by their validators, --state-mode against --modes here.
  if (args.state_mode > args.modes)
    throw CLI::ValidationError("--state-mode", "must be between 1 and --modes (" + std::to_string(args.modes) +
                                                   "), got " + std::to_string(args.state_mode));
  // 1. Wing; the output folder writable before any work (else exit 4 naming it).
  const wings::Wing wing = wings::load_wing_file(args.wing_file);
  print_wing_warnings(wing);
  const std::filesystem::path dir(args.out_dir);
  io::preflight_output_folder(dir, "modes",
                              args.force);  // unwritable, busy, another's: exit 4 before any work
  io::OutputFolderClaim claim(dir, "modes");
  // SIGINT/SIGTERM: "interrupted" in the manifest, exit 130/143 at once; progress of long stages.
  app::StageMonitor monitor(claim, 5);
  // 2–5. Mesh, K and M, root clamp; the lowest modes of the clamped wing; the static tip
  // load cases; the modes' names from the stations of the chain (docs/reduction.md). A
  // failing solver is a numerical failure (exit 3). The folder is claimed as the second
  // stage begins, the wing meshed: a wing error found by the mesher (exit 2) leaves it as it was.
  bool meshed = false;
  const app::WingModesStage r =
      app::compute_wing_modes(wing, args.modes, args.bodies, command_threads(), [&](const std::string& s) {
        if (meshed) claim.claim_once(args.force);
        meshed = true;
        monitor.stage(s);
      });
  claim.claim_once(args.force);
  const fem::WingFem& fem = r.fem;
  const fem::Mesh& mesh = fem.model.mesh;
  print_mesh_warnings(mesh, wing);
  const fem::WingModes& m = r.modes;
  const std::vector<io::ModeLabel>& labels = r.labels;
  const std::vector<io::StaticResult>& results = r.statics;
  // A coarse mesh has fewer modes than asked for: say so, and animate one it has (before,
  // --state-mode past them read beyond the results: a "mode 96: 0.00 Hz" state, or exit 4).
  const int computed = static_cast<int>(m.modes.frequencies_hz.size());
  if (computed < args.modes)
    std::fprintf(
        stderr,
        "flapsim: warning: the wing's mesh (%d nodes) gives %d modes, not the %d asked for (--modes): "
        "a finer mesh ([mesh] element_size) gives more\n",
        mesh.num_nodes(), computed, args.modes);
  const int state_mode = std::min(args.state_mode, computed);
  if (state_mode < args.state_mode)
    std::fprintf(stderr,
                 "flapsim: warning: --state-mode %d is beyond the %d modes computed: fem_modes.pvsm animates "
                 "mode %d\n",
                 args.state_mode, computed, state_mode);
  monitor.stage("writing the outputs");
  // 6. Outputs (each atomic).
  io::write_modes_csv(dir / "modes.csv", m.modes, labels);
  io::write_fem_vtu(dir / "fem.vtu", mesh, wing.clamp_y, m.modes, labels, results);
  {
    io::FemModeView view;
    view.mode = state_mode;
    const auto k = static_cast<std::size_t>(state_mode - 1);
    view.frequency_hz = m.modes.frequencies_hz(static_cast<Eigen::Index>(k));
    view.kind = labels[k].kind;
    view.shape_kind = labels[k].shape_kind;
    view.bounds = {mesh.nodes[0].x(), mesh.nodes[0].x(), mesh.nodes[0].y(), mesh.nodes[0].y(),
                   mesh.nodes[0].z(), mesh.nodes[0].z()};
    for (const auto& x : mesh.nodes)
      for (int i = 0; i < 3; ++i) {
        view.bounds[2 * i] = std::min(view.bounds[2 * i], x(i));
        view.bounds[2 * i + 1] = std::max(view.bounds[2 * i + 1], x(i));
      }
    io::write_fem_modes_state(dir / "fem_modes.pvsm", view);
  }
  claim.finish("complete");
  monitor.done();

  std::printf("%s: %d nodes, %zu triangles, %zu vein elements, FEM mass %.4g mg\n", wing.name.c_str(),
              mesh.num_nodes(), mesh.triangles.size(), mesh.beams.size(), fem.system.total_mass * 1e6);
  std::printf("%5s %12s  %-8s %10s  %s\n", "mode", "f [Hz]", "kind", "beam share", "shape");
  for (Eigen::Index k = 0; k < m.modes.frequencies_hz.size(); ++k) {
    const io::ModeLabel& l = labels[static_cast<std::size_t>(k)];
    std::printf("%5d %12.3f  %-8s %10.3f  %s\n", static_cast<int>(k + 1), m.modes.frequencies_hz(k), l.kind.c_str(),
                l.beam_share, l.shape_kind.c_str());
  }
  std::printf("wrote %s, %s, %s (ParaView: mode %d animated)\n", (dir / "modes.csv").string().c_str(),
              (dir / "fem.vtu").string().c_str(), (dir / "fem_modes.pvsm").string().c_str(), state_mode);
}

}  // namespace

void add_modes_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "modes",
      "FEM of the wing clamped at its root (nodes with y <= clamp_y): the lowest modes\n"
      "(Lanczos, shift-invert) named bending, torsion or film from the motion of the\n"
      "stations of the N-body chain, as 'flapsim reduce' names them (beam share: the part\n"
      "of the motion the stations' rigid sections carry; below 1/2 a film mode), beside\n"
      "their shape classification (bending, torsion, chordwise, in-plane),\n"
      "and four static cases (unit tip force at the leading and at the trailing edge,\n"
      "unit tip bending moment, unit tip torque, at 90 % of the span).\n"
      "Writes DIR/modes.csv (mode, frequency_hz, kind, beam_share, shape_kind) and DIR/fem.vtu:\n"
      "point vectors mode_NN scaled so the largest displacement is 10 % of the span (field data\n"
      "mode_NN_frequency_Hz, mode_NN_kind, mode_NN_beam_share, mode_NN_shape_kind,\n"
      "mode_NN_scale) and static_<case>_m_per_N[_m]\n"
      "(displacement per unit load), and DIR/fem_modes.pvsm: a ParaView state animating the\n"
      "--state-mode mode (Warp By Vector, its frequency and kinds as text).\n"
      "Exit status: 0 ok, 2 bad input, 3 numerical failure\n"
      "of the FEM, 4 output error, 130/143 interrupted by SIGINT/SIGTERM (at once;\n"
      "flapsim_outputs.toml says \"interrupted\"). A stage over 2 s is shown on stderr.");
  auto args = std::make_shared<ModesArgs>();
  cmd->add_option("WING", args->wing_file, "wing file (TOML)")->required();
  cmd->add_option("-o,--output", args->out_dir, "output directory")->check(non_empty_option())->capture_default_str();
  cmd->add_option("--modes", args->modes, "number of modes")->check(CLI::Range(1, 500))->capture_default_str();
  cmd->add_option("--bodies", args->bodies, "bodies of the chain whose stations name the modes (as flapsim reduce --bodies)")
      ->check(CLI::Range(2, 1000))
      ->capture_default_str();
  cmd->add_option("--state-mode", args->state_mode, "the mode fem_modes.pvsm animates (1-based, at most --modes)")
      ->check(CLI::Range(1, 500))
      ->capture_default_str();
  cmd->add_flag("--force", args->force, "replace another command's outputs in the folder that this command would overwrite");
  cmd->callback([args] { run_modes(*args); });
}

}  // namespace flapsim::cli
