#include "wings/loader/toml_preflight.hpp"

#include "wings/loader/input_error.hpp"

namespace flapsim::wings {

namespace {

/// A recursive-descent walk over TOML's structure (TOML 1.0.0, as toml++ 3.x reads it
/// without its unreleased features). Each function returns false where toml++ reports a
/// syntax error: the walk ends there, since toml++ reads nothing after its first error.
class Preflight {
 public:
  Preflight(std::string_view text, const std::string& file) : s_(text), file_(file) {}

  void document() {
    if (s_.substr(0, 3) == "\xEF\xBB\xBF") p_ = 3;  // a UTF-8 byte-order mark
    while (!eof()) {
      skip_spaces();
      if (eof()) return;
      const char c = s_[p_];
      if (c == '\n' || c == '\r') {
        if (!line_break()) {
          stop();
          return;
        }
      } else if (c == '#') {
        skip_comment();
      } else if (c == '[') {
        if (!table_header()) return;  // (table_header stopped)
      } else if (key_start(c)) {
        if (!key_value() || !end_of_statement()) return;
      } else {
        stop();  // toml++: "expected keys, tables, whitespace or comments"
        return;
      }
    }
  }

 private:
  bool eof() const { return p_ >= s_.size(); }
  char at(std::size_t k) const { return p_ + k < s_.size() ? s_[p_ + k] : '\0'; }

  static bool bare_key_char(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
  }
  static bool key_start(char c) { return bare_key_char(c) || c == '"' || c == '\''; }

  [[noreturn]] void refuse(const std::string& what) const {
    throw InputError(file_, line_, "", "TOML syntax error: " + what);
  }

  static bool non_ascii(char c) { return static_cast<unsigned char>(c) >= 0x80; }

  /// Where toml++ reports an error: the walk ends (false). toml++ 3.3 first asks whether
  /// the character there is whitespace, and for U+00A1-U+049A and U+FB26-U+FEFE that
  /// question itself is undefined behaviour (an unreachable branch in
  /// is_non_ascii_horizontal_whitespace): TOML allows non-ASCII characters only in
  /// strings and comments, so one here is refused.
  bool stop() const {
    if (!eof() && non_ascii(s_[p_])) refuse("a non-ASCII character outside a string or comment");
    return false;
  }

  /// The UTF-8 encodings of U+0085, U+2028 and U+2029, which toml++ counts as line
  /// breaks that end a value but does not accept as line breaks between values.
  bool unicode_line_separator_here() const {
    return s_.substr(p_, 2) == "\xC2\x85" || s_.substr(p_, 3) == "\xE2\x80\xA8" ||
           s_.substr(p_, 3) == "\xE2\x80\xA9";
  }

  /// Spaces and tabs; true if there were any.
  bool skip_spaces() {
    const std::size_t start = p_;
    while (!eof() && (s_[p_] == ' ' || s_[p_] == '\t')) ++p_;
    return p_ > start;
  }

  /// "\n" or "\r\n" (a lone '\r' is toml++'s error).
  bool line_break() {
    if (at(0) == '\r') {
      if (at(1) != '\n') return stop();
      ++p_;
    }
    if (at(0) != '\n') return stop();
    ++p_;
    ++line_;
    return true;
  }

  /// From '#' to (not including) the line break.
  void skip_comment() {
    while (!eof() && s_[p_] != '\n' && s_[p_] != '\r') ++p_;
  }

  /// After a key-value pair or a header: spaces, then a comment, a line break or the end.
  bool end_of_statement() {
    skip_spaces();
    if (eof()) return true;
    if (s_[p_] == '#') {
      skip_comment();
      return true;
    }
    return s_[p_] == '\n' || s_[p_] == '\r' || stop();
  }

  /// "[name]" or "[[name]]" at the start of a statement.
  bool table_header() {
    ++p_;  // '['
    const bool spaced = skip_spaces();
    if (eof()) return stop();
    bool array_of_tables = false;
    if (s_[p_] == '[') {
      if (spaced) return stop();  // toml++: "[ [" is an error of its own
      array_of_tables = true;
      ++p_;
      skip_spaces();
      if (eof()) return stop();
    }
    const char c = s_[p_];
    if (c == ']') return stop();  // toml++: "tables with blank bare keys"
    if (!key_start(c)) {
      if (c == '\n' || c == '\r')
        refuse(std::string("\"") + (array_of_tables ? "[[" : "[") + "\" at the end of a line (a table header needs a name)");
      if (c == '[') refuse("\"[[[\" (a table header needs a name)");
      const bool printable = static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7f;
      refuse(printable ? std::string("a table header cannot start with '") + c + "'"
                       : std::string("a table header must start with a key (a letter, digit, '_', '-' or a quote)"));
    }
    if (!key()) return stop();
    skip_spaces();
    if (at(0) != ']') return stop();
    ++p_;
    if (array_of_tables) {
      if (at(0) != ']') return stop();
      ++p_;
    }
    return end_of_statement();
  }

