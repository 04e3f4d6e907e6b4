// What travels between the ranks of a sweep and back from an earlier run: a case's results
// as summary.json text, read back exactly (pipeline/app/sweep/summary_reader,
// sweep_table's encode_outcome/decode_outcome).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "pipeline/app/run_results.hpp"
#include "pipeline/app/sweep/summary_reader.hpp"
#include "pipeline/app/sweep/sweep_table.hpp"

namespace {

using namespace flapsim;

app::RunResults sample_results() {
  app::RunResults r;
  r.set("case", "plate \"a\"\nb\\c");    // quotes, a newline, a backslash
  r.set("air", true);
  r.set("steps", 48);
  r.set("mean_lift_N", 0.1 + 0.2);       // 0.30000000000000004: the last bit must survive
  r.set("mean_CL", 1.0 / 3.0);
  r.set("tip_rotation_phase", -9.055256544598934e-17);
  r.set("r2", std::nan(""));             // written as null
  r.set("status", "ok");
  r.set("inputs_hash", "0123456789abcdef");
  return r;
}

TEST(SweepTable, SummaryJsonReadsBackToTheSameResults) {
  const app::RunResults r = sample_results();
  const auto back = sweep::parse_summary_json(app::summary_json(r).to_string());
  ASSERT_TRUE(back.has_value());
  for (std::size_t i = 0; i < app::kRunResults.size(); ++i) {
    ASSERT_EQ(back->at(i).has_value(), r.at(i).has_value()) << app::kRunResults[i].key;
    if (!r.at(i)) continue;
    if (const double* x = std::get_if<double>(&*r.at(i))) {
      const double y = std::get<double>(*back->at(i));
      if (std::isnan(*x))
        EXPECT_TRUE(std::isnan(y));
      else
        EXPECT_EQ(y, *x) << app::kRunResults[i].key;  // bit for bit
    } else {
      EXPECT_EQ(*back->at(i), *r.at(i)) << app::kRunResults[i].key;
    }
  }
  // Keys that are not results are skipped; text that is not the flat object is refused.
  EXPECT_TRUE(sweep::parse_summary_json("{\n  \"no_such_result\": 1,\n  \"steps\": 3\n}\n").has_value());
  EXPECT_FALSE(sweep::parse_summary_json("{\n  \"steps\": 3.5\n}\n").has_value());  // an integer result
  EXPECT_FALSE(sweep::parse_summary_json("{\n  \"steps\": 3\n").has_value());      // cut short
  EXPECT_FALSE(sweep::parse_summary_json("").has_value());
}

TEST(SweepTable, OutcomeTravelsBetweenRanksUnchanged) {
  sweep::CaseOutcome o;
  o.status = "failed";
  o.message = "step 12 (t = 0.0046 s): coupling did not converge, 50 iterations";
  o.rank = 7;
  o.host = "node-3";
  o.results = sample_results();
  o.overhead_s = 0.0123;
  std::size_t index = 0;
  const sweep::CaseOutcome back = sweep::decode_outcome(sweep::encode_outcome(4242, o), index);
  EXPECT_EQ(index, 4242u);
  EXPECT_EQ(back.status, o.status);
  EXPECT_EQ(back.message, o.message);
  EXPECT_EQ(back.rank, 7);
  EXPECT_EQ(back.host, "node-3");
  EXPECT_EQ(back.overhead_s, 0.0123);
  EXPECT_EQ(back.results.number("mean_lift_N"), 0.1 + 0.2);
  EXPECT_EQ(back.results.text("case"), "plate \"a\"\nb\\c");
  EXPECT_THROW(sweep::decode_outcome("12:garbled", index), std::runtime_error);
}

}  // namespace
