#include "pipeline/cli/commands.hpp"

#include <CLI/CLI.hpp>

#include <stdexcept>

namespace flapsim::cli {

void add_sweep_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("sweep", "(under construction)");
  cmd->callback([] { throw std::runtime_error("'flapsim sweep' is not available yet"); });
}

}  // namespace flapsim::cli
