#pragma once
// The text of a shipped case file (cases/<name>.toml) with its wing path made absolute, so
// that a test can edit it and run it from a scratch folder.
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace flapsim::test {

inline std::string shipped_case_text(const std::string& name) {
  const std::string source = FLAPSIM_SOURCE_DIR;
  std::ifstream in(source + "/cases/" + name + ".toml");
  std::stringstream text;
  text << in.rdbuf();
  return std::regex_replace(text.str(), std::regex("wing = \"\\.\\./wings/"), "wing = \"" + source + "/wings/");
}

}  // namespace flapsim::test
