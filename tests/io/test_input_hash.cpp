// The fingerprint of a run's inputs (pipeline/io/input_hash): FNV-1a 64 against the
// reference test vectors, and a hash that follows the inputs and not where they are.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/scratch_dir.hpp"
#include "pipeline/io/case_file.hpp"
#include "pipeline/io/input_hash.hpp"
#include "wings/loader/wing_file.hpp"

namespace {

namespace fs = std::filesystem;
using namespace flapsim;

TEST(InputHash, Fnv1a64MatchesTheReferenceVectors) {
  // Test vectors of the FNV reference code (Fowler/Noll/Vo, test_fnv.c, FNV-1a 64):
  // "" -> the offset basis, "a" -> af63dc4c8601ec8c, "foobar" -> 85944171f73967e8.
  EXPECT_EQ(io::fnv1a_64(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(io::fnv1a_64("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(io::fnv1a_64("foobar"), 0x85944171f73967e8ull);
}

TEST(InputHash, FollowsTheInputsNotTheirPlace) {
  const fs::path data = fs::path(FLAPSIM_SOURCE_DIR) / "tests" / "data";
  const io::Case c = io::load_case_file((data / "valid_tiny_case.toml").string());
  const wings::Wing w = wings::load_wing_file((data / "valid_tiny_wing.toml").string());
  const std::string h = io::input_hash(c, &w, "", 1.0);
  EXPECT_EQ(h.size(), 16u);
  EXPECT_EQ(h, io::input_hash(c, &w, "", 1.0));  // deterministic

  // The same files in another folder: the same hash (paths are not inputs).
  const test::ScratchDir dir("input_hash");
  fs::copy_file(data / "valid_tiny_case.toml", dir / "valid_tiny_case.toml");
  fs::copy_file(data / "valid_tiny_wing.toml", dir / "valid_tiny_wing.toml");
  const io::Case moved = io::load_case_file((dir / "valid_tiny_case.toml").string());
  const wings::Wing moved_wing = wings::load_wing_file((dir / "valid_tiny_wing.toml").string());
  EXPECT_EQ(io::input_hash(moved, &moved_wing, "", 1.0), h);

  // Any change of a value changes it: a case key, a wing key, the spring factor, the wing.
  const io::Case phase =
      io::load_case_file((data / "valid_tiny_case.toml").string(), {{"kinematics.rotation_phase", "-0.05"}});
  EXPECT_NE(io::input_hash(phase, &w, "", 1.0), h);
  const io::Case tol =
      io::load_case_file((data / "valid_tiny_case.toml").string(), {{"numerics.coupling_tolerance", "1e-7"}});
  EXPECT_NE(io::input_hash(tol, &w, "", 1.0), h);
  wings::Wing thick = w;
  thick.membrane.thickness *= 1.0 + 1e-15;  // the last bits count
  EXPECT_NE(io::input_hash(c, &thick, "", 1.0), h);
  EXPECT_NE(io::input_hash(c, &w, "", 2.0), h);
  EXPECT_NE(io::input_hash(c, nullptr, "", 1.0), h);
  // Keys hashed only when set (numerics.steady, kinematics.revolution) still count when set.
  io::Case steady = c;
  steady.numerics.steady = true;
  EXPECT_NE(io::input_hash(steady, &w, "", 1.0), h);
  io::Case first_order = c;  // numerics.circulation_rate = "bdf1": other loads
  first_order.numerics.circulation_rate = io::CirculationRate::Bdf1;
  EXPECT_NE(io::input_hash(first_order, &w, "", 1.0), h);
  io::Case plain = c;  // numerics.added_mass off: the same fixed point, other iterates
  plain.numerics.added_mass = false;
  EXPECT_NE(io::input_hash(plain, &w, "", 1.0), h);
  io::Case revolving = c;
  revolving.kinematics.revolution.rate = 1.0;
  EXPECT_NE(io::input_hash(revolving, &w, "", 1.0), h);
  revolving.kinematics.revolution.ramp = 0.1;
  EXPECT_NE(io::input_hash(revolving, &w, "", 1.0), io::input_hash([&] {
              io::Case r = c;
              r.kinematics.revolution.rate = 1.0;
              return r;
            }(), &w, "", 1.0));

  // A chain file enters by its bytes.
  std::ofstream(dir / "a.toml") << "# chain a\n";
  std::ofstream(dir / "b.toml") << "# chain b\n";
  EXPECT_NE(io::input_hash(c, &w, (dir / "a.toml").string(), 1.0),
            io::input_hash(c, &w, (dir / "b.toml").string(), 1.0));
}

// [output] vtk_every decides only which files a run writes (its ParaView series), not its
// numbers: it is no input, so a sweep run again after the case's interval was edited keeps
// its cases. It was in the hash.
TEST(InputHash, TheParaViewIntervalIsNoInput) {
  const fs::path data = fs::path(FLAPSIM_SOURCE_DIR) / "tests" / "data";
  const io::Case c = io::load_case_file((data / "valid_tiny_case.toml").string());
  const wings::Wing w = wings::load_wing_file((data / "valid_tiny_wing.toml").string());
  io::Case no_series = c;
  no_series.output.vtk_every = c.output.vtk_every + 7;
  EXPECT_EQ(io::input_hash(no_series, &w, "", 1.0), io::input_hash(c, &w, "", 1.0));
  EXPECT_EQ(io::canonical_inputs(c, &w, "", 1.0).find("vtk_every"), std::string::npos);
}

// Fields no result depends on are no inputs: the case's, the wing's and its veins' names
// (labels), and the clamp line of a wing whose FEM is not built (a rigid wing, a flexible
// one whose chain comes from a file). Until 3 Dec they were in the hash: `--vary
// wing.planform.clamp_y=1,2,3` on a rigid case and `--vary name=alpha,beta` ran every case
// to bit-identical rows where docs/sweeps.md promised a refusal, and renaming a case made a
// resumed sweep run every case again.
TEST(InputHash, NamesAndAnUnusedClampLineAreNoInputs) {
  const fs::path data = fs::path(FLAPSIM_SOURCE_DIR) / "tests" / "data";
  const io::Case flexible =
      io::load_case_file((data / "valid_tiny_case.toml").string());  // reduced in process
  const wings::Wing w = wings::load_wing_file((data / "valid_tiny_wing.toml").string());
  io::Case renamed = flexible;
  renamed.name = "another";
  wings::Wing relabelled = w;
  relabelled.name = "another";
  ASSERT_FALSE(relabelled.veins.empty());
  relabelled.veins[0].name = "another";
  const std::string h = io::input_hash(flexible, &w, "", 1.0);
  EXPECT_EQ(io::input_hash(renamed, &w, "", 1.0), h);
  EXPECT_EQ(io::input_hash(flexible, &relabelled, "", 1.0), h);
  wings::Wing clamped = w;
  clamped.clamp_y += 1e-3;
  // Reduced in process and the FEM: the clamp line holds the wing, an input.
  EXPECT_NE(io::input_hash(flexible, &clamped, "", 1.0), h);
  io::Case fem = flexible;
  fem.structure.kind = io::Case::Structure::Kind::Fem;
  EXPECT_NE(io::input_hash(fem, &clamped, "", 1.0), io::input_hash(fem, &w, "", 1.0));
  // Rigid, or a chain from a file: no input.
  io::Case rigid = flexible;
  rigid.structure.kind = io::Case::Structure::Kind::Rigid;
  EXPECT_EQ(io::input_hash(rigid, &clamped, "", 1.0), io::input_hash(rigid, &w, "", 1.0));
  const test::ScratchDir dir("input_hash_clamp");
  std::ofstream(dir / "chain.toml") << "# a chain\n";
  const std::string chain = (dir / "chain.toml").string();
  EXPECT_EQ(io::input_hash(flexible, &clamped, chain, 1.0), io::input_hash(flexible, &w, chain, 1.0));
}

}  // namespace
