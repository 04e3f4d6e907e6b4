#pragma once
/// \file svg_numbers.hpp
/// \brief Numbers as SVG writes them in path data, point lists and transforms (SVG 1.1,
/// 8.3.9: "1.5.5" is 1.5 and .5, "1-2" is 1 and −2, separators optional), and the error of
/// a bad attribute, which the drawing's reader names by file and line
/// (wings/loader/svg_drawing.hpp).

#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string_view>

namespace flapsim::wings {

/// A syntax error in one attribute's value (path data, a transform, a length).
struct SvgSyntaxError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Reads the numbers of an attribute's value one by one.
class NumberScanner {
 public:
  explicit NumberScanner(std::string_view s) : s_(s) {}
  void skip_separators() {
    while (i_ < s_.size() && (std::isspace(static_cast<unsigned char>(s_[i_])) || s_[i_] == ',')) ++i_;
  }
  bool at_end() {
    skip_separators();
    return i_ >= s_.size();
  }
  std::size_t position() const { return i_; }
  char peek() {
    skip_separators();
    return i_ < s_.size() ? s_[i_] : '\0';
  }
  void advance() { ++i_; }
  std::optional<double> number() {
    skip_separators();
    std::size_t j = i_;
    if (j < s_.size() && (s_[j] == '+' || s_[j] == '-')) ++j;
    const std::size_t digits_from = j;
    while (j < s_.size() && std::isdigit(static_cast<unsigned char>(s_[j]))) ++j;
    if (j < s_.size() && s_[j] == '.') {
      ++j;
      while (j < s_.size() && std::isdigit(static_cast<unsigned char>(s_[j]))) ++j;
    }
    if (j == digits_from || (j == digits_from + 1 && s_[digits_from] == '.')) return std::nullopt;
    if (j < s_.size() && (s_[j] == 'e' || s_[j] == 'E')) {
      std::size_t k = j + 1;
      if (k < s_.size() && (s_[k] == '+' || s_[k] == '-')) ++k;
      if (k < s_.size() && std::isdigit(static_cast<unsigned char>(s_[k]))) {
        while (k < s_.size() && std::isdigit(static_cast<unsigned char>(s_[k]))) ++k;
        j = k;
      }
    }
    const std::size_t from = s_[i_] == '+' ? i_ + 1 : i_;  // from_chars takes no '+'
    double v = 0.0;
    const auto r = std::from_chars(s_.data() + from, s_.data() + j, v);
    if (r.ec != std::errc() || !std::isfinite(v)) return std::nullopt;
    i_ = j;
    return v;
  }
  // An arc's flag: one character, 0 or 1, with or without a separator after it.
  std::optional<bool> flag() {
    const char c = peek();
    if (c != '0' && c != '1') return std::nullopt;
    ++i_;
    return c == '1';
  }

 private:
  std::string_view s_;
  std::size_t i_ = 0;
};

}  // namespace flapsim::wings
