#include "wings/loader/svg_xml_tags.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>

#include "wings/loader/input_error.hpp"

namespace flapsim::wings {

namespace {

std::string decode_entities(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '&') {
      out += s[i];
      continue;
    }
    const std::size_t semi = s.find(';', i);
    if (semi == std::string_view::npos) {
      out += s[i];
      continue;
    }
    const std::string_view e = s.substr(i + 1, semi - i - 1);
    if (e == "amp")
      out += '&';
    else if (e == "lt")
      out += '<';
    else if (e == "gt")
      out += '>';
    else if (e == "quot")
      out += '"';
    else if (e == "apos")
      out += '\'';
    else if (!e.empty() && e[0] == '#') {
      unsigned long code = 0;
      const bool hex = e.size() > 1 && (e[1] == 'x' || e[1] == 'X');
      const std::string_view digits = e.substr(hex ? 2 : 1);
      std::from_chars(digits.data(), digits.data() + digits.size(), code, hex ? 16 : 10);
      out += code < 128 ? static_cast<char>(code) : '?';
    } else {
      out += std::string("&").append(e).append(";");
    }
    i = semi;
  }
  return out;
}

}  // namespace

void SvgTagReader::fail(int line, const std::string& what) const {
  throw InputError(file_, line, key_, what);
}

bool SvgTagReader::next(SvgTag& tag) {
  while (true) {
    const std::size_t lt = t_.find('<', i_);
    if (lt == std::string_view::npos) return false;
    count_lines(lt);
    i_ = lt;
    if (t_.compare(i_, 4, "<!--") == 0) {
      skip_past("-->", "a comment");
      continue;
    }
    if (t_.compare(i_, 9, "<![CDATA[") == 0) {
      skip_past("]]>", "a CDATA section");
      continue;
    }
    if (t_.compare(i_, 2, "<?") == 0) {
      skip_past("?>", "a processing instruction");
      continue;
    }
    if (t_.compare(i_, 2, "<!") == 0) {  // <!DOCTYPE ...>, with an internal subset in [ ]
      const std::size_t bracket = t_.find('[', i_), gt = t_.find('>', i_);
      if (bracket != std::string_view::npos && bracket < gt) {
        i_ = bracket;
        skip_past("]>", "a DOCTYPE");
      } else {
        skip_past(">", "a DOCTYPE");
      }
      continue;
    }
    read_tag(tag);
    return true;
  }
}

void SvgTagReader::count_lines(std::size_t to) {
  line_ += static_cast<int>(std::count(t_.begin() + static_cast<std::ptrdiff_t>(counted_),
                                       t_.begin() + static_cast<std::ptrdiff_t>(to), '\n'));
  counted_ = to;
}
void SvgTagReader::skip_past(std::string_view end, const char* what) {
  const std::size_t e = t_.find(end, i_);
  if (e == std::string_view::npos) fail(line_, std::string("malformed SVG: ") + what + " is not closed");
  i_ = e + end.size();
}
void SvgTagReader::read_tag(SvgTag& tag) {
  tag = SvgTag{};
  tag.line = line_;
  std::size_t j = i_ + 1;
  if (j < t_.size() && t_[j] == '/') {
    tag.closing = true;
    ++j;
  }
  const auto is_name = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == ':' || c == '-' || c == '_' || c == '.';
  };
  const std::size_t name_from = j;
  while (j < t_.size() && is_name(t_[j])) ++j;
  tag.name = std::string(t_.substr(name_from, j - name_from));
  if (tag.name.empty()) fail(line_, "malformed SVG: a '<' that starts no tag");
  if (tag.name.rfind("svg:", 0) == 0) tag.name.erase(0, 4);
  while (true) {
    while (j < t_.size() && std::isspace(static_cast<unsigned char>(t_[j]))) ++j;
    if (j >= t_.size()) fail(tag.line, "malformed SVG: the tag <" + tag.name + "> is not closed");
    if (t_[j] == '>') {
      ++j;
      break;
    }
    if (t_[j] == '/' && j + 1 < t_.size() && t_[j + 1] == '>') {
      tag.self_closing = true;
      j += 2;
      break;
    }
    const std::size_t key_from = j;
    while (j < t_.size() && is_name(t_[j])) ++j;
    if (j == key_from) fail(tag.line, "malformed SVG: an attribute of <" + tag.name + "> has no name");
    std::string key(t_.substr(key_from, j - key_from));
    while (j < t_.size() && std::isspace(static_cast<unsigned char>(t_[j]))) ++j;
    if (j >= t_.size() || t_[j] != '=')
      fail(tag.line, "malformed SVG: the attribute " + key + " of <" + tag.name + "> has no value");
    ++j;
    while (j < t_.size() && std::isspace(static_cast<unsigned char>(t_[j]))) ++j;
    if (j >= t_.size() || (t_[j] != '"' && t_[j] != '\''))
      fail(tag.line, "malformed SVG: the value of " + key + " in <" + tag.name + "> is not quoted");
    const char quote = t_[j];
    const std::size_t end = t_.find(quote, j + 1);
    if (end == std::string_view::npos)
      fail(tag.line, "malformed SVG: the value of " + key + " in <" + tag.name + "> is not closed");
    tag.attributes.emplace_back(std::move(key), decode_entities(t_.substr(j + 1, end - j - 1)));
    j = end + 1;
  }
  i_ = j;
}

}  // namespace flapsim::wings
