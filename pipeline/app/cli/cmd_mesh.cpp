// flapsim mesh WING.toml -o DIR: mesh a wing with gmsh (veins fragmented into
// the membrane) and write DIR/mesh.msh and DIR/mesh.vtu.
#include "pipeline/app/cli/commands.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "fem/wing_mesher.hpp"
#include "pipeline/io/fem_vtk.hpp"
#include "pipeline/io/atomic_file.hpp"
#include "wings/wing_file.hpp"

namespace flapsim::cli {

namespace {

struct MeshArgs {
  std::string wing_file;
  std::string out_dir = "out";
};

void run_mesh(const MeshArgs& args) {
  // 1. Read and check the wing (InputError: exit 2, nothing written).
  const wings::Wing wing = wings::load_wing_file(args.wing_file);
  print_wing_warnings(wing);
  // 2. Mesh; gmsh saves mesh.msh (atomically) on the way.
  const std::filesystem::path dir(args.out_dir);
  io::ensure_directory(dir);
  fem::MeshOptions opt;
  opt.msh_path = dir / "mesh.msh";
  const fem::Mesh mesh = fem::mesh_wing(wing, opt);
  // 3. The same mesh for ParaView.
  io::write_vtu(dir / "mesh.vtu", io::fem_unstructured_mesh(mesh, wing.clamp_y));
  std::printf("%s: %d nodes, %zu membrane triangles, %zu vein elements (%zu veins)\n", wing.name.c_str(),
              mesh.num_nodes(), mesh.triangles.size(), mesh.beams.size(), mesh.vein_names.size());
  std::printf("wrote %s, %s\n", (dir / "mesh.msh").string().c_str(), (dir / "mesh.vtu").string().c_str());
}

}  // namespace

void add_mesh_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "mesh",
      "Mesh a wing for the FEM: the outline as a membrane surface, the veins as beam\n"
      "elements sharing its nodes (gmsh). Sizes from the wing file's [mesh] table.\n"
      "Writes DIR/mesh.msh (gmsh) and DIR/mesh.vtu (ParaView; cell data 'vein', point\n"
      "data 'clamped'). Exit status: 0 ok, 2 bad input.");
  auto args = std::make_shared<MeshArgs>();
  cmd->add_option("WING", args->wing_file, "wing file (TOML)")->required();
  cmd->add_option("-o,--output", args->out_dir, "output directory")->capture_default_str();
  cmd->callback([args] { run_mesh(*args); });
}

}  // namespace flapsim::cli
