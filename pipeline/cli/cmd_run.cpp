#include "pipeline/cli/commands.hpp"

#include <CLI/CLI.hpp>

#include <stdexcept>

namespace flapsim::cli {

void add_run_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("run", "(under construction)");
  cmd->callback([] { throw std::runtime_error("'flapsim run' is not available yet"); });
}

}  // namespace flapsim::cli
