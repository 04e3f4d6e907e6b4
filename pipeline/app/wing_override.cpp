#include "pipeline/app/wing_override.hpp"

#include <cstdio>
#include <filesystem>

namespace flapsim::app {

namespace {

// A TOML basic string of any text (TOML 1.0, "String"): quotes, backslashes and control
// characters escaped.
std::string toml_basic_string(const std::string& text) {
  std::string out = "\"";
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += ch;
    } else if (c < 0x20 || c == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04X", static_cast<unsigned>(c));
      out += escaped;
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

}  // namespace

std::pair<std::string, std::string> wing_file_override(const std::string& wing_file) {
  return {"wing", toml_basic_string(std::filesystem::absolute(wing_file).lexically_normal().string())};
}

}  // namespace flapsim::app
