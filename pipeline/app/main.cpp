// flapsim command-line entry point; see `flapsim --help` and README.md.
#include "pipeline/app/cli/commands.hpp"
#include "pipeline/app/cli/thread_options.hpp"

int main(int argc, char** argv) {
  flapsim::cli::use_passive_omp_wait_policy(argv);  // before OpenMP starts (docs/performance.md)
  return flapsim::cli::run(argc, argv);
}
