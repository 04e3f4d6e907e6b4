// Case-file values at the edges: step counts whose product overflows an int, denormal and
// huge frequencies, and a case name that would be a path.
#include <gtest/gtest.h>

#include <string>

#include "inline_case.hpp"
#include "pipeline/io/case_file.hpp"
#include "pipeline/io/case_model.hpp"
#include "pipeline/io/case_summary.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/toml_reader.hpp"

namespace p = flapsim::io;
using flapsim::InputError;

namespace {

std::string case_text(const std::string& numerics, const std::string& head = "",
                      const std::string& frequency = "20.0") {
  return head + "wing = \"valid_tiny_wing.toml\"\n[kinematics]\nfrequency_hz = " + frequency +
         "\nsweep = { mean_deg = 0.0, cos_deg = [60.0] }\nrotation = { mean_deg = 90.0, sin_deg = [-60.0] }\n"
         "[structure]\nkind = \"rigid\"\n[numerics]\n" + numerics;
}

TEST(CaseLimits, StepCountsBeyondTheMaximumAreRejectedNotWrapped) {
  // 1,000,000 x 4,295 = 4.295e9 steps wrapped to 32,704 in an int and ran "ok";
  // 65,536 x 65,536 = 2^32 wrapped to 0 steps.
  for (const auto& [spc, cycles] : {std::pair{1000000, 4295}, std::pair{65536, 65536}}) {
    const auto e = error_of(case_text("steps_per_cycle = " + std::to_string(spc) + "\ncycles = " +
                                      std::to_string(cycles) + "\n"));
    EXPECT_EQ(e.key(), "numerics.cycles") << e.what();
    EXPECT_EQ(e.line(), 10) << e.what();
    EXPECT_NE(e.message().find(std::to_string(static_cast<long long>(spc) * cycles)), std::string::npos)
        << e.what();
  }
  // At the documented maximum, exactly: 10^6 x 100 = 10^8 steps is accepted and counted in 64 bits.
  const p::Case c = case_from_text(case_text("steps_per_cycle = 1000000\ncycles = 100\n"));
  EXPECT_EQ(c.numerics.total_steps(), p::kMaxTotalSteps);
}

TEST(CaseLimits, TheSummaryCountsStepsIn64Bits) {
  // `check` printed a negative count when steps_per_cycle x cycles exceeded INT_MAX
  // (2,147,483,647): 10^6 x 3000 = 3e9 steps (a Case not from a file: the reader refuses it).
  p::Case c = case_from_text(case_text(""));
  c.numerics.steps_per_cycle = 1000000;
  c.numerics.cycles = 3000;
  EXPECT_EQ(c.numerics.total_steps(), 3000000000LL);
  const std::string text = p::describe_case(c);
  EXPECT_NE(text.find("= 3000000000 (dt"), std::string::npos) << text;
}

TEST(CaseLimits, FrequenciesMustBeNormalAndBelowTheMaximum) {
  // A denormal frequency gave dt = inf ms in check.
  auto e = error_of(case_text("", "", "4e-320"));
  EXPECT_EQ(e.key(), "kinematics.frequency_hz") << e.what();
  EXPECT_EQ(e.line(), 3);
  e = error_of(case_text("", "", "2e6"));  // above the documented 1e6 Hz
  EXPECT_EQ(e.key(), "kinematics.frequency_hz") << e.what();
}

TEST(CaseLimits, ACaseNameIsNotAPath) {
  // name = "../../x" or an absolute name wrote outside out/.
  for (const char* name : {"../../x", "/tmp/x", "a/b", "..", ".hidden", "", "a b"}) {
    const auto e = error_of(case_text("", std::string("name = \"") + name + "\"\n"));
    EXPECT_EQ(e.key(), "name") << name << ": " << e.what();
    EXPECT_EQ(e.line(), 1) << name;
  }
  EXPECT_EQ(case_from_text(case_text("", "name = \"hover_flexible-2.5\"\n")).name, "hover_flexible-2.5");
  EXPECT_EQ(p::folder_name_of("../../x"), "_._.._x");  // no "/" and no leading "."
  EXPECT_EQ(p::folder_name_of("/tmp/x"), "_tmp_x");
  EXPECT_EQ(p::folder_name_of(""), "case");
}

TEST(CaseLimits, ASignalOfMoreThanTheMostHarmonicsIsRefusedAtItsEntry) {
  // One million sweep harmonics ran unbounded (every step evaluates each one). The limit is
  // 1000 cosine and 1000 sine coefficients; the error names entry 1001 of the array.
  std::string many = "[";
  for (std::size_t i = 0; i <= p::kMaxSignalHarmonics; ++i) many += (i ? ",\n" : "") + std::string("0.001");
  many += "]";
  std::string text = case_text("");
  const std::string sweep = "cos_deg = [60.0]";
  text.replace(text.find(sweep), sweep.size(), "cos_deg = " + many);
  auto e = error_of(text);
  EXPECT_EQ(e.key(), "kinematics.sweep.cos_deg") << e.what();
  EXPECT_EQ(e.line(), 4 + static_cast<int>(p::kMaxSignalHarmonics)) << e.what();  // one entry a line from line 4
  EXPECT_NE(e.message().find("more than 1000 harmonics"), std::string::npos) << e.what();
  // Exactly the limit is read, as is the same count of sines.
  text = case_text("");
  const std::string rot = "sin_deg = [-60.0]";
  many = "[-60.0";
  for (std::size_t i = 1; i < p::kMaxSignalHarmonics; ++i) many += ", 0.0";
  many += "]";
  text.replace(text.find(rot), rot.size(), "sin_deg = " + many);
  EXPECT_NO_THROW(case_from_text(text));
}

}  // namespace
