#pragma once
/// \file input_warning.hpp
/// \brief A value that is accepted but implausible (a film thinner than 1 µm, a Young's
/// modulus of a few pascal): located like flapsim::InputError and naming the likely unit
/// mistake. Loaders collect them; the command line prints each on stderr as
/// "flapsim: warning: FILE:LINE: key 'KEY': MESSAGE" and carries on.

#include <string>

namespace flapsim {

struct InputWarning {
  std::string file;
  int line = 0;         ///< 1-based, 0 if unknown
  std::string key;      ///< dotted key, e.g. "membrane.thickness"
  std::string message;

  /// "FILE:LINE: key 'KEY': MESSAGE", as InputError::what().
  std::string text() const {
    std::string s(file.empty() ? "<input>" : file);  // appended only (input_error.hpp: GCC bug 105329)
    if (line > 0) s.append(":").append(std::to_string(line));
    s.append(": ");
    if (!key.empty()) s.append("key '").append(key).append("': ");
    s.append(message);
    return s;
  }
};

}  // namespace flapsim
