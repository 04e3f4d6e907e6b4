#include "pipeline/cli/commands.hpp"

#include <CLI/CLI.hpp>

#include <stdexcept>

namespace flapsim::cli {

void add_modes_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("modes", "(under construction)");
  cmd->callback([] { throw std::runtime_error("'flapsim modes' is not available yet"); });
}

}  // namespace flapsim::cli
