// A case's structure.gravity that is almost certainly a mistake is warned at its key
// (pipeline/io/gravity_warning.hpp; docs/case_file.md, "[structure]"): before 5 Dec nothing
// checked it, and [0, 0, -9810] (mm/s²) flew a plate in vacuum with a thousand times its
// weight, to a negative mean drive power, without a word.
#include <gtest/gtest.h>

#include <string>

#include "hover_case_text.hpp"
#include "inline_case.hpp"

namespace {

flapsim::io::Case case_with_gravity(const std::string& gravity) {
  std::string text = hover_case_text("cycles = 1\n");
  const std::string kind = "kind = \"rigid\"\n";
  text.insert(text.find(kind) + kind.size(), "gravity = " + gravity + "\n");  // line 8
  return case_from_text(text);
}

std::string gravity_message(const flapsim::io::Case& c) {
  for (const auto& w : c.warnings)
    if (w.key == "structure.gravity") {
      EXPECT_EQ(w.line, 8);
      return w.message;
    }
  return "";
}

TEST(GravityWarning, MillimetresPerSecondSquaredAnUpwardPullAndGsAreNamed) {
  // The Earth's, the Moon's (1.62) and Jupiter's (24.8) pass; none given, none warned.
  for (const char* g : {"[0.0, 0.0, -9.81]", "[0.0, 0.0, -1.62]", "[0.0, -24.8, 0.0]", "[0.0, 0.0, 0.0]"})
    EXPECT_EQ(gravity_message(case_with_gravity(g)), "") << g;
  EXPECT_NE(gravity_message(case_with_gravity("[0.0, 0.0, -9810.0]"))
                .find("gravity of 9810 m/s², 1e+03 times the Earth's 9.81: gravity is in m/s² whatever the "
                      "length_unit; was it written in mm/s² (9.81 m/s²)?"),
            std::string::npos);
  EXPECT_NE(gravity_message(case_with_gravity("[0.0, 0.0, 9.81]"))
                .find("gravity points up the ground frame's z axis (9.81 m/s² along +z)"),
            std::string::npos);
  EXPECT_NE(gravity_message(case_with_gravity("[0.0, 0.0, -0.01]")).find("was it written in km/s² or in g"),
            std::string::npos);
}

}  // namespace
