// numerics.skin_friction (docs/case_file.md): "none" (default) or "laminar"; anything else is
// bad input at its key; "laminar" enters the inputs hash and check's loads line.
#include <gtest/gtest.h>

#include <string>

#include "hover_case_text.hpp"
#include "inline_case.hpp"
#include "pipeline/io/case_summary.hpp"
#include "pipeline/io/input_hash.hpp"

TEST(SkinFrictionKey, LaminarIsReadHashedAndShownAndAnythingElseRefused) {
  const flapsim::io::Case plain = case_from_text(hover_case_text("cycles = 1\n"));
  const flapsim::io::Case laminar =
      case_from_text(hover_case_text("cycles = 1\nskin_friction = \"laminar\"\n"));
  const flapsim::io::Case none = case_from_text(hover_case_text("cycles = 1\nskin_friction = \"none\"\n"));
  EXPECT_FALSE(plain.numerics.laminar_skin_friction);
  EXPECT_TRUE(laminar.numerics.laminar_skin_friction);
  EXPECT_FALSE(none.numerics.laminar_skin_friction);
  EXPECT_NE(flapsim::io::input_hash(laminar, nullptr, "", 1.0),
            flapsim::io::input_hash(plain, nullptr, "", 1.0));
  EXPECT_EQ(flapsim::io::input_hash(none, nullptr, "", 1.0),
            flapsim::io::input_hash(plain, nullptr, "", 1.0));
  EXPECT_NE(flapsim::io::describe_case(laminar).find("leading edge separated, laminar skin friction"),
            std::string::npos)
      << flapsim::io::describe_case(laminar);
  const flapsim::InputError e = error_of(hover_case_text("cycles = 1\nskin_friction = \"turbulent\"\n"));
  EXPECT_EQ(e.key(), "numerics.skin_friction");
  EXPECT_EQ(e.line(), 11);  // [numerics] on line 8, then steps, cycles, the key
}
