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

  /// An error relayed by its text alone (an optimisation's start that failed on another
  /// rank or thread): what() is \p what as it was, not located again ("<input>: <input>: …").
  static InputError relayed(const std::string& what) { return InputError(Relayed{}, what); }

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& key() const { return key_; }
  const std::string& message() const { return message_; }

 private:
  struct Relayed {};
  InputError(Relayed, const std::string& what) : std::runtime_error(what), line_(0), message_(what) {}

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

/// Bad input in a value that was not written in the file but set over it (a sweep's
/// `--vary` or `--cases` value; wings::TomlTable::apply_overrides): the file names no line
/// for it, so the message says where it came from, and a caller that knows the value's
/// own source (a row of a case table) can name that instead.
class OverrideInputError : public InputError {
 public:
  /// \param key           the dotted key the problem concerns (the override's, or a table on its path)
  /// \param detail        what is wrong, without the note on the override
  /// \param override_key  the dotted key of the override it concerns
  OverrideInputError(std::string file, std::string key, const std::string& detail, std::string override_key)
      : InputError(std::move(file), 0, std::move(key), detail + " (value given as an override)"),
        detail_(detail), override_key_(std::move(override_key)) {}

  const std::string& detail() const { return detail_; }
  const std::string& override_key() const { return override_key_; }
  /// Whether the problem is the key's name, not its value: an unknown key or table on its
  /// path, a path through a value that is not a table, text that is not a TOML value.
  bool concerns_the_key() const {
    return key() != override_key_ || detail_.rfind("unknown key", 0) == 0 || detail_.rfind("override:", 0) == 0;
  }

 private:
  std::string detail_;
  std::string override_key_;
};

}  // namespace flapsim
