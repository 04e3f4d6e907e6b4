// flapsim check FILE.toml: validate a wing or case file and print its summary.
// GCC 12 warns -Wrestrict inside CLI11's Formatter::make_option_usage (std::string operator+ inlined
// from <string>: GCC bug 105329, a false positive that comes and goes with inlining decisions).
#pragma GCC diagnostic ignored "-Wrestrict"

#include "pipeline/app/cli/commands.hpp"
#include "pipeline/app/cli/option_checks.hpp"
#include "pipeline/app/cli/wing_option.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "fem/wing_mesher.hpp"
#include "pipeline/app/frames_size.hpp"
#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/app/low_reynolds_warning.hpp"
#include "pipeline/app/numerical_stage.hpp"
#include "pipeline/app/resource_estimate.hpp"
#include "pipeline/app/setup_warnings.hpp"
#include "pipeline/app/watched_setup.hpp"
#include "pipeline/io/case_file.hpp"
#include "pipeline/io/case_summary.hpp"
#include "pipeline/io/kinematics_samples.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/toml_reader.hpp"
#include "wings/loader/wing_file.hpp"
#include "wings/loader/wing_summary.hpp"

namespace flapsim::cli {

namespace {

/// gmsh's dry run: the wing is meshed (no file written), so an outline or mesh sizes
/// gmsh cannot handle fail here, as they would in mesh, modes, reduce and run. With
/// \p warn a sliver in the mesh is warned about, as mesh, modes and reduce warn.
void check_meshable(const wings::Wing& wing, bool warn) {
  const fem::Mesh mesh = fem::mesh_wing(wing);
  if (warn) print_mesh_warnings(mesh, wing);
}

/// Everything `flapsim run` checks before its first step, without running: the chain file,
/// a wing for a run in air, loads and markers on existing bodies, the wing meshable when
/// it is reduced in process, and the run's size against the memory (the estimate is part
/// of the summary).
/// `stream_radius` gets r2·R [m] of the run's lattice (in air), where the case's summary
/// gives the angle of attack in a free stream.
std::string check_case_like_run(const io::Case& c, const std::string& chain_file,
                                std::optional<double>& stream_radius) {
  std::string text;
  std::optional<wings::Wing> wing;
  if (!c.wing_file.empty()) wing = print_wing_warnings(wings::load_wing_file(c.wing_file));
  if (c.air.enabled && !wing)
    throw InputError(c.file, c.line_of("wing"), "wing",
                     "a run in air needs the wing's outline for the vortex lattice: name a wing "
                     "file, or set air = \"none\" for a vacuum run of the chain");
  int bodies = c.structure.bodies, fem_dofs = 0, reduced_fem_dofs = 0;
  std::string reynolds;  // the run's Reynolds number line (in air)
  const bool reduced_in_process = app::reduces_wing_in_process(c, chain_file);
  if (reduced_in_process && wing) app::check_lattice_can_follow(c, *wing);
  {
    // Reads the chain file, or reduces the wing in process as `run` does (its FEM: seconds
    // to a minute, shown as run shows it), so that the chain's frequencies can be warned about.
    app::SetupOptions options;
    options.chain_file = chain_file;  // check --chain, as run --chain
    // A failure of the numerics in the setup (the FEM or the reduction of a wing reduced in
    // process) is exit status 3, as in run (numerical_stage.hpp), not a system error.
    const app::FsiSetup setup = app::numerical_stage("check setup", [&] {
      return app::build_fsi_setup_watched(c, options, "check", [&] {
        if (reduced_in_process && wing) check_meshable(*wing, true);
      });
    });
    bodies = setup.chain().num_bodies();
    if (c.air.enabled) stream_radius = setup.reference.r2 * setup.reference.span;
    if (setup.model.air) reynolds = "  Reynolds number        " + app::describe_reynolds(c, setup) + "\n";
    if (setup.fem_structure) fem_dofs = setup.fem_structure->num_dofs();
    reduced_fem_dofs = setup.reduced_fem_dofs;
    for (const std::string& w : app::setup_warnings(c, setup))
      std::fprintf(stderr, "flapsim: warning: %s\n", w.c_str());
  }
  const app::RunEstimate estimate = app::estimate_run(c, bodies, fem_dofs, reduced_fem_dofs);
  app::refuse_if_it_cannot_fit(estimate, c);
  // The folder of a run is not known here (run -o): the size alone is warned.
  if (const std::string w = app::frames_size_warning(c, fem_dofs, std::nullopt); !w.empty())
    std::fprintf(stderr, "flapsim: warning: %s\n", w.c_str());
  if (const std::string w = app::frames_interval_warning(c); !w.empty())
    std::fprintf(stderr, "flapsim: warning: %s\n", w.c_str());
  text += reynolds;
  text += "  " + app::describe(estimate) + "\n";
  if (wing) {
    // An FEM case's sliver is among the setup's warnings; a chain file's run has no FEM.
    if (!reduced_in_process) check_meshable(*wing, false);
    text += "\n" + wings::describe_wing(*wing);
  }
  return text;
}

/// Reads the file, decides whether it is a wing ([planform]) or a case ([kinematics]),
/// checks it completely (a case as `run` would: its wing, chain file and size) and returns
/// the summary text. Nothing is printed until everything has been checked.
std::string check_file(const std::string& path, const std::string& chain_file, const std::string& wing_file,
                       const std::string& kinematics_file) {
  wings::TomlTable root = wings::parse_toml_file(path);
  const bool wing = wings::is_wing_document(root), case_file = io::is_case_document(root);
  if (wing && case_file)
    throw InputError(path, root.line_of("planform"), "planform",
                     "a file is either a wing file ([planform]) or a case file ([kinematics]), not both");
  if (wing) {
    if (!chain_file.empty()) throw CLI::ValidationError("--chain", "applies to a case file, not a wing file");
    if (!wing_file.empty()) throw CLI::ValidationError("--wing", "applies to a case file, not a wing file");
    if (!kinematics_file.empty())
      throw CLI::ValidationError("--kinematics", "applies to a case file, not a wing file");
    const wings::Wing w = print_wing_warnings(wings::read_wing(root));
    check_meshable(w, true);
    return wings::describe_wing(w);
  }
  if (case_file) {
    apply_wing_option(root, wing_file, chain_file);
    const io::Case c = print_case_warnings(io::read_case(root));
    warn_unused_structure_options(c, chain_file, 1.0);  // as run warns
    std::optional<double> stream_radius;
    const std::string checked = check_case_like_run(c, chain_file, stream_radius);
    std::string written;
    if (!kinematics_file.empty()) {
      // The angles the run flies, at its steps: to plot beside a measured wingbeat.
      io::write_kinematics_samples(kinematics_file, c.kinematics, c.numerics.steps_per_cycle);
      written = "\nkinematics of one wingbeat at the run's " + std::to_string(c.numerics.steps_per_cycle) +
                " steps (angles, rates, accelerations): " + kinematics_file + "\n";
    }
    return io::describe_case(c, stream_radius) + checked + written;
  }
  if (root.has("bodies"))
    throw InputError(path, root.line_of("bodies"), "bodies",
                     "a chain file (it has [[bodies]]): check reads wing and case files; 'flapsim check CASE "
                     "--chain " + path + "' checks the chain with the case that runs it");
  // A file with a wing's tables ([membrane], [materials], ...) or a case's ([numerics], wing = ...)
  // but not its defining one is that kind of file with a misspelled table: its own reader
  // names the unknown key at its line ("[planfrom]" was "not a wing file ... nor a case file"
  // at line 1).
  for (const char* key : {"membrane", "materials", "veins", "mesh", "surface"})
    if (root.has(key)) (void)wings::read_wing(root);
  for (const char* key : {"wing", "chain", "air", "structure", "numerics", "output", "loads", "markers"})
    if (root.has(key)) (void)io::read_case(root);
  throw InputError(path, 1, "",
                   "not a wing file (no [planform] table) nor a case file (no [kinematics] table)");
}

}  // namespace

void add_check_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "check",
      "Check a wing or case file and print its summary.\n"
      "A wing file (it has a [planform] table) prints span, area, mean chord S/R,\n"
      "aspect ratio R^2/S, r2/R, the number of veins and the estimated mass.\n"
      "A case file (it has a [kinematics] table) prints sweep, deviation, rotation and\n"
      "the geometric angle of attack at phases 0, 0.25, 0.5, 0.75 (in a free stream also\n"
      "the angle and speed of the air at r2 of the span), then air, structure\n"
      "and numerics, and checks the wing file it names.\n"
      "Check validates what run and mesh would: the chain file, a wing for a run in air,\n"
      "loads and markers on existing bodies, the wing meshed by gmsh (no file written), the\n"
      "mesh-size budget, and the run's estimate (memory, ParaView frames on disk, interactions, time) "
      "against the memory.\n"
      "For a flexible case it builds the chain as run does (from --chain, the case's 'chain', or\n"
      "the wing reduced in process) and warns about a chain that does not match the wing, one\n"
      "driven above or near its resonance (docs/case_file.md, \"Warnings\").\n"
      "--kinematics FILE writes the case's kinematics over one wingbeat (angles, rates and\n"
      "accelerations at the run's steps) to a CSV file, to plot beside a measured wingbeat.\n"
      "Exit status: 0 valid, 2 bad input (the message names file, line and key), 3 a numerical\n"
      "failure of the FEM or the reduction of a wing reduced in process (as run), 4 --kinematics\n"
      "not written.\n"
      "Formats: docs/wing_file.md, docs/case_file.md.");
  auto file = std::make_shared<std::string>();
  auto chain = std::make_shared<std::string>();
  auto wing = std::make_shared<std::string>();
  cmd->add_option("FILE", *file, "wing or case file (TOML)")->required();
  cmd->add_option("--chain", *chain, "for a case: the chain file run --chain would use (overrides the case's 'chain')")
      ->check(non_empty_option());
  cmd->add_option("--wing", *wing,
                  "for a case: the wing file run --wing would fly (overrides the case's 'wing')")
      ->check(non_empty_option());
  auto kinematics = std::make_shared<std::string>();
  cmd->add_option(
         "--kinematics", *kinematics,
         "for a case: write the wing base's angles, rates and accelerations over one wingbeat at the "
         "run's steps to this CSV file (docs/case_file.md, \"Measured kinematics\")")
      ->check(non_empty_option());
  cmd->callback([file, chain, wing, kinematics] {
    check_chain_option(*chain);
    std::cout << check_file(*file, *chain, *wing, *kinematics) << std::flush;
  });
}

}  // namespace flapsim::cli
