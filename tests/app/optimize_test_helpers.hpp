#pragma once
// Helpers of the optimize tests: the shipped rigid rotation-phase case shortened, and a
// value of summary.json.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace flapsim::test {

// cases/rotation_phase_rigid.toml with `steps` steps per cycle and `cycles` cycles (the
// shipped case: 100 and 4), its wing by absolute path, no VTK. Everything else as shipped.
inline std::string shortened_rotation_phase_case(int steps, int cycles) {
  std::ifstream in(std::string(FLAPSIM_SOURCE_DIR) + "/cases/rotation_phase_rigid.toml");
  std::stringstream s;
  s << in.rdbuf();
  std::string text = s.str();
  const auto replace = [&text](const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    if (at == std::string::npos) return false;
    text.replace(at, from.size(), to);
    return true;
  };
  const bool ok = replace("steps_per_cycle = 100", "steps_per_cycle = " + std::to_string(steps)) &&
                  replace("cycles = 4", "cycles = " + std::to_string(cycles)) &&
                  replace("wing = \"../wings/hawkmoth.toml\"",
                          "wing = \"" + std::string(FLAPSIM_SOURCE_DIR) + "/wings/hawkmoth.toml\"") &&
                  replace("vtk_every = 10", "vtk_every = 0");
  return ok ? text : std::string();  // empty: the shipped case changed; the test fails reading it
}

// The value of a key of a summary.json text ("" if absent).
inline std::string summary_value(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\": ");
  if (at == std::string::npos) return "";
  const auto begin = at + key.size() + 4;
  return json.substr(begin, json.find_first_of(",\n", begin) - begin);
}

}  // namespace flapsim::test
