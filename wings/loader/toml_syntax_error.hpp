#pragma once
/// \file toml_syntax_error.hpp
/// \brief What the line of a TOML syntax error says, for the error message: the key written
/// there (with its table: "kinematics.frequency_hz"; the key of the value a multi-line
/// array continues) and a hint for the two mistakes a user makes most, a number with its
/// unit (`frequency_hz = 25Hz`) and a text without quotes (`kind = flexible`). The parser
/// (toml++) names only the line and what it expected.

#include <string>
#include <string_view>

namespace flapsim::wings {

struct SyntaxErrorContext {
  std::string key;   ///< dotted key of the value on that line ("" for a table header or unknown)
  std::string hint;  ///< "" or a sentence on the mistake the value shows
};

/// \param text  the whole file
/// \param line  the error's line, 1-based
SyntaxErrorContext syntax_error_context(std::string_view text, int line);

}  // namespace flapsim::wings
