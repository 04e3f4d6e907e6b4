#pragma once
// Running the flapsim program as a user does (tests of the command line).

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace flapsim::test {

/// Runs `flapsim ARGS` (the program built with the tests) without progress lines and
/// with one OpenMP thread; stdout and stderr are discarded. Returns the exit status
/// (-1 if the program did not exit normally).
/// With \p stdout_file, the program's stdout goes there instead.
inline int run_flapsim(const std::string& args, const std::filesystem::path& stdout_file = "/dev/null") {
  const std::string cmd = "FLAPSIM_QUIET=1 OMP_NUM_THREADS=1 '" + std::string(FLAPSIM_BINARY) + "' " +
                          args + " > '" + stdout_file.string() + "' 2> /dev/null";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// The exit status of a flapsim command (-1 if it did not exit normally) and its stderr.
struct FlapsimOutcome {
  int status = -1;
  std::string err;
};

/// Runs `flapsim ARGS` as run_flapsim does, its stderr written to DIR/stderr.txt and returned.
inline FlapsimOutcome run_flapsim_capturing_stderr(const std::filesystem::path& dir, const std::string& args) {
  const std::filesystem::path err_file = dir / "stderr.txt";
  const std::string cmd = "FLAPSIM_QUIET=1 OMP_NUM_THREADS=1 '" + std::string(FLAPSIM_BINARY) + "' " + args +
                          " > /dev/null 2> '" + err_file.string() + "'";
  const int status = std::system(cmd.c_str());
  std::ifstream in(err_file);
  std::stringstream text;
  text << in.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

/// Runs `PREFIX flapsim ARGS` in /bin/sh (e.g. PREFIX "ulimit -f 8; exec"); as run_flapsim.
inline int run_flapsim_in_shell(const std::string& prefix, const std::string& args) {
  const std::string cmd = "FLAPSIM_QUIET=1 OMP_NUM_THREADS=1; export FLAPSIM_QUIET OMP_NUM_THREADS; " + prefix +
                          " '" + std::string(FLAPSIM_BINARY) + "' " + args + " > /dev/null 2> /dev/null";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// The number after "KEY": in a JSON text such as summary.json (NaN if the key is absent).
inline double json_number(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\": ");
  if (at == std::string::npos) return std::nan("");
  return std::strtod(json.c_str() + at + key.size() + 4, nullptr);
}

/// The whole text of a file ("" if it cannot be read).
inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace flapsim::test
