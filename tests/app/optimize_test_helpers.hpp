#pragma once
// Helpers of the optimize tests: the shipped rigid rotation-phase case shortened, and a
// value of summary.json.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace flapsim::test {

// cases/<name>.toml with `steps` steps per cycle and `cycles` cycles (rotation_phase_rigid:
// 100 and 4; rotation_phase_flexible: 100 and 6), its wing by absolute path, no VTK.
// Everything else as shipped; empty when the shipped case no longer has those keys.
inline std::string shortened_case(const std::string& name, int steps, int cycles) {
  std::ifstream in(std::string(FLAPSIM_SOURCE_DIR) + "/cases/" + name + ".toml");
  std::stringstream s;
  s << in.rdbuf();
  std::string text = s.str();
  const auto replace = [&text](const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    if (at == std::string::npos) return false;
    text.replace(at, from.size(), to);
    return true;
  };
  const bool ok = replace("\nsteps_per_cycle = 100", "\nsteps_per_cycle = " + std::to_string(steps)) &&
                  (replace("\ncycles = 4", "\ncycles = " + std::to_string(cycles)) ||
                   replace("\ncycles = 6", "\ncycles = " + std::to_string(cycles))) &&
                  replace("wing = \"../wings/hawkmoth.toml\"",
                          "wing = \"" + std::string(FLAPSIM_SOURCE_DIR) + "/wings/hawkmoth.toml\"");
  replace("vtk_every = 10", "vtk_every = 0");
  return ok ? text : std::string();
}

// The value of a key of a summary.json text ("" if absent).
inline std::string summary_value(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\": ");
  if (at == std::string::npos) return "";
  const auto begin = at + key.size() + 4;
  return json.substr(begin, json.find_first_of(",\n", begin) - begin);
}

}  // namespace flapsim::test
