// A TOML syntax error names the key written on its line and, for a number with a unit or a
// text without quotes, says so. Before: "case.toml:5: TOML syntax error: Error while parsing
// value: could not determine value type" for `frequency_hz = 25Hz`, no key, no cause.
#include <gtest/gtest.h>

#include <string>

#include "expect_input_error.hpp"
#include "wings/loader/toml_reader.hpp"

using flapsim::wings::parse_toml_string;

namespace {

flapsim::InputError error_of(const std::string& text) {
  return expect_input_error([&] { parse_toml_string(text, "c.toml"); });
}

}  // namespace

TEST(TomlSyntaxErrors, ANumberWithAUnitNamesTheKeyAndTheUnit) {
  const auto e = error_of("name = \"x\"\n[kinematics]\nrotation_phase = 0.0 # advanced < 0\nfrequency_hz = 25Hz\n");
  EXPECT_EQ(e.line(), 4);
  EXPECT_EQ(e.key(), "kinematics.frequency_hz");
  EXPECT_NE(e.message().find("a number takes no unit ('25Hz')"), std::string::npos) << e.what();
  // With a space and in a dotted key: 4e9 Pa.
  const auto m = error_of("[materials]\nchitin.youngs_modulus = 4e9 Pa\n");
  EXPECT_EQ(m.key(), "materials.chitin.youngs_modulus");
  EXPECT_NE(m.message().find("('4e9 Pa')"), std::string::npos) << m.what();
}

TEST(TomlSyntaxErrors, ATextWithoutQuotesIsSaidToNeedThem) {
  const auto e = error_of("[structure]\nkind = flexible\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.key(), "structure.kind");
  EXPECT_NE(e.message().find("a text value needs quotes: \"flexible\""), std::string::npos) << e.what();
}

// In a multi-line array the key is the array's; a table header in a string or an array of
// arrays does not count as a header; [[veins]] is the table of the keys after it.
TEST(TomlSyntaxErrors, ALineOfAMultiLineArrayNamesTheArraysKey) {
  const auto e = error_of("[planform]\nname = \"[x]\"\noutline = [\n  [0.0, 0.0],\n  [3.0 10.0],\n]\n");
  EXPECT_EQ(e.line(), 5);
  EXPECT_EQ(e.key(), "planform.outline");
  const auto v = error_of("[[veins]]\nname = \"costa\"\nwall = 0.02 mm\n");
  EXPECT_EQ(v.key(), "veins.wall");
  EXPECT_NE(v.message().find("no unit ('0.02 mm')"), std::string::npos) << v.what();
}

// A broken table header has no key; toml++'s own description stands.
TEST(TomlSyntaxErrors, ABrokenHeaderHasNoKey) {
  const auto e = error_of("a = 1\n[structure\nkind = \"rigid\"\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.key(), "");
  EXPECT_NE(e.message().find("TOML syntax error"), std::string::npos) << e.what();
}

// A table defined twice names the table (toml++ says "cannot redefine existing table";
// before, no key; found by a user's test of case files).
TEST(TomlSyntaxErrors, ATableDefinedTwiceNamesTheTable) {
  const auto e = error_of("[structure]\nkind = \"rigid\"\n[numerics]\ncycles = 1\n[structure]\nkind = \"fem\"\n");
  EXPECT_EQ(e.line(), 5);
  EXPECT_EQ(e.key(), "structure");
  const auto v = error_of("[[veins]]\nname = \"a\"\n[ veins ]\n");
  EXPECT_EQ(v.line(), 3);
  EXPECT_EQ(v.key(), "veins");
}
