// Numbers at the edges of what a double and an int hold (issue: integers beyond 2^53 read
// as garbage, denormals passing "> 0", step counts wrapping in an int).
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>

#include "wings/loader/checked_integer.hpp"
#include "expect_input_error.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/toml_reader.hpp"
#include "wings/loader/wing_file.hpp"

using flapsim::InputError;
using flapsim::wings::Bounds;
using flapsim::wings::parse_toml_string;

namespace {

// 2^53 = 9007199254740992 is the largest integer n with every integer up to n exact in a
// double (IEEE 754 binary64: 53-bit significand).
TEST(ExactIntegers, IntegersUpTo2Pow53AreReadExactly) {
  const auto t = parse_toml_string("a = 9007199254740992\nb = -9007199254740992\nc = 3\n", "f.toml");
  EXPECT_EQ(t.get_double("a"), 9007199254740992.0);
  EXPECT_EQ(t.get_double("b"), -9007199254740992.0);
  EXPECT_EQ(t.get_double("c", Bounds::positive()), 3.0);
}

TEST(ExactIntegers, LargerIntegersInNumberKeysAreRejectedWithFileLineAndKey) {
  // The examples: a density of INT64_MIN and a rest angle of INT64_MAX were read
  // as -9.2e18 / 9.2e18 and, for open bounds, passed.
  const auto t = parse_toml_string(
      "[m]\ndensity = -9223372036854775808\nangle = 9223372036854775807\nodd = 9007199254740993\n"
      "list = [1, 9007199254740993]\nrows = [[0, 1], [2, -9223372036854775808]]\n",
      "w.toml");
  const auto m = t.get_table("m");
  auto e = expect_input_error([&] { m.get_double("density"); });
  EXPECT_EQ(e.file(), "w.toml");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.key(), "m.density");
  EXPECT_NE(e.message().find("2^53"), std::string::npos) << e.what();
  EXPECT_EQ(expect_input_error([&] { m.get_double("angle", Bounds::any()); }).line(), 3);
  EXPECT_EQ(expect_input_error([&] { m.get_double("odd"); }).key(), "m.odd");
  EXPECT_EQ(expect_input_error([&] { m.get_doubles("list"); }).key(), "m.list[1]");
  EXPECT_EQ(expect_input_error([&] { m.get_number_rows("rows", 2); }).key(), "m.rows[1]");
}

TEST(Denormals, DenormalValuesAreRejectedByEveryNumberKey) {
  // 1e-320 is below the smallest normal double 2.2250738585072014e-308 (DBL_MIN): a
  // denormal, which passed "> 0" (core_radius = 1e-320 failed later without a line).
  ASSERT_EQ(std::fpclassify(1e-320), FP_SUBNORMAL);
  const auto t = parse_toml_string("core_radius = 1e-320\nlist = [1.0, -4e-310]\nok = 2.3e-308\n", "c.toml");
  auto e = expect_input_error([&] { t.get_double("core_radius", Bounds::positive()); });
  EXPECT_EQ(e.line(), 1);
  EXPECT_EQ(e.key(), "core_radius");
  EXPECT_NE(e.message().find("denormal"), std::string::npos) << e.what();
  EXPECT_EQ(expect_input_error([&] { t.get_doubles("list"); }).key(), "list[1]");
  EXPECT_EQ(t.get_double("ok", Bounds::positive()), 2.3e-308);  // normal: accepted
  EXPECT_EQ(flapsim::wings::kSmallestNormal, std::numeric_limits<double>::min());
}

TEST(Denormals, ALengthThatBecomesDenormalInMetresIsRejected) {
  // 1e-306 mm = 1e-309 m: normal as written, denormal once converted.
  const auto t = parse_toml_string("length_unit = \"mm\"\nthickness = 1e-306\nlist = [1.0, 1e-306]\n", "w.toml");
  t.read_length_unit();
  EXPECT_EQ(expect_input_error([&] { t.get_length("thickness", Bounds::positive()); }).line(), 2);
  EXPECT_EQ(expect_input_error([&] { t.get_lengths("list"); }).key(), "list[1]");
}

TEST(Denormals, AnOutlinePointThatBecomesDenormalInMetresIsRejected) {
  // Found by the loader fuzzer (make fuzz): 2.2250738585072014e-308 mm is the smallest
  // normal double as written, 2.2e-311 m (denormal) once converted.
  const std::string wing =
      "name = \"t\"\nlength_unit = \"mm\"\n[planform]\n"
      "outline = [[2.0, 0.0], [2.0, 10.0], [-3.0, 10.0], [2.2250738585072014e-308, 0.0]]\nclamp_y = 0.0\n"
      "[materials.film]\nyoungs_modulus = 4.0e9\npoisson_ratio = 0.3\ndensity = 1400.0\n"
      "[membrane]\nthickness = 0.05\nmaterial = \"film\"\n";
  const auto e = expect_input_error([&] { flapsim::wings::read_wing(parse_toml_string(wing, "w.toml")); });
  EXPECT_EQ(e.key(), "planform.outline") << e.what();
  EXPECT_EQ(e.line(), 4);
}

TEST(CheckedIntegers, ProductsAndSumsReportOverflow) {
  using flapsim::wings::checked_add;
  using flapsim::wings::checked_multiply;
  using flapsim::wings::checked_narrow;
  // The step counts: 1,000,000 x 4,295 = 4,295,000,000 wraps to 32,704 ... in an
  // int32 (4,295,000,000 - 2^32 = 32,704); in 64 bits it is exact.
  EXPECT_EQ(*checked_multiply(1000000, 4295), 4295000000LL);
  EXPECT_EQ(static_cast<std::int32_t>(static_cast<std::uint32_t>(4295000000LL)), 32704);
  EXPECT_EQ(*checked_multiply(65536, 65536), 4294967296LL);
  EXPECT_FALSE(checked_multiply(std::int64_t{1} << 32, std::int64_t{1} << 31));
  EXPECT_FALSE(checked_add(std::numeric_limits<std::int64_t>::max(), 1));
  EXPECT_FALSE(checked_narrow(4295000000LL));
  EXPECT_EQ(*checked_narrow(-5), -5);
}

TEST(CheckedIntegers, Int64KeysKeepTheirRange) {
  const auto t = parse_toml_string("n = 4295000000\nbig = 9223372036854775807\nf = 3.0\n", "c.toml");
  EXPECT_EQ(t.get_int64("n", 1, 5000000000LL), 4295000000LL);
  EXPECT_EQ(expect_input_error([&] { t.get_int64("big", 1, 5000000000LL); }).key(), "big");
  EXPECT_EQ(expect_input_error([&] { t.get_int64("f", 1, 10); }).key(), "f");
  // An int key given more than an int holds says so with its range (no wrap).
  auto e = expect_input_error([&] { t.get_int("n", Bounds::closed(1, 1000000)); });
  EXPECT_NE(e.message().find("4295000000"), std::string::npos) << e.what();
}

}  // namespace
