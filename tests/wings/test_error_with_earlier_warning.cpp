// An error in a wing file carries the warnings before it, which often name its cause.
// Before: an outline written in m under length_unit = "mm" (a 32 µm wing) gave only
// "key 'mesh.element_size': must not exceed half the span"; the warning "shorter than any
// flapping wing ... was it written in m?" is printed only for a wing that reads.
#include <gtest/gtest.h>

#include <string>

#include "expect_input_error.hpp"
#include "wings/loader/toml_reader.hpp"
#include "wings/loader/wing_file.hpp"

using flapsim::wings::parse_toml_string;
using flapsim::wings::read_wing;

namespace {

// A 10 x 32 plate: in mm, a wing; in m written under "mm", a 0.032 mm wing whose 1 mm
// mesh size exceeds half its span (0.016 mm).
std::string plate(const std::string& outline) {
  return "name = \"p\"\nlength_unit = \"mm\"\n[planform]\noutline = " + outline +
         "\nclamp_y = 0.0\n[materials.pet]\nyoungs_modulus = 4.0e9\npoisson_ratio = 0.38\ndensity = 1390.0\n"
         "[membrane]\nthickness = 0.05\nmaterial = \"pet\"\n[mesh]\nelement_size = 1.0\n";
}

}  // namespace

TEST(WingErrorWithEarlierWarning, AnOutlineInMetresUnderMillimetresNamesItsCause) {
  const auto e = expect_input_error([] {
    read_wing(parse_toml_string(plate("[[0.0, 0.0], [0.0, 0.032], [-0.01, 0.032], [-0.01, 0.0]]"), "m.toml"));
  });
  EXPECT_EQ(e.line(), 14);
  EXPECT_EQ(e.key(), "mesh.element_size");
  EXPECT_NE(e.message().find("must not exceed half the span (element_size 1 mm, span 0.032 mm); perhaps the cause, "
                             "a warning before it: m.toml:4: key 'planform.outline': the wing would be 3.2e-05 m"),
            std::string::npos)
      << e.what();
  EXPECT_NE(e.message().find("was it written in m (length_unit = \"m\")?"), std::string::npos) << e.what();
}

TEST(WingErrorWithEarlierWarning, AnErrorWithoutWarningsIsUnchanged) {
  const auto e = expect_input_error([] {
    read_wing(parse_toml_string(plate("[[0.0, 0.0], [0.0, 1.5], [-10.0, 1.5], [-10.0, 0.0]]"), "s.toml"));
  });
  EXPECT_EQ(e.message(), "must not exceed half the span (element_size 1 mm, span 1.5 mm)") << e.what();
}

// A span in mm written 1000 times too large (40000 for 40): the outline's sliver check
// (R²/S 3334) came before the span's warning, and the error alone named no unit.
TEST(WingErrorWithEarlierWarning, ASliverOfASpanNoWingHasNamesTheUnit) {
  const auto e = expect_input_error([] {
    read_wing(parse_toml_string(
        "name = \"p\"\nlength_unit = \"mm\"\n[planform]\nshape = \"rounded_rectangle\"\nspan = "
        "40000.0\nchord = 12.0\n"
        "root_y = 2.0\nclamp_y = 3.0\n[materials.pet]\nyoungs_modulus = 4.0e9\npoisson_ratio = 0.38\n"
        "density = 1390.0\n[membrane]\nthickness = 0.05\nmaterial = \"pet\"\n",
        "span.toml"));
  });
  EXPECT_EQ(e.key(), "planform.shape");
  EXPECT_NE(e.message().find("the outline is a sliver"), std::string::npos) << e.what();
  EXPECT_NE(
      e.message().find("span.toml:5: key 'planform.span': the wing would be 40 m from pivot to tip, longer "
                       "than any flapping wing (2 m)"),
      std::string::npos)
      << e.what();
  EXPECT_NE(e.message().find("was it written in um"), std::string::npos) << e.what();
}
