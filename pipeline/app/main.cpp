// flapsim command-line entry point; see `flapsim --help` and README.md.
#include "pipeline/app/cli/baseline_math_library.hpp"
#include "pipeline/app/cli/commands.hpp"
#include "pipeline/app/cli/sequential_vtk.hpp"

int main(int argc, char** argv) {
  flapsim::cli::run_with_the_baseline_math_library(argv);  // the same bits on any x86-64 CPU
  flapsim::cli::run_vtk_on_the_calling_thread();
  return flapsim::cli::run(argc, argv);
}