  /// A dotted key: bare or quoted (single-line) segments joined by '.'.
  bool key() {
    for (;;) {
      if (eof()) return stop();
      const char c = s_[p_];
      if (bare_key_char(c)) {
        while (!eof() && bare_key_char(s_[p_])) ++p_;
      } else if (c == '"' || c == '\'') {
        if (at(1) == c && at(2) == c) {  // toml++ reads the string, then refuses it in a key
          string_value();
          return false;
        }
        if (!string_value()) return stop();
      } else {
        return stop();
      }
      skip_spaces();
      if (eof() || s_[p_] != '.') return true;
      ++p_;
      skip_spaces();
    }
  }

  /// key = value
  bool key_value() {
    if (!key()) return stop();
    skip_spaces();
    if (at(0) != '=') return stop();
    ++p_;
    skip_spaces();
    if (eof() || ends_value(s_[p_]) || unicode_line_separator_here()) return stop();  // "expected value"
    return value();
  }

  static bool ends_value(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f' || c == ']' || c == '}' ||
           c == ',' || c == '#';
  }

  bool value() {
    // toml++ refuses values nested deeper than 256 (TOML_MAX_NESTED_VALUES); the walk
    // stops a little deeper, where toml++ has certainly stopped, and bounds its stack.
    struct Depth {
      int& d;
      explicit Depth(int& depth) : d(++depth) {}
      ~Depth() { --d; }
    } depth(depth_);
    if (depth_ > kMaxDepth) return stop();
    const char c = s_[p_];
    if (c == '"' || c == '\'') return string_value();
    if (c == '[') return array();
    if (c == '{') return inline_table();
    // toml++ starts a number with a digit, a sign or '.', a boolean with t or f, inf and
    // nan with i or n (either case); anything else is its "expected value" error.
    const bool scalar_start = (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.' || c == 't' || c == 'T' ||
                              c == 'f' || c == 'F' || c == 'i' || c == 'I' || c == 'n' || c == 'N';
    if (!scalar_start) return stop();
    if (date_then_lone_digit())
      refuse(
          "a date (or a value shaped like one: 10 characters, '-' at 5 and 8), a space and a single digit "
          "(a date-time needs a full time: 1979-05-27 07:32:00)");
    // A number, boolean, date or time: one line without ',', ']', '}' or '#', so it ends
    // at the first of these or a line break (a date and a time may be joined by a space).
    while (!eof()) {
      const char d = s_[p_];
      if (d == ',' || d == ']' || d == '}' || d == '#' || d == '\n' || d == '\r') break;
      if (non_ascii(d)) return stop();  // toml++ asks of each character whether it ends the value
      ++p_;
    }
    return true;
  }

  /// True where toml++ 3.3 takes a value for a date and a time joined by a space, reads
  /// one digit after the space and asserts (parse_value) on the terminator after it (e.g.
  /// "1979-05-27 0\n"). Its test, mirrored here: the token up to the first terminator,
  /// underscores left out (at most 127 characters read), is 10 characters long, starts with
  /// a digit, has '-' at 4 and 7, and of the "traits" toml++ notes while reading it has
  /// only digits and '-'. A letter other than b, e, o, p, t, x, z notes nothing, nor do
  /// characters such as '!', ';' or a control character, so "0----!----" and "0aaa-bb-cc"
  /// pass the test too (found by a coverage-guided fuzzer, 5 Dec); b, o and x note one only
  /// as the second character of a token starting with '0', e only before a '-' (p only after
  /// such an x, which has noted one already).
  bool date_then_lone_digit() const {
    std::size_t k = p_, read = 0;
    if (k >= s_.size() || !(s_[k] >= '0' && s_[k] <= '9')) return false;
    const bool begins_zero = s_[k] == '0';
    std::string chars;
    bool other_trait = false, has_minus = false;
    while (k < s_.size() && !ends_value(s_[k])) {
      const char c = s_[k++];
      if (non_ascii(c)) return false;   // value() refuses it (toml++ would ask whether it ends the value)
      if (++read >= 128) return false;  // toml++ reads no further: no space follows
      if (c == '_') continue;
      chars += c;
      const std::size_t n = chars.size();
      const char lower = static_cast<char>(c | 0x20);
      if (c >= '0' && c <= '9') continue;
      if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z')) {
        if (((lower == 'b' || lower == 'o' || lower == 'x') && n == 2 && begins_zero) || lower == 't' ||
            lower == 'z' || (lower == 'e' && n > 1 && !has_minus))
          other_trait = true;
        continue;
      }
      if (c == '-')
        has_minus = true;
      else if (c == '+' || c == '.' || c == ':')
        other_trait = true;
    }
    if (chars.size() != 10 || other_trait || chars[4] != '-' || chars[7] != '-') return false;
    const auto digit = [&](std::size_t i) { return i < s_.size() && s_[i] >= '0' && s_[i] <= '9'; };
    return k + 2 < s_.size() && s_[k] == ' ' && digit(k + 1) && (ends_value(s_[k + 2]) || non_ascii(s_[k + 2]));
  }

