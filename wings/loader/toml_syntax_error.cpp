#include "wings/loader/toml_syntax_error.hpp"

#include <cctype>
#include <vector>

#include "wings/loader/text_trim.hpp"

namespace flapsim::wings {

namespace {

std::vector<std::string> split_lines(std::string_view text) {
  std::vector<std::string> lines;
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t end = text.find('\n', at);
    lines.emplace_back(text.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at));
    if (end == std::string_view::npos) break;
    at = end + 1;
  }
  return lines;
}

// The line without a comment and without the text of its strings (each string becomes ""),
// so that brackets inside them do not count.
std::string code_of(const std::string& line) {
  std::string out;
  char quote = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quote) {
      if (c == '\\' && quote == '"') ++i;
      else if (c == quote) {
        quote = 0;
        out += c;
      }
      continue;
    }
    if (c == '#') break;
    if (c == '"' || c == '\'') quote = c;
    out += c;
  }
  return out;
}

bool bare_key_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
}

// "key" of a line "key = value" (bare or dotted keys; spaces around dots allowed), "" if none.
std::string key_of(const std::string& code, std::string* value) {
  const std::string t = trim(code);
  const auto eq = t.find('=');
  if (eq == std::string::npos || eq == 0) return "";
  std::string key;
  for (char c : trim(t.substr(0, eq))) {
    if (c == ' ' || c == '\t') continue;
    if (!bare_key_char(c)) return "";
    key += c;
  }
  if (value) *value = trim(t.substr(eq + 1));
  return key;
}

std::string hint_for(const std::string& value) {
  if (value.empty()) return "";
  const unsigned char first = static_cast<unsigned char>(value[0]);
  // A number followed by letters: 25Hz, 0.05 mm, 4e9 Pa.
  if (std::isdigit(first) || ((first == '-' || first == '+' || first == '.') && value.size() > 1)) {
    std::size_t i = 0;
    while (i < value.size() && (std::isdigit(static_cast<unsigned char>(value[i])) || value[i] == '.' ||
                                value[i] == '-' || value[i] == '+' || value[i] == '_' ||
                                ((value[i] == 'e' || value[i] == 'E') && i > 0 &&
                                 std::isdigit(static_cast<unsigned char>(value[i - 1])))))
      ++i;
    std::size_t j = i;
    while (j < value.size() && value[j] == ' ') ++j;
    if (i > 0 && j < value.size() && (std::isalpha(static_cast<unsigned char>(value[j])) || value[j] == '%' ||
                                      static_cast<unsigned char>(value[j]) >= 0x80))
      return "a number takes no unit ('" + value + "'): write the number alone; the unit is in the key's name "
             "(_hz, _deg) or the file's length_unit, material constants are SI";
    return "";
  }
  // A text without quotes: flexible, mylar.
  if (std::isalpha(first)) {
    std::string word;
    for (char c : value) {
      if (!bare_key_char(c)) break;
      word += c;
    }
    if (word == "true" || word == "false" || word == "inf" || word == "nan") return "";
    return "a text value needs quotes: \"" + word + "\"";
  }
  return "";
}

}  // namespace

SyntaxErrorContext syntax_error_context(std::string_view text, int line) {
  SyntaxErrorContext out;
  const std::vector<std::string> lines = split_lines(text);
  if (line < 1 || line > static_cast<int>(lines.size())) return out;
  std::string table;      // the current [table] or [[array of tables]]
  std::string open_key;   // the key whose value is still open (a multi-line array or table)
  int depth = 0;          // brackets and braces open at the start of a line
  for (int n = 1; n <= line; ++n) {
    const std::string code = code_of(lines[static_cast<std::size_t>(n - 1)]);
    const std::string t = trim(code);
    std::string value;
    const std::string key = depth == 0 ? key_of(code, &value) : "";
    const bool header = depth == 0 && !t.empty() && t[0] == '[';  // [table] or [[array of tables]]
    std::string header_name;
    if (header) {
      std::string name = t.substr(t.rfind('[') + 1);
      name = name.substr(0, name.find(']'));
      for (char c : name)
        if (c != ' ' && c != '\t') header_name += c;
    }
    if (n == line) {
      if (depth > 0) out.key = open_key;
      else if (header) {
        if (t.find(']') != std::string::npos) out.key = header_name;  // e.g. a table defined twice
      }
      else if (!key.empty()) {
        out.key = table.empty() ? key : table + "." + key;
        out.hint = hint_for(value);
      }
      break;
    }
    if (header) {
      table = header_name;
      continue;
    }
    if (!key.empty()) open_key = table.empty() ? key : table + "." + key;
    for (char c : code) depth += (c == '[' || c == '{') ? 1 : (c == ']' || c == '}') ? -1 : 0;
    if (depth < 0) depth = 0;
  }
  return out;
}

}  // namespace flapsim::wings
