// flapsim command-line entry point; see `flapsim --help` and README.md.
#include "pipeline/app/cli/commands.hpp"

int main(int argc, char** argv) { return flapsim::cli::run(argc, argv); }
