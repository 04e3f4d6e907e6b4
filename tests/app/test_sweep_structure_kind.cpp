// A sweep over the structure's kind of a case written for a chain: `--vary
// structure.kind=rigid,flexible,fem` was refused ("a rigid wing is one body (found 3)"), and no
// case table could leave the chain's bodies out for the FEM ("kind = \"fem\" ... has no
// bodies: omit bodies"), so rigid, chain and FEM could not share one table (a user's film
// wing study, 6 Dec). Now a point that sets structure.kind leaves out the file's keys of
// the other kinds (io::load_case_file): each row is the run of the case written for its kind.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "sweep_test_helpers.hpp"

using namespace flapsim;

TEST(SweepStructureKind, RigidChainAndFemOfOneCaseAreEachTheCaseWrittenForItsKind) {
  const test::ScratchDir dir("sweep_structure_kind");
  std::string chain_case = test::tiny_plate_case(16);
  const std::string rigid = "kind = \"rigid\"\n";
  chain_case.replace(chain_case.find(rigid), rigid.size(), "kind = \"flexible\"\nbodies = 3\n");
  std::ofstream(dir / "chain.toml") << chain_case;
  const auto sweep = test::run_flapsim_capturing_stderr(
      dir.path(), "sweep " + (dir / "chain.toml").string() +
                      " --vary structure.kind=rigid,flexible,fem -j 1 -o " + (dir / "sweep").string());
  ASSERT_EQ(sweep.status, 0) << sweep.err;
  const auto table = test::read_sweep_table((dir / "sweep" / "sweep.csv").string());
  ASSERT_EQ(table.rows.size(), 3u);
  // Each kind's own case file, run alone: the same inputs (hash) and the same lift, to the bit.
  const std::string kinds[3] = {"rigid", "flexible", "fem"};
  for (int k = 0; k < 3; ++k) {
    std::string own = test::tiny_plate_case(16);
    if (kinds[k] != "rigid") own.replace(own.find(rigid), rigid.size(), "kind = \"" + kinds[k] + "\"\n");
    if (kinds[k] == "flexible")
      own.replace(own.find("kind = \"flexible\"\n"), 18, "kind = \"flexible\"\nbodies = 3\n");
    const std::string name = kinds[k] + ".toml";
    std::ofstream(dir / name) << own;
    ASSERT_EQ(test::run_flapsim("run " + (dir / name).string() + " -q -o " + (dir / kinds[k]).string()), 0)
        << kinds[k];
    const std::string summary = test::read_text(dir / kinds[k] / "summary.json");
    const auto& row = table.rows[static_cast<std::size_t>(k)];
    EXPECT_EQ(row.at("structure.kind"), kinds[k]);
    EXPECT_EQ(row.at("status"), "ok") << kinds[k];
    const std::string case_summary = test::read_text(dir / "sweep" / row.at("folder") / "summary.json");
    const auto hash_of = [](const std::string& json) {
      const auto at = json.find("\"inputs_hash\": \"");
      return at == std::string::npos ? std::string("none") : json.substr(at + 16, 16);
    };
    EXPECT_NE(hash_of(summary), "none") << summary;
    EXPECT_EQ(hash_of(case_summary), hash_of(summary)) << kinds[k];
    EXPECT_EQ(std::stod(row.at("mean_lift_N")), test::json_number(summary, "mean_lift_N")) << kinds[k];
  }
  // A case table that gives the FEM a body count is refused at its cell, as before: the table
  // sets the key, the FEM has none.
  std::ofstream(dir / "kinds.csv") << "structure.kind,structure.bodies\nrigid,1\nfem,1\n";
  const auto table_sweep = test::run_flapsim_capturing_stderr(
      dir.path(), "sweep " + (dir / "chain.toml").string() + " --cases " + (dir / "kinds.csv").string() +
                      " -o " + (dir / "table").string());
  EXPECT_EQ(table_sweep.status, 2) << table_sweep.err;
  EXPECT_NE(table_sweep.err.find("has no bodies"), std::string::npos) << table_sweep.err;
}
