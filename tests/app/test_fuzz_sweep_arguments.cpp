// The mutation fuzzer (tests/io/mutation_fuzzer.hpp) over the arguments of `flapsim
// sweep`: `--vary KEY=VALUES` texts, each loaded variation's values written into a valid case
// as the sweep writes them (sweep::load_case_with), and `--cases` CSV tables. Each mutant
// must be accepted with what docs/sweeps.md allows (a key, 1 … 10000 finite values; a table
// of unique keys and finite cells; a case within docs/case_file.md's ranges) or refused with
// flapsim::InputError; any other exception, a crash or a hang fails. `make test`: 600
// mutants each; `make fuzz`: FLAPSIM_FUZZ_MUTANTS.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "io/mutation_fuzzer.hpp"
#include "common/scratch_dir.hpp"
#include "io/documented_ranges.hpp"
#include "pipeline/app/sweep/case_table.hpp"
#include "pipeline/app/sweep/sweep_values.hpp"

namespace {

namespace fs = std::filesystem;
using flapsim::test::fuzz;
using flapsim::test::mutants_per_loader;

const std::string kSource = FLAPSIM_SOURCE_DIR;
constexpr std::uint64_t kSeed = 20261128;  // fixed: every run sees the same mutants

// A value of `wing` is a path, kept as written (a file that is not there is refused when the
// case is loaded); every other key's is a finite number or a word.
std::string values_out_of_range(const flapsim::sweep::Variation& v) {
  if (v.values.empty() || v.values.size() > flapsim::sweep::kMaxVaryValues) return "value count";
  for (const flapsim::sweep::Assignment& a : v.values) {
    if (flapsim::sweep::takes_paths(v.key)
            ? a.word.empty()
            : !std::isfinite(a.value) || !(a.word.empty() || flapsim::sweep::is_word_value(a.word)))
      return "value";
  }
  return "";
}

TEST(FuzzSweepArguments, VaryTexts) {
  const std::string case_file = kSource + "/tests/data/valid_tiny_case.toml";
  int cases_loaded = 0;
  for (const std::string seed : {"kinematics.rotation_phase=-0.2:0.05:0.1", "numerics.steps_per_cycle=24,40,80",
                                 "spring_scale=0.5,1,2", "wing.membrane.thickness=0.01:0.005:0.02"}) {
    fuzz("--vary " + seed, seed, kSeed + seed.size(), mutants_per_loader() / 4, [&](const std::string& text) {
      const flapsim::sweep::Variation v = flapsim::sweep::parse_variation(text);
      if (v.key.empty()) return std::string("key");
      if (const std::string bad = values_out_of_range(v); !bad.empty()) return bad;
      const auto grid = flapsim::sweep::cartesian_grid({v});
      if (grid.size() != v.values.size()) return std::string("grid size");
      // A case key's values go into the case as the sweep writes them (wing keys and the
      // spring factor are checked with the wing and the chain).
      if (v.key.rfind("wing.", 0) == 0 || v.key == "spring_scale") return std::string();
      for (std::size_t i = 0; i < std::min<std::size_t>(v.values.size(), 3); ++i) {
        const flapsim::io::Case c = flapsim::sweep::load_case_with(case_file, v.values[i]);
        if (const std::string bad = flapsim::test::case_out_of_range(c); !bad.empty()) return bad;
        ++cases_loaded;
      }
      return std::string();
    });
  }
  EXPECT_GT(cases_loaded, 0);  // some mutants reached the case
}

TEST(FuzzSweepArguments, CaseTables) {
  flapsim::test::ScratchDir dir("fuzz_case_table");
  const fs::path file = dir / "cases.csv";
  const std::string seed =
      "# rotation phase and springs\nkinematics.rotation_phase,spring_scale,wing.membrane.thickness\n"
      "-0.10,1,0.012\n0.05,2,0.015\n\n0.0,0.5,0.02\n";
  fuzz("--cases table", seed, kSeed + 100, mutants_per_loader(), [&](const std::string& text) {
    std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
    const flapsim::sweep::CaseTable t = flapsim::sweep::read_case_table(file.string());
    if (t.keys.empty() || t.points.empty() || t.points.size() != t.lines.size()) return std::string("table shape");
    if (std::set<std::string>(t.keys.begin(), t.keys.end()).size() != t.keys.size()) return std::string("keys");
    for (const auto& k : t.keys)
      if (k.empty()) return std::string("key");
    for (const auto& p : t.points) {
      if (p.size() != t.keys.size()) return std::string("row size");
      for (const auto& a : p)
        if (!std::isfinite(a.value)) return std::string("cell");
    }
    return std::string();
  });
}

}  // namespace
