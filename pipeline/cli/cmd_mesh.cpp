#include "pipeline/cli/commands.hpp"

#include <CLI/CLI.hpp>

#include <stdexcept>

namespace flapsim::cli {

void add_mesh_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("mesh", "(under construction)");
  cmd->callback([] { throw std::runtime_error("'flapsim mesh' is not available yet"); });
}

}  // namespace flapsim::cli
