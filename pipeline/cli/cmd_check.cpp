#include "pipeline/cli/commands.hpp"

#include <CLI/CLI.hpp>

#include <stdexcept>

namespace flapsim::cli {

void add_check_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("check", "(under construction)");
  cmd->callback([] { throw std::runtime_error("'flapsim check' is not available yet"); });
}

}  // namespace flapsim::cli
