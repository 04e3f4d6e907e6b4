#include "pipeline/app/cli/thread_options.hpp"

#include "pipeline/app/cli/option_checks.hpp"

#include <CLI/CLI.hpp>
#include <omp.h>

namespace flapsim::cli {

namespace {
int g_threads = 0;  // 0: not given
}

void add_threads_option(CLI::App& command) {
  command
      .add_option_function<int>(
          "--threads",
          [](const int& n) {
            g_threads = n;
            omp_set_num_threads(n);
          },
          "threads to use (default: the available cores, or OMP_NUM_THREADS)")
      ->check(whole_number(1, kMaxThreads));
}

int command_threads() { return g_threads > 0 ? g_threads : omp_get_max_threads(); }

int requested_threads() { return g_threads; }

}  // namespace flapsim::cli
