#pragma once
/// \file svg_xml_tags.hpp
/// \brief The start and end tags of an SVG file with their attributes and lines: as much of
/// XML as the drawing's reader needs (wings/loader/svg_drawing.hpp). Comments, CDATA, processing
/// instructions and a DOCTYPE (with its internal subset) are skipped, text between tags is
/// ignored, entities in attribute values are decoded (&amp; &lt; &gt; &quot; &apos; and
/// numeric ones); an "svg:" prefix of a name is dropped. Malformed markup is an
/// flapsim::InputError naming the file and line.

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace flapsim::wings {

/// One tag.
struct SvgTag {
  std::string name;  ///< without an "svg:" prefix
  std::vector<std::pair<std::string, std::string>> attributes;
  bool closing = false, self_closing = false;  ///< </name>, <name ... />
  int line = 0;                                ///< of its '<' (1-based)
  /// The value of an attribute (entities decoded), nullptr if it has none.
  const std::string* attribute(std::string_view key) const {
    for (const auto& [k, v] : attributes)
      if (k == key) return &v;
    return nullptr;
  }
};

/// Reads the tags of a text one by one.
class SvgTagReader {
 public:
  /// \param file, key  name the file and the wing file's key in messages
  SvgTagReader(std::string_view text, std::string file, std::string key)
      : t_(text), file_(std::move(file)), key_(std::move(key)) {}
  /// The next start or end tag; false at the end of the text.
  /// \throws flapsim::InputError for malformed markup
  bool next(SvgTag& tag);

 private:
  [[noreturn]] void fail(int line, const std::string& what) const;
  void count_lines(std::size_t to);
  void skip_past(std::string_view end, const char* what);
  void read_tag(SvgTag& tag);

  std::string_view t_;
  std::string file_, key_;
  std::size_t i_ = 0, counted_ = 0;
  int line_ = 1;
};

}  // namespace flapsim::wings
