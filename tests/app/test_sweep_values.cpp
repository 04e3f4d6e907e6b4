// The --vary arguments of flapsim sweep, their grid, the --cases table and the case made
// for each point (pipeline/app/sweep/sweep_values, case_table, sweep_case).
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "common/scratch_dir.hpp"
#include "pipeline/app/sweep/case_table.hpp"
#include "pipeline/app/sweep/sweep_case.hpp"
#include "pipeline/app/sweep/sweep_values.hpp"
#include "wings/loader/input_error.hpp"

namespace {

using namespace flapsim;

TEST(SweepValues, RangesListsAndErrors) {
  const auto v = sweep::parse_variation("kinematics.rotation_phase=-0.10:0.05:0.10");
  EXPECT_EQ(v.key, "kinematics.rotation_phase");
  ASSERT_EQ(v.values.size(), 5u);  // −0.10, −0.05, 0, 0.05, 0.10 (inclusive)
  const double expected[5] = {-0.10, -0.05, 0.0, 0.05, 0.10};
  for (int i = 0; i < 5; ++i) EXPECT_EQ(v.values[static_cast<std::size_t>(i)].value, expected[i]);
  EXPECT_EQ(sweep::parse_variation("k=-0.20:0.05:0.10").values.size(), 7u);  // the rigid study
  const auto list = sweep::parse_variation("k=3,1,2");
  ASSERT_EQ(list.values.size(), 3u);
  EXPECT_EQ(list.values[0].value, 3);
  EXPECT_EQ(list.values[1].value, 1);
  EXPECT_EQ(list.values[2].value, 2);
  EXPECT_EQ(list.values[2].word, "");
  EXPECT_THROW(sweep::parse_variation("k=0:0:1"), InputError);
  EXPECT_THROW(sweep::parse_variation("k=1:0.1:0"), InputError);
  // Words are the values of a text or boolean key; a number with letters, inf and nan are not.
  const auto words = sweep::parse_variation("numerics.leading_edge=none,separated,shed");
  ASSERT_EQ(words.values.size(), 3u);
  EXPECT_EQ(words.values[2].word, "shed");
  EXPECT_EQ(sweep::value_text(words.values[2]), "\"shed\"");
  EXPECT_EQ(sweep::value_label(words.values[2]), "shed");
  EXPECT_EQ(sweep::value_text(sweep::parse_variation("numerics.free_wake=true,false").values[1]), "false");
  EXPECT_THROW(sweep::parse_variation("k=1a,2"), InputError);
  EXPECT_THROW(sweep::parse_variation("k=nan"), InputError);
  EXPECT_THROW(sweep::parse_variation("k=Inf,1"), InputError);
  EXPECT_THROW(sweep::parse_variation("k=a:1:2"), InputError);  // a range is of numbers
  EXPECT_THROW(sweep::parse_variation("novalues"), InputError);
  // At most 10000 values (sweep_values.hpp), stop included: 0.01:1e-6:0.02 is 10001 of them
  // (the loader fuzzer's mutant of 5 Dec got through with the steps counted, not the values).
  EXPECT_EQ(sweep::parse_variation("k=1:1:10000").values.size(), 10000u);
  EXPECT_THROW(sweep::parse_variation("k=0:1:10000"), InputError);
  EXPECT_THROW(sweep::parse_variation("wing.membrane.thickness=0.01:1e-6:0.02"), InputError);
  std::string many = "k=1";
  for (int i = 0; i < 10000; ++i) many += ",1";
  EXPECT_THROW(sweep::parse_variation(many), InputError);  // 10001 in a list
}

TEST(SweepValues, BlanksAroundAValueGoAndBlanksInsideItStay) {
  // Before, every blank went: "2 6" ran 26 Hz and "wing=sp ace.toml" flew space.toml.
  const auto spaced = sweep::parse_variation(" kinematics.frequency_hz = 26 , 30\t");
  EXPECT_EQ(spaced.key, "kinematics.frequency_hz");
  ASSERT_EQ(spaced.values.size(), 2u);
  EXPECT_EQ(spaced.values[0].value, 26);
  EXPECT_EQ(spaced.values[1].value, 30);
  EXPECT_EQ(sweep::parse_variation("k= -0.1 : 0.1 : 0.1").values.size(), 3u);
  EXPECT_THROW(sweep::parse_variation("kinematics.frequency_hz=2 6,3 0"), InputError);
  EXPECT_THROW(sweep::parse_variation("k=0:0. 1:1"), InputError);
  EXPECT_THROW(sweep::parse_variation("numerics.leading_edge=sh ed"), InputError);
  EXPECT_THROW(sweep::parse_variation(" =1"), InputError);
  const auto wings = sweep::parse_variation("wing=my wings/sp ace.toml, b.toml");
  ASSERT_EQ(wings.values.size(), 2u);
  EXPECT_EQ(wings.values[0].word, "my wings/sp ace.toml");
  EXPECT_EQ(wings.values[1].word, "b.toml");
}

TEST(SweepValues, CaseIsReReadWithTheValue) {
  const std::string hover = std::string(FLAPSIM_SOURCE_DIR) + "/cases/hover.toml";
  const auto c = sweep::load_case_with(hover, "kinematics.rotation_phase", -0.15);
  EXPECT_DOUBLE_EQ(c.kinematics.rotation_phase, -0.15);
  EXPECT_EQ(sweep::load_case_with(hover, "numerics.cycles", 7).numerics.cycles, 7);
  // An integer key refuses a fraction; a value out of the case file's bounds is an input error.
  EXPECT_THROW(sweep::load_case_with(hover, "numerics.cycles", 2.5), InputError);
  EXPECT_THROW(sweep::load_case_with(hover, "kinematics.rotation_phase", 3.0), InputError);
  EXPECT_THROW(sweep::load_case_with(hover, "name.x", 1.0), InputError);
}

TEST(SweepValues, GridIsTheCartesianProductFirstKeySlowest) {
  const auto points = sweep::cartesian_grid({sweep::parse_variation("kinematics.rotation_phase=-0.1,0.1"),
                                             sweep::parse_variation("spring_scale=1,2,4")});
  ASSERT_EQ(points.size(), 6u);  // 2 × 3 combinations
  const double phase[6] = {-0.1, -0.1, -0.1, 0.1, 0.1, 0.1}, scale[6] = {1, 2, 4, 1, 2, 4};
  for (std::size_t i = 0; i < 6; ++i) {
    ASSERT_EQ(points[i].size(), 2u);
    EXPECT_EQ(points[i][0].key, "kinematics.rotation_phase");
    EXPECT_EQ(points[i][0].value, phase[i]);
    EXPECT_EQ(points[i][1].key, "spring_scale");
    EXPECT_EQ(points[i][1].value, scale[i]);
  }
  EXPECT_THROW(sweep::cartesian_grid({sweep::parse_variation("k=1,2"), sweep::parse_variation("k=3")}),
               InputError);
  EXPECT_EQ(sweep::case_folder(3, 6, points[3]), "03_0.1_1");
  EXPECT_EQ(sweep::case_folder(7, 1200, points[5]), "0007_0.1_4");
}

TEST(SweepValues, CaseTableRowsAndErrorsWithTheirLine) {
  const test::ScratchDir dir("sweep_case_table");
  std::ofstream(dir / "good.csv")
      << "# a comment\nkinematics.rotation_phase, spring_scale\n-0.1,1\n\n0.05,2.5\n";
  const auto table = sweep::read_case_table((dir / "good.csv").string());
  EXPECT_EQ(table.keys, (std::vector<std::string>{"kinematics.rotation_phase", "spring_scale"}));
  ASSERT_EQ(table.points.size(), 2u);
  EXPECT_EQ(table.points[1][0].value, 0.05);
  EXPECT_EQ(table.points[1][1].value, 2.5);
  // A word is a text key's value (a case table's leading_edge column: shed).
  // A spreadsheet may quote its text cells: "none" is none.
  std::ofstream(dir / "words.csv") << "numerics.leading_edge,numerics.cycles\nshed,2\n\"none\",3\n";
  const auto words = sweep::read_case_table((dir / "words.csv").string());
  ASSERT_EQ(words.points.size(), 2u);
  EXPECT_EQ(words.points[0][0].word, "shed");
  EXPECT_EQ(words.points[1][0].word, "none");
  EXPECT_EQ(words.points[1][1].value, 3);
  std::ofstream(dir / "bad.csv") << "a,b\n1,2\n3,2x\n";
  try {
    sweep::read_case_table((dir / "bad.csv").string());
    ADD_FAILURE() << "a cell that is not a number must be refused";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.key(), "b");
  }
  std::ofstream(dir / "short.csv") << "a,b\n1\n";
  EXPECT_THROW(sweep::read_case_table((dir / "short.csv").string()), InputError);
  std::ofstream(dir / "empty.csv") << "a,b\n";
  EXPECT_THROW(sweep::read_case_table((dir / "empty.csv").string()), InputError);
}

