#include "pipeline/cli/commands.hpp"

#include <CLI/CLI.hpp>

#include <stdexcept>

namespace flapsim::cli {

void add_reduce_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("reduce", "(under construction)");
  cmd->callback([] { throw std::runtime_error("'flapsim reduce' is not available yet"); });
}

}  // namespace flapsim::cli
