#include "pipeline/app/cli/thread_options.hpp"

#include "pipeline/app/cli/option_checks.hpp"

#include <CLI/CLI.hpp>
#include <omp.h>
#include <unistd.h>

#include <cstdlib>

namespace flapsim::cli {

namespace {
int g_threads = 0;  // 0: not given
}

void use_passive_omp_wait_policy(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr) return;
  if (setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
  execv("/proc/self/exe", argv);  // returns only on failure: keep going with the old policy
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
