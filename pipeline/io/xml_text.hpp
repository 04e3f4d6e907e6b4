#pragma once
// Text for XML files (the .pvd series and the ParaView state): one escaping rule for both.

#include <string>

namespace flapsim::io {

/// \brief \p text with &, <, > and " replaced by their entities, for an XML attribute value.
inline std::string xml_attribute(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace flapsim::io
