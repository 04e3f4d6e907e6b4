#pragma once
/// \file input_error.hpp
/// \brief The one error type for bad user input (wing files, case files, chain
/// files, command-line values). The CLI turns it into exit status 2.

#include <stdexcept>
#include <string>

namespace flapsim {

/// Bad input, located as precisely as known: file, line (1-based, 0 if unknown)
/// and the dotted key (e.g. "veins[2].diameter_mm"; empty if none).
/// what() reads "FILE:LINE: key 'KEY': MESSAGE".
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, std::string key, const std::string& message)
      : std::runtime_error(format(file, line, key, message)),
        file_(std::move(file)), line_(line), key_(std::move(key)), message_(message) {}

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& key() const { return key_; }
  const std::string& message() const { return message_; }

 private:
  static std::string format(const std::string& file, int line, const std::string& key,
                            const std::string& message) {
    // Built by appending only: GCC 12 warns (-Wrestrict, a false positive, GCC bug 105329)
    // about `"literal" + std::string&&` once this is inlined.
    std::string s;
    s.reserve(file.size() + key.size() + message.size() + 32);
    s.append(file.empty() ? "<input>" : file);
    if (line > 0) s.append(":").append(std::to_string(line));
    s.append(": ");
    if (!key.empty()) s.append("key '").append(key).append("': ");
    s.append(message);
    return s;
  }
  std::string file_;
  int line_;
  std::string key_;
  std::string message_;
};

}  // namespace flapsim
