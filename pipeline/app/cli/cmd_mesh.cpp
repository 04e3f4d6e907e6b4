// flapsim mesh WING.toml -o DIR: mesh a wing with gmsh (veins fragmented into
// the membrane) and write DIR/mesh.msh and DIR/mesh.vtu.
#include "pipeline/app/cli/commands.hpp"
#include "pipeline/app/cli/option_checks.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <system_error>

#include <unistd.h>

#include "fem/mesh_quality.hpp"
#include "fem/wing_mesher.hpp"
#include "pipeline/app/stage_monitor.hpp"
#include "pipeline/io/fem_vtk.hpp"
#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/output_manifest.hpp"
#include "wings/loader/wing_file.hpp"

namespace flapsim::cli {

namespace {

struct MeshArgs {
  std::string wing_file;
  std::string out_dir = "out";
  bool force = false;
};

/// gmsh's file while it is checked and copied: in the system's temporary folder (the output
/// folder may not exist yet), removed however the command ends.
struct StagedGmshFile {
  std::filesystem::path path;
  StagedGmshFile() {
    std::error_code ec;
    const char* tmpdir = std::getenv("TMPDIR");
    const std::string named = tmpdir && *tmpdir ? tmpdir : "/tmp";
    const std::filesystem::path folder = std::filesystem::temp_directory_path(ec);
    if (ec)
      throw io::OutputError(named,
                            "the system's temporary folder (TMPDIR), for gmsh's file: " + ec.message());
    path = folder / ("flapsim_mesh." + std::to_string(static_cast<long>(::getpid())) + ".msh");
    // Writable, or gmsh's failure to save there read as a wing it cannot mesh (exit 2,
    // "check the outline") where the folder is at fault (exit 4).
    errno = 0;
    const bool writable = static_cast<bool>(std::ofstream(path) << "probe\n");
    const int error = errno;
    std::filesystem::remove(path, ec);
    if (!writable)
      throw io::OutputError(folder,
                            "the system's temporary folder (TMPDIR), for gmsh's file, is not writable: "
                            "cannot create '" +
                                path.filename().string() + "' there" +
                                (error ? " (" + std::string(std::strerror(error)) + ")" : std::string()) +
                                "; set TMPDIR to a writable folder");
  }
  StagedGmshFile(const StagedGmshFile&) = delete;
  StagedGmshFile& operator=(const StagedGmshFile&) = delete;
  ~StagedGmshFile() {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
  }
};

void run_mesh(const MeshArgs& args) {
  // 1. Read and check the wing (InputError: exit 2, nothing written).
  const wings::Wing wing = wings::load_wing_file(args.wing_file);
  print_wing_warnings(wing);
  // 2. The output folder, writable before any work (else exit 4 naming it); claimed once
  // the wing is meshed, so that a wing error the mesher finds (exit 2) leaves it as it was.
  const std::filesystem::path dir(args.out_dir);
  io::preflight_output_folder(dir, "mesh", args.force);
  io::OutputFolderClaim claim(dir, "mesh");
  // 3. Mesh; gmsh saves the mesh to a staging file in the system's temporary folder (with
  // the .msh extension gmsh needs), copied into the folder as mesh.msh only if complete
  // (gmsh does not report a failed write: the file must end with its $EndElements
  // section), flushed to disk and renamed.
  const StagedGmshFile staged;
  // SIGINT/SIGTERM: "interrupted" in the manifest, exit 130/143 at once; progress of a long mesh.
  app::StageMonitor::Options watch;
  watch.scratch_file = staged.path;
  app::StageMonitor monitor(claim, 2, watch);
  monitor.stage("meshing (gmsh)");
  fem::MeshOptions opt;
  opt.msh_path = staged.path;
  const fem::Mesh mesh = fem::mesh_wing(wing, opt);
  print_mesh_warnings(mesh, wing);
  claim.claim(args.force);
  const std::filesystem::path msh = dir / "mesh.msh";
  io::publish_file_atomically(
      msh,
      [&](const std::filesystem::path& tmp) {
        std::error_code ec;
        std::filesystem::copy_file(staged.path, tmp, std::filesystem::copy_options::overwrite_existing, ec);
        if (ec) throw io::OutputError(msh, "cannot copy gmsh's file: " + ec.message());
      },
      "$EndElements\n");
  // 4. The same mesh for ParaView.
  monitor.stage("writing the outputs");
  io::write_vtu(dir / "mesh.vtu", io::fem_unstructured_mesh(mesh, wing.clamp_y));
  std::printf("%s: %d nodes, %zu membrane triangles, %zu vein elements (%zu veins), smallest angle %.3g deg\n",
              wing.name.c_str(), mesh.num_nodes(), mesh.triangles.size(), mesh.beams.size(), mesh.vein_names.size(),
              fem::smallest_triangle_angle(mesh).degrees);
  claim.finish("complete");
  monitor.done();
  std::printf("wrote %s, %s\n", (dir / "mesh.msh").string().c_str(), (dir / "mesh.vtu").string().c_str());
}

}  // namespace

void add_mesh_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "mesh",
      "Mesh a wing for the FEM: the outline as a membrane surface, the veins as beam\n"
      "elements sharing its nodes (gmsh). Sizes from the wing file's [mesh] table.\n"
      "Writes DIR/mesh.msh (gmsh) and DIR/mesh.vtu (ParaView; cell data 'vein', point\n"
      "data 'clamped'). Exit status: 0 ok, 2 bad input (gmsh errors name the key),\n"
      "4 output error (nothing truncated is left under a final name), 130/143 interrupted by\n"
      "SIGINT/SIGTERM (at once; flapsim_outputs.toml says \"interrupted\").");
  auto args = std::make_shared<MeshArgs>();
  cmd->add_option("WING", args->wing_file, "wing file (TOML)")->required();
  cmd->add_option("-o,--output", args->out_dir, "output directory")->check(non_empty_option())->capture_default_str();
  cmd->add_flag("--force", args->force, "replace another command's outputs in the folder that this command would overwrite");
  cmd->callback([args] { run_mesh(*args); });
}

}  // namespace flapsim::cli
