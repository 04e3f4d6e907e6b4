// The input hash: FNV-1a 64 against the published test values, and a hash that follows
// the values a run reads, not how its files are written.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "common/scratch_dir.hpp"
#include "pipeline/io/input_hash.hpp"

namespace io = flapsim::io;

namespace {

const std::string kSource = FLAPSIM_SOURCE_DIR;

TEST(InputHash, Fnv1a64MatchesTheReferenceValues) {
  // Test vectors of the FNV reference code (Noll, fnv/test_fnv.c, FNV-1a 64):
  // "" -> cbf29ce484222325 (the offset basis), "a" -> af63dc4c8601ec8c,
  // "foobar" -> 85944171f73967e8.
  EXPECT_EQ(io::fnv1a64(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(io::fnv1a64("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(io::fnv1a64("foobar"), 0x85944171f73967e8ull);
  EXPECT_EQ(io::hash_hex(0xaf63dc4c8601ec8cull), "af63dc4c8601ec8c");
  EXPECT_EQ(io::hash_hex(1), "0000000000000001");
}

// A case and a wing (with its outline CSV), written into a folder.
void write_inputs(const flapsim::test::ScratchDir& dir, const std::string& case_text, const std::string& wing_text) {
  std::ofstream(dir / "case.toml") << case_text;
  std::ofstream(dir / "wing.toml") << wing_text;
  std::ofstream(dir / "o.csv") << "x,y\n0.1,0\n0.1,1\n-0.2,1\n-0.2,0\n";
}

const std::string kCase =
    "wing = \"wing.toml\"\n[kinematics]\nfrequency_hz = 26.1\nsweep = { mean_deg = 10.0, cos_deg = [50.0] }\n"
    "rotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n[structure]\nkind = \"rigid\"\n";
const std::string kWing =
    "name = \"w\"\nlength_unit = \"mm\"\n[planform]\noutline_file = \"o.csv\"\nspan = 40.0\nclamp_y = 0.0\n"
    "[materials.film]\nyoungs_modulus = 4.0e9\npoisson_ratio = 0.3\ndensity = 1400.0\n"
    "[membrane]\nthickness = 0.05\nmaterial = \"film\"\n";

TEST(InputHash, SameValuesGiveTheSameHashWhateverTheSpelling) {
  flapsim::test::ScratchDir a("input_hash_a"), b("input_hash_b");
  write_inputs(a, kCase, kWing);
  write_inputs(b, kCase, kWing);
  // Same values: other key order, comments, whitespace, 26.1 as 2.61e1, another folder.
  std::ofstream(b / "case.toml")
      << "# the same case\nwing = \"wing.toml\"\n[structure]\nkind = \"rigid\"\n\n[kinematics]\n"
         "rotation = { sin_deg = [-45.0], mean_deg = 90.0 }\nsweep = {cos_deg=[50.0],mean_deg=10.0}\n"
         "frequency_hz = 2.61e1\n";
  EXPECT_EQ(io::input_hash((a / "case.toml").string()), io::input_hash((b / "case.toml").string()))
      << io::canonical_inputs((a / "case.toml").string()) << "\n---\n"
      << io::canonical_inputs((b / "case.toml").string());
}

TEST(InputHash, EveryInputChangesTheHash) {
  flapsim::test::ScratchDir dir("input_hash_changes");
  write_inputs(dir, kCase, kWing);
  const std::string file = (dir / "case.toml").string();
  const auto base = io::input_hash(file);
  // An override (a sweep value) of the case.
  EXPECT_NE(io::input_hash(file, {{"kinematics.rotation_phase", "-0.1"}}), base);
  EXPECT_EQ(io::input_hash(file, {{"kinematics.frequency_hz", "26.1"}}), base);  // same value
  // The integer 1 and the float 1.0 are different TOML values (a key may accept only one).
  EXPECT_NE(io::input_hash(file, {{"kinematics.frequency_hz", "26"}}),
            io::input_hash(file, {{"kinematics.frequency_hz", "26.0"}}));
  // The wing file.
  std::ofstream(dir / "wing.toml") << kWing << "nonstructural_mass_per_area = 0.01\n";
  const auto wing_changed = io::input_hash(file);
  EXPECT_NE(wing_changed, base);
  // The outline CSV the wing names.
  std::ofstream(dir / "o.csv") << "x,y\n0.1,0\n0.1,1\n-0.3,1\n-0.2,0\n";
  EXPECT_NE(io::input_hash(file), wing_changed);
  // A chain file given on the command line.
  std::ofstream(dir / "chain.toml") << "root = \"rigid\"\n";
  EXPECT_NE(io::input_hash(file, {}, (dir / "chain.toml").string()), io::input_hash(file));
}

}  // namespace
