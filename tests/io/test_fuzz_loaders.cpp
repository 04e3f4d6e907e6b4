// A mutation fuzzer over every loader of user files: wing files, case files, chain files,
// outline CSV files and SVG drawings. From valid seeds, a fixed-seed generator makes mutants (bytes
// flipped, inserted, deleted; lines dropped, doubled, swapped; numbers replaced by edge
// values: 0, denormals, 2^53 + 1, INT64_MIN, 1e308, inf, nan, ...; pieces of TOML
// structure inserted; truncation). Each
// mutant must either load or be refused with flapsim::InputError. The test fails on
//  - a crash (the process dies; under `make test-asan` also any sanitizer report),
//  - any other exception (std::bad_alloc, std::out_of_range, ...),
//  - a hang (a mutant taking over 10 s aborts the test, naming the loader),
//  - a mutant that loads with a value outside the documented ranges (docs/wing_file.md,
//    docs/case_file.md, docs/multibody.md): the "exit 0 on a bad value" of the CLI.
// `make test`: 600 mutants per loader (3000); `make fuzz`: FLAPSIM_FUZZ_MUTANTS per loader.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "io/mutation_fuzzer.hpp"
#include "common/scratch_dir.hpp"
#include "io/documented_ranges.hpp"
#include "pipeline/io/case_file.hpp"
#include "pipeline/io/case_model.hpp"
#include "pipeline/io/chain_file.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/mesh_budget.hpp"
#include "wings/loader/outline_csv.hpp"
#include "wings/loader/toml_reader.hpp"
#include "wings/loader/wing_file.hpp"

namespace fs = std::filesystem;
namespace io = flapsim::io;
namespace w = flapsim::wings;
using flapsim::InputError;

namespace {

using flapsim::test::case_out_of_range;
using flapsim::test::chain_out_of_range;
using flapsim::test::fuzz;
using flapsim::test::normal_or_zero;
using flapsim::test::wing_out_of_range;
using flapsim::test::mutants_per_loader;

const std::string kSource = FLAPSIM_SOURCE_DIR;
constexpr std::uint64_t kSeed = 20261126;  // fixed: every run sees the same mutants


std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(FuzzLoaders, WingFiles) {
  const std::string seed = read_file(kSource + "/tests/data/valid_tiny_wing.toml");
  const auto t = fuzz("wing", seed, kSeed, mutants_per_loader(), [](const std::string& text) {
    return wing_out_of_range(w::read_wing(w::parse_toml_string(text, kSource + "/tests/data/fuzz_wing.toml")));
  });
  EXPECT_GT(t.loaded + t.refused, 0u);
}

TEST(FuzzLoaders, CaseFiles) {
  const std::string seed = read_file(kSource + "/tests/data/valid_tiny_case.toml");
  fuzz("case", seed, kSeed + 1, mutants_per_loader(), [](const std::string& text) {
    return case_out_of_range(io::read_case(w::parse_toml_string(text, kSource + "/tests/data/fuzz_case.toml")));
  });
}

TEST(FuzzLoaders, ChainFiles) {
  const std::string seed =
      "length_unit = \"mm\"\nroot = \"sprung\"\nroot_offset = [0.0, 1.0, 0.0]\n"
      "[[bodies]]\nlength = 20.0\nmass = 1e-5\ncenter_of_mass = [0, 10, 0]\n"
      "inertia = [[4e-10,0,0],[0,1e-11,0],[0,0,4e-10]]\n"
      "[bodies.joint]\nbend_stiffness = 4e-3\ntwist_stiffness = 1e-3\nbend_rest = 0.1\n"
      "[[bodies]]\nlength = 20.0\nmass = 2e-5\ncenter_of_mass = [-2, 10, 0]\n"
      "inertia = [[8e-10,0,0],[0,2e-11,0],[0,0,8e-10]]\noutboard_joint = [0, 20, 0]\n"
      "[bodies.joint]\nbend_stiffness = 2e-3\ntwist_stiffness = 5e-4\nbend_damping = 1e-6\n";
  fuzz("chain", seed, kSeed + 2, mutants_per_loader(), [](const std::string& text) {
    return chain_out_of_range(io::parse_chain_text(text, "fuzz_chain.toml"));
  });
}

TEST(FuzzLoaders, OutlineCsvFiles) {
  flapsim::test::ScratchDir dir("fuzz_outline");
  const std::string seed = "# outline\nx,y\n0.10,0.0\n0.12,0.5\n0.05,1.0\n-0.20,0.9\n-0.25,0.3\n-0.15,0.0\n";
  const fs::path file = dir / "o.csv";
  fuzz("outline CSV", seed, kSeed + 3, mutants_per_loader(), [&](const std::string& text) {
    std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
    const w::Polygon p = w::read_outline_csv(file.string(), "planform.outline_file");
    if (p.size() < 3 || p.size() > w::kMaxOutlinePoints) return std::string("point count");
    for (const auto& q : p)
      if (!std::isfinite(q.x()) || !std::isfinite(q.y()) || !normal_or_zero(q.x()) || !normal_or_zero(q.y()))
        return std::string("point value");
    return std::string();
  });
}

// An SVG drawing (wings/loader/svg_drawing.hpp) read as a wing's outline and veins: the test
// drawing's mutants, through tests/data/drawn_wing.toml's keys.
TEST(FuzzLoaders, SvgDrawings) {
  flapsim::test::ScratchDir dir("fuzz_drawing");
  const std::string seed = read_file(kSource + "/tests/data/drawn_wing.svg");
  std::ofstream(dir / "drawn_wing.toml") << read_file(kSource + "/tests/data/drawn_wing.toml");
  const fs::path file = dir / "drawn_wing.svg";
  const auto t = fuzz("SVG drawing", seed, kSeed + 4, mutants_per_loader(), [&](const std::string& text) {
    std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
    const w::Wing wing = w::read_wing(w::parse_toml_file((dir / "drawn_wing.toml").string()));
    if (wing.outline.size() > w::kMaxOutlinePoints) return std::string("outline point count");
    for (const auto& v : wing.veins)
      for (const auto& q : v.points)
        if (!std::isfinite(q.x()) || !std::isfinite(q.y())) return std::string("vein point");
    return wing_out_of_range(wing);
  });
  EXPECT_GT(t.loaded, 0u);  // the fuzzer reaches the wing, not only the XML's errors
  EXPECT_GT(t.refused, 0u);
}

}  // namespace
