#pragma once
/// \file summary_json.hpp
/// \brief A flat, ordered JSON object (key -> number, integer, string or bool) for
/// a run's summary.json, written atomically.

#include <concepts>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace flapsim::io {

class SummaryJson {
 public:
  using Value = std::variant<double, std::int64_t, std::string, bool>;

  /// \brief Sets \p key (keeps its first position if it was set before).
  /// Non-finite numbers are written as null (JSON has no NaN).
  void set(std::string_view key, double value) { put(key, Value(value)); }
  void set(std::string_view key, std::string_view value) { put(key, Value(std::string(value))); }
  void set(std::string_view key, const char* value) { put(key, Value(std::string(value))); }
  void set(std::string_view key, bool value) { put(key, Value(value)); }
  template <std::integral T>
    requires(!std::same_as<T, bool>)
  void set(std::string_view key, T value) {
    put(key, Value(static_cast<std::int64_t>(value)));
  }

  /// \brief The object as JSON text, one key per line, ending with a newline.
  std::string to_string() const;

  /// \brief Writes to_string() atomically.
  /// \throws OutputError
  void write(const std::filesystem::path& path) const;

  const std::vector<std::pair<std::string, Value>>& items() const { return items_; }

 private:
  void put(std::string_view key, Value value);
  std::vector<std::pair<std::string, Value>> items_;
};

/// \brief A JSON string literal (quoted, escaped) for \p text.
std::string json_quote(std::string_view text);

}  // namespace flapsim::io
