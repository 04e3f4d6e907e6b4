// --threads on every command, and the passive OpenMP wait policy (docs/performance.md).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <omp.h>

#include "common/run_flapsim.hpp"
#include "pipeline/app/cli/commands.hpp"
#include "pipeline/app/cli/thread_options.hpp"

namespace fs = std::filesystem;

namespace {

struct Output {
  int status = -1;
  std::string text;  // stdout and stderr
};

// Runs `ENV flapsim ARGS` and captures stdout and stderr together.
Output run_with_env(const std::string& env, const std::string& args) {
  const fs::path out = fs::temp_directory_path() / ("flapsim_threads_" + std::to_string(getpid()) + ".txt");
  const std::string cmd = "env -u OMP_WAIT_POLICY " + env + " FLAPSIM_QUIET=1 '" +
                          std::string(FLAPSIM_BINARY) + "' " + args + " > '" + out.string() + "' 2>&1";
  const int status = std::system(cmd.c_str());
  Output o{WIFEXITED(status) ? WEXITSTATUS(status) : -1, flapsim::test::read_text(out)};
  fs::remove(out);
  return o;
}

const std::string kCase = std::string(FLAPSIM_SOURCE_DIR) + "/cases/bench_hover.toml";

}  // namespace

TEST(ThreadsOption, EveryCommandTakesIt) {
  for (const char* command : {"check", "mesh", "modes", "reduce", "run", "sweep"}) {
    const Output o = run_with_env("", std::string(command) + " --help");
    EXPECT_EQ(o.status, 0) << command;
    EXPECT_NE(o.text.find("--threads"), std::string::npos) << command << " --help:\n" << o.text;
  }
  EXPECT_EQ(run_with_env("", "check '" + kCase + "' --threads 2").status, 0);
}

TEST(ThreadsOption, RefusesZeroAndNonNumbers) {
  // A usage error (exit 1), as every malformed option.
  EXPECT_EQ(run_with_env("", "check '" + kCase + "' --threads 0").status, 1);
  EXPECT_EQ(run_with_env("", "check '" + kCase + "' --threads two").status, 1);
}

TEST(ThreadsOption, SetsTheOpenMpThreadCount) {
  // In-process: after `flapsim check CASE --threads 3` OpenMP's parallel regions use 3
  // threads (omp_get_max_threads), whatever the count was before.
  omp_set_num_threads(1);
  std::string c = kCase;
  char a0[] = "flapsim", a1[] = "check", a3[] = "--threads", a4[] = "3";
  char* argv[] = {a0, a1, c.data(), a3, a4, nullptr};
  ASSERT_EQ(flapsim::cli::run(5, argv), 0);
  EXPECT_EQ(omp_get_max_threads(), 3);
  EXPECT_EQ(flapsim::cli::command_threads(), 3);
  omp_set_num_threads(1);
}

TEST(ThreadsOption, IdleThreadsSleep) {
  // GNU OpenMP shows its settings with OMP_DISPLAY_ENV=verbose; under the passive policy
  // its spin count is 0 (the default policy spins 300000 times before sleeping).
  const Output passive = run_with_env("OMP_DISPLAY_ENV=verbose", "check '" + kCase + "'");
  EXPECT_EQ(passive.status, 0);
  EXPECT_NE(passive.text.find("GOMP_SPINCOUNT = '0'"), std::string::npos) << passive.text;
  // A policy the user sets is kept.
  const Output active = run_with_env("OMP_DISPLAY_ENV=verbose OMP_WAIT_POLICY=active", "check '" + kCase + "'");
  EXPECT_EQ(active.status, 0);
  EXPECT_EQ(active.text.find("GOMP_SPINCOUNT = '0'"), std::string::npos) << active.text;
}
