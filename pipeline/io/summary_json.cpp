#include "pipeline/io/summary_json.hpp"

#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/csv_writer.hpp"

#include <cmath>
#include <cstdio>

namespace flapsim::io {

std::string json_quote(std::string_view text) {
  std::string out = "\"";
  for (char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof(buf), "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

void SummaryJson::put(std::string_view key, Value value) {
  for (auto& [k, v] : items_)
    if (k == key) {
      v = std::move(value);
      return;
    }
  items_.emplace_back(std::string(key), std::move(value));
}

std::string SummaryJson::to_string() const {
  std::string out = "{";
  for (std::size_t i = 0; i < items_.size(); ++i) {
    out += i ? ",\n  " : "\n  ";
    out += json_quote(items_[i].first);
    out += ": ";
    const Value& v = items_[i].second;
    if (const double* d = std::get_if<double>(&v)) {
      out += std::isfinite(*d) ? format_number(*d) : "null";
    } else if (const std::int64_t* n = std::get_if<std::int64_t>(&v)) {
      out += std::to_string(*n);
    } else if (const std::string* s = std::get_if<std::string>(&v)) {
      out += json_quote(*s);
    } else {
      out += std::get<bool>(v) ? "true" : "false";
    }
  }
  out += items_.empty() ? "}\n" : "\n}\n";
  return out;
}

void SummaryJson::write(const std::filesystem::path& path) const {
  write_text_atomically(path, to_string());
}

}  // namespace flapsim::io
