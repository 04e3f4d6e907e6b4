#include "pipeline/app/sweep/summary_reader.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace flapsim::sweep {

namespace {

class Reader {
 public:
  explicit Reader(std::string_view t) : t_(t) {}
  void space() {
    while (i_ < t_.size() && (t_[i_] == ' ' || t_[i_] == '\n' || t_[i_] == '\r' || t_[i_] == '\t')) ++i_;
  }
  bool eat(char c) {
    space();
    if (i_ < t_.size() && t_[i_] == c) {
      ++i_;
      return true;
    }
    return false;
  }
  bool at_end() {
    space();
    return i_ == t_.size();
  }
  std::optional<std::string> string() {
    if (!eat('"')) return std::nullopt;
    std::string out;
    while (i_ < t_.size()) {
      char c = t_[i_++];
      if (c == '"') return out;
      if (c != '\\') {
        out += c;
        continue;
      }
      if (i_ >= t_.size()) return std::nullopt;
      c = t_[i_++];
      switch (c) {
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': {  // json_quote writes \u00XX for control characters only
          if (i_ + 4 > t_.size()) return std::nullopt;
          unsigned v = 0;
          if (std::from_chars(t_.data() + i_, t_.data() + i_ + 4, v, 16).ec != std::errc())
            return std::nullopt;
          out += static_cast<char>(v);
          i_ += 4;
          break;
        }
        default: out += c;
      }
    }
    return std::nullopt;
  }
  // The raw text of a scalar that is not a string (number, true, false, null).
  std::string_view token() {
    space();
    const std::size_t b = i_;
    while (i_ < t_.size() && t_[i_] != ',' && t_[i_] != '}' && t_[i_] != '\n' && t_[i_] != ' ') ++i_;
    return t_.substr(b, i_ - b);
  }
  bool peek_quote() {
    space();
    return i_ < t_.size() && t_[i_] == '"';
  }

 private:
  std::string_view t_;
  std::size_t i_ = 0;
};

std::optional<std::size_t> result_index(std::string_view key) {
  for (std::size_t i = 0; i < app::kRunResults.size(); ++i)
    if (app::kRunResults[i].key == key) return i;
  return std::nullopt;
}

template <typename T>
bool parse_exact(std::string_view s, T& v) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

}  // namespace

std::optional<app::RunResults> parse_summary_json(std::string_view text) {
  Reader in(text);
  app::RunResults results;
  if (!in.eat('{')) return std::nullopt;
  if (in.eat('}')) return in.at_end() ? std::optional(results) : std::nullopt;
  do {
    const auto key = in.string();
    if (!key || !in.eat(':')) return std::nullopt;
    const auto index = result_index(*key);
    if (in.peek_quote()) {
      auto s = in.string();
      if (!s) return std::nullopt;
      if (!index) continue;
      if (app::kRunResults[*index].kind != app::ResultKind::text) return std::nullopt;
      results.set_value(*index, std::move(*s));
      continue;
    }
    const std::string_view tok = in.token();
    if (tok.empty()) return std::nullopt;
    if (!index) continue;
    switch (app::kRunResults[*index].kind) {
      case app::ResultKind::number: {
        double v = std::numeric_limits<double>::quiet_NaN();
        if (tok != "null" && !parse_exact(tok, v)) return std::nullopt;
        results.set_value(*index, v);
        break;
      }
      case app::ResultKind::integer: {
        std::int64_t v = 0;
        if (!parse_exact(tok, v)) return std::nullopt;
        results.set_value(*index, v);
        break;
      }
      case app::ResultKind::flag:
        if (tok != "true" && tok != "false") return std::nullopt;
        results.set_value(*index, tok == "true");
        break;
      case app::ResultKind::text: return std::nullopt;
    }
  } while (in.eat(','));
  if (!in.eat('}') || !in.at_end()) return std::nullopt;
  return results;
}

std::optional<app::RunResults> read_summary_results(const std::filesystem::path& summary_json) {
  std::ifstream in(summary_json, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return parse_summary_json(text.str());
}

std::optional<app::RunResults> kept_results(const std::filesystem::path& summary_json,
                                            const std::string& inputs_hash) {
  auto results = read_summary_results(summary_json);
  if (!results || results->text("status") != "ok" || results->text("inputs_hash") != inputs_hash)
    return std::nullopt;
  return results;
}

}  // namespace flapsim::sweep
