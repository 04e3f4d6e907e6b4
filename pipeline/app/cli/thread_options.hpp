#pragma once
/// \file thread_options.hpp
/// \brief How many threads a command uses (--threads, on every command) and how idle
/// OpenMP threads wait (passive: they sleep instead of spinning, so a run on a busy
/// machine does not steal the cores its own threads or other programs need; set for every
/// program linking flapsim_app by libflapsim_omp_wait_policy.so, cli/passive_wait_policy.cpp).

namespace CLI { class App; }

namespace flapsim::cli {

/// Add `--threads N` to a subcommand: N ≥ 1 threads for the command (OpenMP threads of a
/// run; for a sweep, the threads shared by the cases it runs at once). Default: the
/// cores available to the process (OMP_NUM_THREADS if set).
void add_threads_option(CLI::App& command);

/// The largest --threads (and sweep -j) accepted.
constexpr long kMaxThreads = 4096;

/// The thread count in effect: --threads if given, else OpenMP's default.
int command_threads();

/// --threads if given, else 0.
int requested_threads();

}  // namespace flapsim::cli