TEST(SweepValues, WingKeysAndSpringScaleChangeTheCaseAndItsHash) {
  const std::string hover = std::string(FLAPSIM_SOURCE_DIR) + "/cases/hover.toml";
  const sweep::SweepInputs inputs{hover, "", 1.0, ""};
  const auto base = sweep::resolve_case(inputs, {});
  const auto same =
      sweep::resolve_case(inputs, {{"kinematics.rotation_phase", base.c.kinematics.rotation_phase}});
  EXPECT_EQ(same.inputs_hash, base.inputs_hash);  // the same inputs, however given
  const auto thick = sweep::resolve_case(inputs, {{"wing.membrane.thickness", 0.02}});
  ASSERT_EQ(thick.wing_overrides.size(), 1u);
  EXPECT_EQ(thick.wing_overrides[0].first, "membrane.thickness");
  EXPECT_NE(thick.inputs_hash, base.inputs_hash);
  const auto stiff = sweep::resolve_case(inputs, {{"spring_scale", 2.0}});
  EXPECT_EQ(stiff.spring_scale, 2.0);
  EXPECT_NE(stiff.inputs_hash, base.inputs_hash);
  const auto phase = sweep::resolve_case(inputs, {{"kinematics.rotation_phase", 0.05}});
  EXPECT_EQ(phase.c.kinematics.rotation_phase, 0.05);
  EXPECT_NE(phase.inputs_hash, base.inputs_hash);
  // A bad wing value names the wing file and the key, and says which case it was.
  try {
    sweep::resolve_case(inputs, {{"wing.membrane.thickness", -1.0}});
    ADD_FAILURE() << "a negative membrane thickness must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(e.file().find("hawkmoth"), std::string::npos) << e.what();
    EXPECT_EQ(e.key(), "membrane.thickness");
    EXPECT_NE(e.message().find("with wing.membrane.thickness = -1"), std::string::npos) << e.what();
  }
  EXPECT_THROW(sweep::resolve_case(inputs, {{"spring_scale", 0.0}}), InputError);
  EXPECT_EQ(sweep::key_target("wing.membrane.thickness"), sweep::KeyTarget::wing_file);
  EXPECT_EQ(sweep::key_target("spring_scale"), sweep::KeyTarget::spring_scale);
  EXPECT_EQ(sweep::key_target("air.density"), sweep::KeyTarget::case_file);
}

}  // namespace
