// summary.json: a flat, ordered JSON object written atomically.

#include "pipeline/io/summary_json.hpp"
#include "common/scratch_dir.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

using flapsim::io::SummaryJson;
using flapsim::test::ScratchDir;

TEST(OutputSummaryJson, WritesAnOrderedFlatObject) {
  // Expected text follows RFC 8259: strings quoted with \" and \\ escapes,
  // numbers in shortest round-trip form, no NaN (written as null).
  SummaryJson s;
  s.set("case", "hover \"eq8\"\\");
  s.set("mean_lift_N", 0.0123);
  s.set("steps", 300);
  s.set("cycles", std::size_t{3});
  s.set("converged", true);
  s.set("max_tip_deflection_m", std::numeric_limits<double>::quiet_NaN());
  s.set("mean_lift_N", 0.5);  // replaced in place, keeps its position
  EXPECT_EQ(s.to_string(),
            "{\n"
            "  \"case\": \"hover \\\"eq8\\\"\\\\\",\n"
            "  \"mean_lift_N\": 0.5,\n"
            "  \"steps\": 300,\n"
            "  \"cycles\": 3,\n"
            "  \"converged\": true,\n"
            "  \"max_tip_deflection_m\": null\n"
            "}\n");
  EXPECT_EQ(SummaryJson().to_string(), "{}\n");
  EXPECT_EQ(flapsim::io::json_quote("a\nb\x01"), "\"a\\nb\\u0001\"");

  ScratchDir dir("summary");
  s.write(dir / "run/summary.json");
  std::ifstream in(dir / "run/summary.json");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, s.to_string());
  EXPECT_TRUE(dir.temporaries().empty());
}
