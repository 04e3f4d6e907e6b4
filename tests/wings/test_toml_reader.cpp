// The checked TOML layer: types, bounds, units, unknown keys, and the line of each error.
#include <gtest/gtest.h>

#include <string>

#include "expect_input_error.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/toml_reader.hpp"

using flapsim::InputError;
using flapsim::wings::Bounds;
using flapsim::wings::parse_toml_string;
using flapsim::wings::TomlTable;

namespace {

const char* kDoc =
    "length_unit = \"mm\"\n"          // 1
    "span = 48.3\n"                    // 2
    "count = 3\n"                      // 3
    "label = \"hawk\"\n"               // 4
    "[membrane]\n"                     // 5
    "thickness = 0.012\n"              // 6
    "flag = true\n"                    // 7
    "list = [1, 2.5, 3]\n"             // 8
    "[[veins]]\n"                      // 9
    "name = \"a\"\n"                   // 10
    "[[veins]]\n"                      // 11
    "name = \"b\"\n"                   // 12
    "points = [[0, 1], [2, 3]]\n";     // 13

}  // namespace

TEST(TomlReader, TypedValuesAndLengthsInMetres) {
  TomlTable root = parse_toml_string(kDoc, "doc.toml");
  root.read_length_unit();
  EXPECT_DOUBLE_EQ(root.length_scale(), 1e-3);
  EXPECT_NEAR(root.get_length("span", Bounds::positive()), 0.0483, 1e-15);
  EXPECT_EQ(root.get_int("count"), 3);
  EXPECT_DOUBLE_EQ(root.get_double("count"), 3.0);  // integers are numbers too
  EXPECT_EQ(root.get_string("label"), "hawk");
  const TomlTable m = root.get_table("membrane");
  EXPECT_NEAR(m.get_length("thickness"), 1.2e-5, 1e-18);
  EXPECT_TRUE(m.get_bool("flag"));
  EXPECT_EQ(m.get_doubles("list"), (std::vector<double>{1.0, 2.5, 3.0}));
  EXPECT_DOUBLE_EQ(m.get_double("absent", 7.0, Bounds::any()), 7.0);
  const auto veins = root.get_tables("veins");
  ASSERT_EQ(veins.size(), 2u);
  EXPECT_EQ(veins[1].path(), "veins[1]");
  EXPECT_EQ(veins[1].line(), 11);
  const auto rows = veins[1].get_number_rows("points", 2);
  EXPECT_EQ(rows[1][0], 2.0);
}

TEST(TomlReader, MissingKeyReportsTableLineAndPath) {
  TomlTable root = parse_toml_string(kDoc, "doc.toml");
  const auto e = expect_input_error([&] { root.get_table("membrane").get_double("density"); });
  EXPECT_EQ(e.file(), "doc.toml");
  EXPECT_EQ(e.line(), 5);
  EXPECT_EQ(e.key(), "membrane.density");
}

TEST(TomlReader, WrongTypeReportsValueLine) {
  TomlTable root = parse_toml_string(kDoc, "doc.toml");
  const auto e = expect_input_error([&] { root.get_double("label"); });
  EXPECT_EQ(e.line(), 4);
  EXPECT_EQ(e.key(), "label");
  EXPECT_NE(e.message().find("expected a number, found a string"), std::string::npos);
  EXPECT_EQ(expect_input_error([&] { root.get_int("span"); }).line(), 2);  // float for int
}

TEST(TomlReader, OutOfRangeValue) {
  TomlTable root = parse_toml_string("x = -1.5\n", "doc.toml");
  const auto e = expect_input_error([&] { root.get_double("x", Bounds::positive()); });
  EXPECT_EQ(e.line(), 1);
  EXPECT_NE(e.message().find("> 0"), std::string::npos);
  EXPECT_NO_THROW(root.get_double("x", Bounds::closed(-2, 0)));
}

TEST(TomlReader, UnknownKeyIsReported) {
  TomlTable root = parse_toml_string(kDoc, "doc.toml");
  const auto e = expect_input_error(
      [&] { root.get_table("membrane").expect_only({"thickness", "flag"}); });
  EXPECT_EQ(e.line(), 8);
  EXPECT_EQ(e.key(), "membrane.list");
}

TEST(TomlReader, UnknownLengthUnit) {
  TomlTable root = parse_toml_string("a = 1\nlength_unit = \"inch\"\n", "doc.toml");
  const auto e = expect_input_error([&] { root.read_length_unit(); });
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.key(), "length_unit");
}

TEST(TomlReader, SyntaxErrorHasLine) {
  const auto e = expect_input_error([] { parse_toml_string("a = 1\nb = [1, 2\n", "cut.toml"); });
  EXPECT_EQ(e.file(), "cut.toml");
  EXPECT_GE(e.line(), 2);
  const std::string what = e.what();
  EXPECT_EQ(what.rfind("cut.toml:", 0), 0u);
}

TEST(TomlReader, ArrayElementErrorsNameTheElement) {
  TomlTable root = parse_toml_string("v = [\n 1.0,\n \"x\",\n]\n", "doc.toml");
  const auto e = expect_input_error([&] { root.get_doubles("v"); });
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.key(), "v[1]");
}

TEST(TomlReader, ChoicesAndPaths) {
  TomlTable root = parse_toml_string("core = \"vatistas\"\nwing = \"../w.toml\"\n", "cases/c.toml");
  EXPECT_EQ(expect_input_error([&] { root.get_choice("core", {"cutoff", "lamb_oseen"}); }).line(), 1);
  EXPECT_EQ(root.get_path("wing"), "w.toml");  // cases/../w.toml
}
