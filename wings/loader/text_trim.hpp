#pragma once
// Trimming of the text cells that the CSV readers (outline files, sweep case tables) split off,
// and the byte-order mark some programs put before a file's first line.

#include <string>

namespace flapsim::wings {

/// \brief \p s without leading and trailing spaces, tabs and carriage returns.
inline std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

/// \brief \p line without a leading UTF-8 byte-order mark (EF BB BF), which spreadsheet
/// programs write at the start of a "CSV UTF-8" file; it is invisible in an error message.
inline std::string without_byte_order_mark(const std::string& line) {
  return line.rfind("\xEF\xBB\xBF", 0) == 0 ? line.substr(3) : line;
}

}  // namespace flapsim::wings