  /// Basic or literal, single- or multi-line.
  bool string_value() {
    const char q = s_[p_];
    const bool basic = q == '"';
    if (at(1) == q && at(2) == q) {  // multi-line
      p_ += 3;
      while (!eof()) {
        const char c = s_[p_];
        if (basic && c == '\\') {
          ++p_;
          if (eof()) return stop();
          if (s_[p_] == ' ' || s_[p_] == '\t' || s_[p_] == '\r' || s_[p_] == '\n') {
            // A line-ending backslash: the whitespace up to the next text is dropped.
            // toml++ 3.3 asks of that text's first character whether it is whitespace
            // (undefined for some non-ASCII ones; see stop()).
            skip_spaces();
            if (!line_break()) return stop();
            while (skip_spaces() || at(0) == '\n' || (at(0) == '\r' && at(1) == '\n'))
              if (!eof() && (s_[p_] == '\n' || s_[p_] == '\r')) line_break();
            if (!eof() && non_ascii(s_[p_]))
              refuse("a non-ASCII character right after a line-ending backslash (write it on the backslash's line)");
            continue;
          }
          if (non_ascii(s_[p_])) refuse("a backslash before a non-ASCII character in a string");
          ++p_;
          continue;
        }
        if (c == q && at(1) == q && at(2) == q) {
          p_ += 3;
          for (int extra = 0; extra < 2 && at(0) == q; ++extra) ++p_;  // up to two quotes end the content
          return true;
        }
        if (c == '\n') ++line_;
        ++p_;
      }
      return stop();
    }
    ++p_;
    while (!eof()) {
      const char c = s_[p_];
      if (c == '\n' || c == '\r') return stop();
      if (basic && c == '\\') {
        if (at(1) == '\n' || at(1) == '\r' || at(1) == '\0') return stop();
        p_ += 2;
        continue;
      }
      ++p_;
      if (c == q) return true;
    }
    return stop();
  }

  /// Spaces, line breaks and comments between array elements.
  bool skip_array_gap() {
    for (;;) {
      if (skip_spaces()) continue;
      if (eof()) return true;
      const char c = s_[p_];
      if (c == '\n' || c == '\r') {
        if (!line_break()) return stop();
      } else if (c == '#') {
        skip_comment();
      } else {
        return true;
      }
    }
  }

  bool array() {
    ++p_;  // '['
    bool after_value = false;
    for (;;) {
      if (!skip_array_gap() || eof()) return stop();
      const char c = s_[p_];
      if (c == ']') {
        ++p_;
        return true;
      }
      if (c == ',') {
        if (!after_value) return stop();
        after_value = false;
        ++p_;
        continue;
      }
      if (after_value) return stop();  // toml++: "expected comma or closing ']'"
      if (c == '}') refuse("'}' where an array element is expected");
      if (unicode_line_separator_here()) refuse("a Unicode line separator where an array element is expected");
      if (c == '\v' || c == '\f') return stop();
      if (!value()) return stop();
      after_value = true;
    }
  }

  /// { key = value, ... } on one line (TOML 1.0.0).
  bool inline_table() {
    ++p_;  // '{'
    enum { none, comma, pair } previous = none;
    for (;;) {
      skip_spaces();
      if (eof()) return stop();
      const char c = s_[p_];
      if (c == ',') {
        if (previous != pair) return stop();
        previous = comma;
        ++p_;
      } else if (c == '}') {
        if (previous == comma) return stop();
        ++p_;
        return true;
      } else if (key_start(c)) {
        if (previous == pair) return stop();
        previous = pair;
        if (!key_value()) return stop();
      } else {
        return stop();
      }
    }
  }

  static constexpr int kMaxDepth = 300;

  std::string_view s_;
  const std::string& file_;
  int depth_ = 0;
  std::size_t p_ = 0;
  int line_ = 1;
};

}  // namespace

void refuse_toml_the_parser_cannot_read_safely(std::string_view text, const std::string& file) {
  Preflight(text, file).document();
}

}  // namespace flapsim::wings
