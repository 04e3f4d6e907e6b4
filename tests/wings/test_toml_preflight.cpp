// The scan before toml++ (wings/loader/toml_preflight.hpp): the inputs on which toml++ 3.x stops
// on its own assertion (an abort in builds without NDEBUG, undefined behaviour with it on
// compilers with an "assume") are refused as bad input at their line; valid TOML that
// looks like them still parses. Each refused input below aborts toml++ 3.3's parser in
// the ASan build (Debug) when given to it directly; the loader fuzzer found them
// (tests/io/test_fuzz_loaders.cpp under `make test-asan`).
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "expect_input_error.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/toml_reader.hpp"

using flapsim::wings::parse_toml_string;

namespace {

// A table header is parsed where a statement starts (top level, start of a line); its
// name must start with a key character or a quote (TOML 1.0.0, "Table"), and toml++
// asserts that it does (parse_key) instead of reporting the error.
TEST(TomlPreflight, TableHeadersWithoutAKeyAreRefusedAtTheirLine) {
  for (const char* text : {"a = 1\n[[\n", "a = 1\n[\n", "a = 1\n[[\r\n", "a = 1\n[=\n", "a = 1\n[[=\n",
                           "a = 1\n[[[1]]]\n", "a = 1\n[ =\n", "a = 1\n[[ =]]\n", "a = 1\n[#structure]\n",
                           "a = 1\n  [# x\n", "a = 1\n[+x]\n", "a = 1\n[{a}]\n", "a = 1\n[\t.x]\n",
                           "a = 1\n[\xE2\x80\xA8]\n", "a = 1\n[[\x01]]\n"}) {
    const auto e = expect_input_error([&] { parse_toml_string(text, "h.toml"); });
    EXPECT_EQ(e.file(), "h.toml") << text;
    EXPECT_EQ(e.line(), 2) << text;
    EXPECT_NE(e.message().find("TOML syntax error"), std::string::npos) << e.what();
  }
}

// A header after a multi-line value is still found: the scan follows strings and arrays
// over lines (the case the fuzzer found, "[#structure]", after a table).
TEST(TomlPreflight, HeadersAfterMultiLineValuesAreFoundAtTheirLine) {
  const char* text =
      "name = \"\"\"two\nlines [=\"\"\"\n"  // lines 1-2: a multi-line string holding "[="
      "x = [\n  1, # [=\n  2,\n]\n"         // lines 3-6: an array over lines, a comment with "[="
      "[kinematics]\n"                     // line 7
      "k = 'a[b'\n"                        // line 8
      "[#structure]\n";                    // line 9
  EXPECT_EQ(expect_input_error([&] { parse_toml_string(text, "c.toml"); }).line(), 9);
}

// An array element cannot start with a character that ends values; toml++ asserts
// (parse_value) on '}' and on the Unicode line separators U+0085, U+2028, U+2029.
TEST(TomlPreflight, ArrayElementsStartingWithAValueTerminatorAreRefusedAtTheirLine) {
  for (const char* text : {"a = 1\nb = [}1]\n", "a = 1\nb = [1, }]\n", "a = 1\nb = [[\n}]]\n",
                           "a = 1\nb = [ # c\n}]\n", "a = 1\nb = [\xE2\x80\xA8]\n", "a = 1\nb = [1,\xC2\x85]\n",
                           "a = 1\nt = {x = [\n}]}\n"}) {
    const auto e = expect_input_error([&] { parse_toml_string(text, "v.toml"); });
    EXPECT_GE(e.line(), 2) << text;
    EXPECT_LE(e.line(), 3) << text;
  }
}

// toml++ 3.3 asks of a non-ASCII character outside strings and comments whether it is
// whitespace, and for U+00A1-U+049A and U+FB26-U+FEFE that is undefined behaviour (an
// unreachable branch; UBSan: "execution reached an unreachable program point"). TOML
// allows non-ASCII text only in strings and comments (TOML 1.0.0, "Keys", "Whitespace"),
// so it is refused elsewhere; in strings and comments it reads as before. Inputs from
// the fuzzer (a '#' lost from a comment with "\u00a7"; a date-time running into text).
TEST(TomlPreflight, NonAsciiOutsideStringsAndCommentsIsRefusedAtItsLine) {
  for (const char* text : {"a = 1\nits \xC2\xA7 4 = 1\n", "a = 1\n  \xC2\xA7= 1.inf225\n", "a = 1\nb = 1 \xC2\xA7\n",
                           "a = 1\nk = 1979-05-27 07:32:\"\"\"a\\00Z\xEF\xAC\xB0\n", "a = 1\nb = [1, \xC3\xA9]\n",
                           "a = 1\n\"\"\"x\\\n \xC2\xA7\"\"\" = 1\n"}) {
    const auto e = expect_input_error([&] { parse_toml_string(text, "n.toml"); });
    EXPECT_GE(e.line(), 2) << text;
    EXPECT_LE(e.line(), 3) << text;
  }
  const auto t = parse_toml_string("# \xC2\xA9 \xEF\xAC\xB0\nname = \"\xC3\xA9 \xC2\xA7\" # \xC2\xA7\nm = '''\n\xC2\xA7'''\n", "u.toml");
  EXPECT_EQ(t.get_string("name"), "\xC3\xA9 \xC2\xA7");
}

// "YYYY-MM-DD" and a space start a date-time for toml++ 3.3; a single digit and then the
// end of the value trips its parse_value assertion. Found by the fuzzer from
// "k = 1979-05-27 07:32:00Z".
TEST(TomlPreflight, ADateWithALoneDigitAfterItsSpaceIsRefused) {
  for (const char* text : {"a = 1\nk = 1979-05-27 0\n", "a = 1\nk = [1979-05-27 0 ]\n", "a = 1\nk = 1979-05-2_7 0,\n"})
    EXPECT_EQ(expect_input_error([&] { parse_toml_string(text, "d.toml"); }).line(), 2) << text;
  EXPECT_TRUE(parse_toml_string("k = 1979-05-27 07:32:00Z\nd = 1979-05-27\n", "ok.toml").has("k"));
}

// toml++ 3.3's test for a date is looser than a date: 10 characters starting with a digit,
// '-' at 5 and 8, and no sign, dot, colon or the letters it notes (b, o, x second after a
// '0'; e before a '-'; t, z). A coverage-guided fuzzer (libFuzzer on the case and chain
// readers, 5 Dec) found "0----!---- 0" and "0-\x12------; 0", each an assertion in
// parse_value; "0aaa-bb-cc 1" is the same. Tokens that note another trait are toml++'s own
// syntax errors, not refused by the scan.
TEST(TomlPreflight, AValueShapedLikeADateWithALoneDigitAfterItsSpaceIsRefused) {
  for (const char* text :
       {"a = 1\ng = 0----!---- 0\n", "a = 1\ng = 0-\x12------; 0\n", "a = 1\ng = 0aaa-bb-cc 1\n",
        "a = 1\ng = [0aaa-bb-cc 1]\n", "a = 1\ng = 0_aaa-bb-cc 1 # c\n"}) {
    const auto e = expect_input_error([&] { parse_toml_string(text, "d.toml"); });
    EXPECT_EQ(e.line(), 2) << text;
    EXPECT_NE(std::string(e.what()).find("a single digit"), std::string::npos) << e.what();  // the scan's
  }
  // Not shaped like a date for toml++ (a 't', a '.', 11 characters, a sign first): its own
  // error, on the same line; and a lone digit at the end of the text is no assertion.
  for (const char* text : {"a = 1\ng = 0t--!--x-- 0\n", "a = 1\ng = 0.--!--x-- 0\n",
                           "a = 1\ng = 0----!----- 0\n", "a = 1\ng = 0----!---- 0"}) {
    const auto e = expect_input_error([&] { parse_toml_string(text, "d.toml"); });
    EXPECT_EQ(e.line(), 2) << text;
    EXPECT_EQ(std::string(e.what()).find("a single digit"), std::string::npos) << e.what();  // toml++'s
  }
}

// Valid TOML with the same characters in places where they are not a header or an
// element start parses as before: lines of a continued array starting "[#", "[+", "[{",
// "[" alone; brackets inside strings, quoted keys and comments.
TEST(TomlPreflight, ValidTomlThatLooksLikeItStillParses) {
  const auto t = parse_toml_string(
      "x = [\n[1, 2],\n[+3.0, -4],\n[\"a\"], [{}],\n[ # a comment\n5],\n[\n],\n]\n"
      "s = \"[}\" # [}\n"
      "m = '''\n[=\n[[\n'''\n"
      "u = {}\nv = [{}, {a = 1, b = [1,\n 2]}]\n"
      "\"[key]\" = 1\n"
      "[ \"t]#\" . 'u' ]  # header with quoted parts\n"
      "y = 1979-05-27 07:32:00Z\n"
      "[[arr]]\n[[ arr ]]\n",
      "ok.toml");
  EXPECT_TRUE(t.has("x"));
  EXPECT_TRUE(t.has("v"));
  EXPECT_TRUE(t.has("[key]"));
  EXPECT_TRUE(t.has("arr"));
}

// Where toml++ reports a syntax error of its own before the input it would assert on,
// its message and line stand (toml++ reads nothing after its first error).
TEST(TomlPreflight, TomlppsOwnEarlierErrorIsReported) {
  const auto e = expect_input_error([&] { parse_toml_string("a = = 1\n[=\n", "e.toml"); });
  EXPECT_EQ(e.line(), 1) << e.what();
}

// Nesting far beyond toml++'s limit (TOML_MAX_NESTED_VALUES = 256) is refused by toml++,
// without the scan running out of stack.
TEST(TomlPreflight, DeepNestingIsAnErrorNotAStackOverflow) {
  const std::string text = "a = " + std::string(200000, '[') + "\n";
  EXPECT_EQ(expect_input_error([&] { parse_toml_string(text, "d.toml"); }).line(), 1);
}

// A command-line override ("--set key=value") goes through the same scan.
TEST(TomlPreflight, OverridesAreScannedToo) {
  auto t = parse_toml_string("a = 1\n", "o.toml");
  const auto e = expect_input_error([&] { t.apply_overrides({{"b", "[}]"}}); });
  EXPECT_EQ(e.key(), "b");
  EXPECT_EQ(e.file(), "o.toml");
}

}  // namespace
