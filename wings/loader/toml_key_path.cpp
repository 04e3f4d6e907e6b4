#include "wings/loader/toml_key_path.hpp"

#include <charconv>

namespace flapsim::wings {

namespace {

[[noreturn]] void malformed(std::string_view dotted, const std::string& why) {
  throw KeyPathError("'" + std::string(dotted) +
                     "' is not a dotted key such as kinematics.frequency_hz or kinematics.rotation.sin_deg[0] (" +
                     why + ")");
}

std::string elements(std::size_t n) { return std::to_string(n) + (n == 1 ? " element" : " elements"); }

}  // namespace

const char* toml_type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a floating-point number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    default: return "nothing";
  }
}

std::vector<KeyPart> parse_key_path(std::string_view dotted) {
  if (dotted.empty()) malformed(dotted, "empty");
  std::vector<KeyPart> parts;
  std::size_t i = 0;
  const std::size_t n = dotted.size();
  for (;;) {
    KeyPart part;
    while (i < n && dotted[i] != '.' && dotted[i] != '[' && dotted[i] != ']') part.name += dotted[i++];
    if (part.name.empty()) malformed(dotted, "an empty part");
    while (i < n && dotted[i] == '[') {
      const std::size_t first = ++i;
      while (i < n && dotted[i] >= '0' && dotted[i] <= '9') ++i;
      if (i == first || i >= n || dotted[i] != ']')
        malformed(dotted, "an index is a whole number from 0 in brackets, e.g. sin_deg[0]");
      std::size_t index = 0;
      const auto [end, ec] = std::from_chars(dotted.data() + first, dotted.data() + i, index);
      if (ec != std::errc() || end != dotted.data() + i) malformed(dotted, "the index is too large");
      part.indices.push_back(index);
      ++i;
    }
    parts.push_back(std::move(part));
    if (i == n) return parts;
    if (dotted[i] != '.') malformed(dotted, "'" + std::string(1, dotted[i]) + "' where '.' or '[' was expected");
    if (++i == n) malformed(dotted, "an empty part");
  }
}

toml::node* ValueSlot::get() const {
  if (array) return array->get(index);
  return table ? table->get(key) : nullptr;
}

void ValueSlot::set(const toml::node& value) const {
  if (array)
    array->replace(array->cbegin() + static_cast<std::ptrdiff_t>(index), value);
  else if (table)
    table->insert_or_assign(key, value);
}

ValueSlot find_value_slot(toml::table& root, std::string_view dotted, bool create_tables) {
  const std::vector<KeyPart> parts = parse_key_path(dotted);
  toml::table* t = &root;
  std::string walked;  // the key up to the part at hand, for messages
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const KeyPart& part = parts[k];
    const bool last = k + 1 == parts.size();
    walked += (k == 0 ? "" : ".") + part.name;
    if (last && part.indices.empty()) return {t, part.name, nullptr, 0};
    toml::node* n = t->get(part.name);
    if (!n) {
      if (!part.indices.empty())
        throw KeyPathError("'" + walked + "' is not in the file: [" + std::to_string(part.indices.front()) +
                           "] names an element of an array the file writes");
      if (!create_tables) return {};
      n = &t->insert_or_assign(part.name, toml::table{}).first->second;
    }
    for (std::size_t j = 0; j < part.indices.size(); ++j) {
      const std::size_t index = part.indices[j];
      if (!n->is_array())
        throw KeyPathError("'" + walked + "' is " + toml_type_name(*n) + ", not an array: [" + std::to_string(index) +
                           "] names an element of an array");
      toml::array& a = *n->as_array();
      if (index >= a.size())
        throw KeyPathError("'" + walked + "' has " + elements(a.size()) + " (indices from 0): index " +
                           std::to_string(index) + " is out of range");
      walked.append("[").append(std::to_string(index)).append("]");
      n = a.get(index);
      if (last && j + 1 == part.indices.size()) {
        if (!n->is_number())
          throw KeyPathError("'" + walked + "' is " + toml_type_name(*n) +
                             ", not a number: KEY[i] sets a number of an array of numbers");
        return {nullptr, "", &a, index};
      }
    }
    if (!n->is_table()) throw KeyPathError("'" + walked + "' is not a table");
    t = n->as_table();
  }
  return {};  // not reached: the last part returns above
}

}  // namespace flapsim::wings
