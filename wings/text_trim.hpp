#pragma once
// Trimming of the text cells that the CSV readers (outline files, sweep case tables) split off.

#include <string>

namespace flapsim::wings {

/// \brief \p s without leading and trailing spaces, tabs and carriage returns.
inline std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

}  // namespace flapsim::wings
