// flapsim command-line entry point; see `flapsim --help` and README.md.
#include "pipeline/app/cli/baseline_math_library.hpp"
#include "pipeline/app/cli/commands.hpp"

int main(int argc, char** argv) {
  flapsim::cli::run_with_the_baseline_math_library(argv);  // the same bits on any x86-64 CPU
  return flapsim::cli::run(argc, argv);
}
