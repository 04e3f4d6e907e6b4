// Dotted keys with array elements, KEY[i] (wings/loader/toml_key_path.hpp), and the overrides of a
// sweep or an optimisation that set such an element (TomlTable::apply_overrides).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "expect_input_error.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/toml_key_path.hpp"
#include "wings/loader/toml_reader.hpp"

namespace {

using namespace flapsim;
using namespace flapsim::wings;

// A case-like file: a harmonic series as an inline table (cases/rotation_phase_rigid.toml),
// an array of tables, an array of strings.
constexpr const char* kFile =
    "[kinematics]\n"
    "rotation_phase = 0.0\n"
    "rotation = { mean_deg = 90.0, sin_deg = [-45.0, 5] }\n"
    "names = [\"a\", \"b\"]\n"
    "[[veins]]\n"
    "width = 1.0\n"
    "[[veins]]\n"
    "width = 2.0\n";

InputError override_error(const std::string& key, const std::string& value = "1.5") {
  auto t = parse_toml_string(kFile, "k.toml");
  return expect_input_error([&] { t.apply_overrides({{key, value}}); });
}

TEST(TomlKeyPath, PartsAndIndices) {
  const auto parts = parse_key_path("kinematics.rotation.sin_deg[0]");
  ASSERT_EQ(parts.size(), 3u);
  EXPECT_EQ(parts[0].name, "kinematics");
  EXPECT_TRUE(parts[0].indices.empty());
  EXPECT_EQ(parts[2].name, "sin_deg");
  EXPECT_EQ(parts[2].indices, (std::vector<std::size_t>{0}));
  const auto nested = parse_key_path("veins[12].points[3][1]");
  ASSERT_EQ(nested.size(), 2u);
  EXPECT_EQ(nested[0].indices, (std::vector<std::size_t>{12}));
  EXPECT_EQ(nested[1].indices, (std::vector<std::size_t>{3, 1}));
  for (const char* bad : {"", ".a", "a.", "a..b", "a[]", "a[-1]", "a[x]", "a[0", "a[0]b", "[0]", "a]",
                          "a[99999999999999999999999]"})
    EXPECT_THROW(parse_key_path(bad), KeyPathError) << bad;
}

// An element override replaces that element only: the array keeps its length and its
// other elements, the read value is the one set (integers and floats alike).
TEST(TomlKeyPath, AnOverrideSetsOneElementOfAnArrayOfNumbers) {
  auto t = parse_toml_string(kFile, "k.toml");
  t.apply_overrides({{"kinematics.rotation.sin_deg[0]", "-50"}, {"kinematics.rotation.sin_deg[1]", "2.5"},
                     {"veins[1].width", "3.0"}});
  EXPECT_EQ(t.get_table("kinematics").get_table("rotation").get_doubles("sin_deg"),
            (std::vector<double>{-50.0, 2.5}));
  EXPECT_EQ(t.get_table("kinematics").get_table("rotation").get_double("mean_deg"), 90.0);
  const auto veins = t.get_tables("veins");
  ASSERT_EQ(veins.size(), 2u);
  EXPECT_EQ(veins[0].get_double("width"), 1.0);
  EXPECT_EQ(veins[1].get_double("width"), 3.0);
}

// Each refusal names the override's key, says what is wrong and that it came from an
// override (no file line).
TEST(TomlKeyPath, AnElementThatIsNotThereOrNotANumberIsRefusedNamingTheKey) {
  const auto out_of_range = override_error("kinematics.rotation.sin_deg[2]");
  EXPECT_EQ(out_of_range.key(), "kinematics.rotation.sin_deg[2]");
  EXPECT_EQ(out_of_range.line(), 0);
  EXPECT_NE(out_of_range.message().find("'kinematics.rotation.sin_deg' has 2 elements (indices from 0): index 2 is "
                                        "out of range"),
            std::string::npos)
      << out_of_range.what();
  EXPECT_NE(out_of_range.message().find("override"), std::string::npos);

  const auto not_an_array = override_error("kinematics.rotation_phase[0]");
  EXPECT_EQ(not_an_array.key(), "kinematics.rotation_phase[0]");
  EXPECT_NE(not_an_array.message().find("'kinematics.rotation_phase' is a floating-point number, not an array"),
            std::string::npos)
      << not_an_array.what();

  const auto a_string = override_error("kinematics.names[1]");
  EXPECT_NE(a_string.message().find("'kinematics.names[1]' is a string, not a number"), std::string::npos)
      << a_string.what();
  const auto a_table = override_error("veins[0]");
  EXPECT_NE(a_table.message().find("'veins[0]' is a table, not a number"), std::string::npos) << a_table.what();
  const auto text_value = override_error("kinematics.rotation.sin_deg[0]", "\"x\"");
  EXPECT_NE(text_value.message().find("its value must be a number, not a string"), std::string::npos)
      << text_value.what();
  const auto absent = override_error("kinematics.rotation.cos_deg[0]");
  EXPECT_NE(absent.message().find("'kinematics.rotation.cos_deg' is not in the file"), std::string::npos)
      << absent.what();
  const auto malformed = override_error("kinematics.rotation.sin_deg[-1]");
  EXPECT_EQ(malformed.key(), "kinematics.rotation.sin_deg[-1]");
  EXPECT_NE(malformed.message().find("not a dotted key"), std::string::npos) << malformed.what();
}

// The reader's own checks of an overridden element (or of its array) are the override's
// problem, not the file's: no line of the file, the key named.
TEST(TomlKeyPath, TheReadersRefusalOfAnOverriddenElementNamesTheOverride) {
  auto t = parse_toml_string(kFile, "k.toml");
  t.apply_overrides({{"kinematics.rotation.sin_deg[1]", "-3"}});
  const auto rotation = t.get_table("kinematics").get_table("rotation");
  const auto element = expect_input_error([&] { (void)rotation.get_doubles("sin_deg", Bounds::closed(-100.0, -10.0)); });
  EXPECT_EQ(element.line(), 0) << element.what();
  EXPECT_NE(element.message().find("override"), std::string::npos) << element.what();
  // A check of the whole array: the file wrote it, but an override changed it.
  const auto whole = expect_input_error([&] { rotation.fail("sin_deg", "too few harmonics"); });
  EXPECT_EQ(whole.line(), 0) << whole.what();
  EXPECT_EQ(whole.key(), "kinematics.rotation.sin_deg");
}

// Without creating tables (reading a value back), a table missing on the way is no slot;
// an element gives the element.
TEST(TomlKeyPath, FindingAValueWithoutCreatingTables) {
  toml::table root = toml::parse(kFile);
  EXPECT_EQ(find_value_slot(root, "air.density", false).get(), nullptr);
  EXPECT_FALSE(root.contains("air"));
  const toml::node* element = find_value_slot(root, "kinematics.rotation.sin_deg[1]", false).get();
  ASSERT_NE(element, nullptr);
  EXPECT_EQ(element->value<double>(), 5.0);
  EXPECT_EQ(find_value_slot(root, "kinematics.rotation_phase", false).get()->value<double>(), 0.0);
  EXPECT_THROW(find_value_slot(root, "kinematics.rotation.sin_deg[5]", false), KeyPathError);
}

}  // namespace
