#pragma once
// The text of a shipped case file (cases/<name>.toml) with its wing path made absolute, so
// that a test can edit it and run it from a scratch folder.
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace flapsim::test {

inline std::string shipped_case_text(const std::string& name) {
  const std::string source = FLAPSIM_SOURCE_DIR;
  std::ifstream in(source + "/cases/" + name + ".toml");
  std::stringstream text;
  text << in.rdbuf();
  return std::regex_replace(text.str(), std::regex("wing = \"\\.\\./wings/"), "wing = \"" + source + "/wings/");
}

/// cases/hover.toml (the hawkmoth hover) as a rigid wing, 2 cycles, no ParaView output: the
/// case of the tests of what the lattice's inputs do to its lift. Its text is checked, so a
/// changed shipped case fails the test that uses it rather than run something else.
inline std::string rigid_hover_case_text() {
  std::string toml = shipped_case_text("hover");
  for (const auto& [from, to] :
       {std::pair<const char*, const char*>{"\nkind = \"flexible\"", "\nkind = \"rigid\""},
        {"\nbodies = 10", ""},
        {"\ncycles = 3", "\ncycles = 2"},
        {"\nvtk_every = 1", "\nvtk_every = 0"}}) {
    const auto at = toml.find(from);
    if (at == std::string::npos)
      throw std::runtime_error(std::string("cases/hover.toml has changed: no ") + from);
    toml.replace(at, std::string(from).size(), to);
  }
  return toml;
}

}  // namespace flapsim::test
