#pragma once
// Sends a signal to a flapsim process in the middle of its work: the shared part of the
// SIGINT/SIGTERM tests of `run`, `sweep` and the model stages (docs/reliability.md).

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "robustness_helpers.hpp"

extern char** environ;

namespace flapsim::test {

/// Starts `flapsim ARGS`, polls `ready()` every `poll` until it is true (at most `timeout`),
/// waits `delay` more, sends `signal_number` and returns the exit status: -1 no normal exit,
/// -2 could not start, -3 ended before the signal, -4 still running `exit_within` after the
/// signal (then killed; 0: waited for however long it takes).
template <class Ready>
int signal_flapsim_when(const std::vector<std::string>& args, Ready ready, int signal_number,
                        std::chrono::milliseconds poll, std::chrono::seconds timeout,
                        std::chrono::milliseconds delay = std::chrono::milliseconds(0),
                        std::chrono::seconds exit_within = std::chrono::seconds(0)) {
  const std::string binary = FLAPSIM_BINARY;
  std::vector<char*> argv{const_cast<char*>(binary.c_str())};
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (::posix_spawn(&pid, binary.c_str(), nullptr, nullptr, argv.data(), environ) != 0) return -2;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  int status = 0;
  while (std::chrono::steady_clock::now() < deadline) {
    if (::waitpid(pid, &status, WNOHANG) == pid) return -3;
    if (ready()) break;
    std::this_thread::sleep_for(poll);
  }
  std::this_thread::sleep_for(delay);
  ::kill(pid, signal_number);
  if (exit_within.count() > 0) {
    const auto end = std::chrono::steady_clock::now() + exit_within;
    while (::waitpid(pid, &status, WNOHANG) != pid) {
      if (std::chrono::steady_clock::now() > end) {
        ::kill(pid, SIGKILL);
        ::waitpid(pid, &status, 0);
        return -4;
      }
      std::this_thread::sleep_for(poll);
    }
  } else {
    ::waitpid(pid, &status, 0);
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// Starts `flapsim ARGS` on one OpenMP thread, waits until `history` holds more than
/// `lines` lines (history.csv is published every 20 rows), sends `signal_number` and returns
/// the exit status as signal_flapsim_when.
inline int signal_flapsim_once_history_grows(const std::vector<std::string>& args,
                                             const std::filesystem::path& history, int signal_number,
                                             long lines = 21) {
  ::setenv("OMP_NUM_THREADS", "1", 1);
  const auto grown = [&] {
    const std::string h = read_text(history);
    return std::count(h.begin(), h.end(), '\n') > lines;
  };
  return signal_flapsim_when(args, grown, signal_number, std::chrono::milliseconds(20), std::chrono::seconds(120));
}

}  // namespace flapsim::test
