#pragma once
/// \file toml_key_path.hpp
/// \brief Where a dotted key of a TOML file sits in its parsed document, for the values a
/// sweep or an optimisation sets over a file (TomlTable::apply_overrides) and for writing
/// a case with such values (pipeline/app/optimize/optimum_case.cpp).
///
/// A key is table keys joined by dots, each optionally followed by array indices in
/// brackets, 0-based (docs/sweeps.md, "What can be varied"):
///   kinematics.rotation_phase         a key of a table
///   kinematics.rotation.sin_deg[0]    the first element of an array of numbers
///   veins[2].width                    a key of the third table of an array of tables
/// Unlike key_path's bare keys, an element must exist: an override can replace an array's
/// element but not lengthen the array (the file's array says how many harmonics, veins, ...).
/// Includes toml++: only for the .cpp files that work on toml++ documents.

#include <toml++/toml.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace flapsim::wings {

/// One part of a dotted key: a table key and the indices after it ("sin_deg[0]": "sin_deg", {0}).
struct KeyPart {
  std::string name;
  std::vector<std::size_t> indices;
};

/// A dotted key that names nothing in the document, with why (the message names the part
/// of the key concerned, e.g. "'kinematics.rotation.sin_deg' has 1 element (indices
/// from 0): index 1 is out of range").
class KeyPathError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// \brief The parts of a dotted key.
/// \throws KeyPathError when it is not one: empty, an empty part ("a..b", ".a"), a bracket
///         without a 0-based decimal index ("a[]", "a[-1]", "a[x]", "a[0"), text after a
///         closing bracket other than "[" or "." ("a[0]b")
std::vector<KeyPart> parse_key_path(std::string_view dotted);

/// The place of a key's value: the key `key` of `table`, or element `index` of `array`.
struct ValueSlot {
  toml::table* table = nullptr;
  std::string key;
  toml::array* array = nullptr;
  std::size_t index = 0;

  /// The value there; nullptr when the key is absent from its table.
  toml::node* get() const;
  /// Sets the value there (the element replaced, or the key inserted or replaced).
  void set(const toml::node& value) const;
};

/// \brief Finds where the dotted key's value sits in `root`.
/// Tables missing on the way are created when `create_tables` (as an override does); else
/// a missing table gives an empty slot (no table, no array: get() is nullptr). An indexed
/// part must name an existing element: a table of an array of tables on the way, a number
/// of an array of numbers at the end (only a number can be set in an array).
/// \throws KeyPathError when the key is malformed, goes through a value that is not a
///         table (or not an array where it has an index), names an element beyond the
///         array's end or an absent array, or names an element that is not a number
ValueSlot find_value_slot(toml::table& root, std::string_view dotted, bool create_tables);

/// "a table", "an array", "a string", "an integer", ... ("nothing" for an empty node).
const char* toml_type_name(const toml::node& n);

}  // namespace flapsim::wings
