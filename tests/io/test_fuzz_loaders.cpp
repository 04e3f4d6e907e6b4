// A mutation fuzzer over every loader of user files: wing files, case files, chain files
// and outline CSV files. From valid seeds, a fixed-seed generator makes mutants (bytes
// flipped, inserted, deleted; lines dropped, doubled, swapped; numbers replaced by edge
// values: 0, denormals, 2^53 + 1, INT64_MIN, 1e308, inf, nan, ...; pieces of TOML
// structure inserted; truncation). Each
// mutant must either load or be refused with flapsim::InputError. The test fails on
//  - a crash (the process dies; under `make test-asan` also any sanitizer report),
//  - any other exception (std::bad_alloc, std::out_of_range, ...),
//  - a hang (a mutant taking over 10 s aborts the test, naming the loader),
//  - a mutant that loads with a value outside the documented ranges (docs/wing_file.md,
//    docs/case_file.md, docs/multibody.md): the "exit 0 on a bad value" of the CLI.
// `make test`: 600 mutants per loader (2400); `make fuzz`: FLAPSIM_FUZZ_MUTANTS per loader.
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

#include "common/scratch_dir.hpp"
#include "pipeline/io/case_file.hpp"
#include "pipeline/io/case_model.hpp"
#include "pipeline/io/chain_file.hpp"
#include "wings/input_error.hpp"
#include "wings/mesh_budget.hpp"
#include "wings/outline_csv.hpp"
#include "wings/toml_reader.hpp"
#include "wings/wing_file.hpp"

namespace fs = std::filesystem;
namespace io = flapsim::io;
namespace w = flapsim::wings;
using flapsim::InputError;

namespace {

const std::string kSource = FLAPSIM_SOURCE_DIR;
constexpr std::uint64_t kSeed = 20261126;  // fixed: every run sees the same mutants

std::size_t mutants_per_loader() {
  if (const char* n = std::getenv("FLAPSIM_FUZZ_MUTANTS")) return std::strtoul(n, nullptr, 10);
  return 600;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// --- the mutator --------------------------------------------------------------------------

const std::vector<std::string> kEdgeValues = {
    "0", "-0", "0.0", "1", "-1", "1e-320", "-4.9e-324", "2.2250738585072014e-308", "1e-300", "1e308",
    "1.7976931348623157e308", "1e400", "inf", "-inf", "nan", "9007199254740992", "9007199254740993",
    "9223372036854775807", "-9223372036854775808", "2147483647", "2147483648", "-2147483649", "4294967296",
    "65536", "1000000", "100000000", "3.0", "1e-6", "0.5", "\"x\"", "[]", "[1, 2]", "true", "{}"};

// Pieces of TOML's structure (headers, multi-line strings, escapes, non-ASCII text, a date
// and a space) where toml++ 3.x has assertions and undefined behaviour of its own
// (wings/toml_preflight.hpp).
const std::vector<std::string> kPieces = {"\n[", "\n[[", "[#", "]]", "\"\"\"", "'''", "\\\n ", "\xC2\xA7", "\xE2\x80\xA8",
                                          "\xEF\xAC\xB0", " 0", "1979-05-27 ", "}", "\r\n", "{a = [\n"};

class Mutator {
 public:
  explicit Mutator(std::uint64_t seed) : rng_(seed) {}

  std::string mutate(std::string s) {
    const int rounds = 1 + static_cast<int>(pick(3));
    for (int r = 0; r < rounds; ++r) s = once(std::move(s));
    return s;
  }

 private:
  std::size_t pick(std::size_t n) { return n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_); }

  std::vector<std::string> lines(const std::string& s) {
    std::vector<std::string> out;
    std::stringstream in(s);
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
  }
  std::string join(const std::vector<std::string>& ls) {
    std::string out;
    for (const auto& l : ls) out += l + "\n";
    return out;
  }

  // Replaces the k-th number-looking token with an edge value.
  std::string replace_number(const std::string& s) {
    std::vector<std::pair<std::size_t, std::size_t>> tokens;
    for (std::size_t i = 0; i < s.size();) {
      const bool start = (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '-' || s[i] == '.') &&
                         (i == 0 || !std::isalnum(static_cast<unsigned char>(s[i - 1])));
      if (!start) { ++i; continue; }
      std::size_t j = i + 1;
      while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '.' || s[j] == '-' || s[j] == '+'))
        ++j;
      tokens.emplace_back(i, j - i);
      i = j;
    }
    if (tokens.empty()) return s;
    const auto [at, len] = tokens[pick(tokens.size())];
    std::string out = s;
    out.replace(at, len, kEdgeValues[pick(kEdgeValues.size())]);
    return out;
  }

  std::string once(std::string s) {
    if (s.empty()) return kEdgeValues[pick(kEdgeValues.size())];
    switch (pick(11)) {
      case 0: case 1: case 2: return replace_number(s);
      case 3: s[pick(s.size())] = static_cast<char>(pick(256)); return s;   // byte
      case 4: s.insert(pick(s.size() + 1), 1, "[]{}=,\"'.#\n\\ 0e-"[pick(17)]); return s;
      case 5: { const auto a = pick(s.size()); s.erase(a, 1 + pick(16)); return s; }
      case 6: { auto ls = lines(s); if (ls.empty()) return s; ls.erase(ls.begin() + pick(ls.size())); return join(ls); }
      case 7: { auto ls = lines(s); if (ls.empty()) return s; const auto i = pick(ls.size()); ls.insert(ls.begin() + i, ls[i]); return join(ls); }
      case 8: { auto ls = lines(s); if (ls.size() < 2) return s; std::swap(ls[pick(ls.size())], ls[pick(ls.size())]); return join(ls); }
      case 9: s.insert(pick(s.size() + 1), kPieces[pick(kPieces.size())]); return s;  // TOML structure
      default: s.resize(pick(s.size())); return s;  // truncated file
    }
  }

  std::mt19937_64 rng_;
};

// --- documented ranges of what loaded ----------------------------------------------------------

bool normal_or_zero(double v) { return v == 0.0 || std::fpclassify(v) == FP_NORMAL; }
bool positive(double v) { return v > 0.0 && std::fpclassify(v) == FP_NORMAL; }

std::string wing_out_of_range(const w::Wing& wing) {
  if (!positive(wing.span)) return "span";
  if (wing.outline.size() < 3) return "outline size";
  for (const auto& p : wing.outline)
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !normal_or_zero(p.x()) || !normal_or_zero(p.y()))
      return "outline point";
  if (!positive(wing.membrane.thickness)) return "membrane.thickness";
  const auto material_ok = [](const w::Material& m) {
    return positive(m.youngs_modulus) && positive(m.density) && m.poisson_ratio > -1.0 && m.poisson_ratio < 0.5;
  };
  if (!material_ok(wing.membrane.material)) return "membrane material";
  if (!(wing.membrane.nonstructural_mass_per_area >= 0.0) || !std::isfinite(wing.membrane.nonstructural_mass_per_area))
    return "nonstructural_mass_per_area";
  for (const auto& v : wing.veins) {
    if (v.points.size() < 2) return "vein points";
    if (!material_ok(v.material)) return "vein material";
    for (const auto* s : {&v.root_section, &v.tip_section}) {
      if (s->shape == w::Section::Shape::HollowCircle &&
          (!positive(s->outer_diameter) || !positive(s->wall) || s->wall > 0.5 * s->outer_diameter * (1 + 1e-12)))
        return "vein section";
      if (s->shape == w::Section::Shape::Rectangle && (!positive(s->width) || !positive(s->height)))
        return "vein section";
    }
  }
  if (!positive(wing.mesh.element_size) || !positive(wing.mesh.vein_element_size)) return "mesh sizes";
  if (w::estimated_mesh_elements(wing) > w::kMaxMeshElements) return "mesh budget";
  return "";
}

std::string case_out_of_range(const io::Case& c) {
  const auto& n = c.numerics;
  if (!positive(c.kinematics.frequency) || c.kinematics.frequency > io::kMaxFrequencyHz) return "frequency_hz";
  if (!(std::abs(c.kinematics.rotation_phase) <= 1.0)) return "rotation_phase";
  if (n.steps_per_cycle < 4 || n.cycles < 1 || n.total_steps() > io::kMaxTotalSteps) return "steps";
  if (n.chordwise_panels < 1 || n.chordwise_panels > 1000 || n.spanwise_panels < 1 || n.spanwise_panels > 1000)
    return "panels";
  if (!(n.core_radius > 0.0 && n.core_radius <= 1.0) || !positive(n.core_radius)) return "core_radius";
  if (!(n.coupling_tolerance > 0.0 && n.coupling_tolerance < 1.0) || !positive(n.coupling_tolerance))
    return "coupling_tolerance";
  if (n.wake_max_rows < 0 || n.max_coupling_iterations < 1) return "wake/coupling counts";
  if (c.air.enabled && !positive(c.air.density)) return "air.density";
  if (!c.air.freestream.allFinite()) return "air.freestream";
  if (c.name.empty() || io::folder_name_of(c.name) != c.name) return "name";
  if (c.structure.bodies < 1 || c.structure.bodies > 1000) return "structure.bodies";
  if (c.output.vtk_every < 0) return "vtk_every";
  return "";
}

std::string chain_out_of_range(const flapsim::mbd::ChainModel& chain) {
  if (chain.bodies.empty() || chain.joints.size() != chain.bodies.size()) return "bodies";
  for (const auto& b : chain.bodies) {
    if (!positive(b.length) || !positive(b.mass)) return "length or mass";
    if (!b.inertia.allFinite() || !b.center_of_mass.allFinite() || !b.outboard_joint.allFinite()) return "finite";
  }
  for (const auto& j : chain.joints)
    for (double v : {j.bend_stiffness, j.twist_stiffness, j.bend_damping, j.twist_damping})
      if (!(v >= 0.0) || !std::isfinite(v) || !normal_or_zero(v)) return "joint springs";
  return "";
}

// --- the driver ------------------------------------------------------------------------------

// Aborts the process if one mutant runs for more than 10 s (a hang), naming it.
class Watchdog {
 public:
  Watchdog() : thread_([this] { watch(); }) {}
  ~Watchdog() {
    done_ = true;
    thread_.join();
  }
  void start(const std::string& what) {
    what_ = what;
    started_ = std::chrono::steady_clock::now().time_since_epoch().count();
  }

 private:
  void watch() {
    while (!done_) {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
      if (now - started_.load() > std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::seconds(10)).count()) {
        std::fprintf(stderr, "fuzz: hang (> 10 s) in %s\n", what_.c_str());
        std::abort();
      }
    }
  }
  std::atomic<bool> done_{false};
  std::atomic<long long> started_{std::chrono::steady_clock::now().time_since_epoch().count()};
  std::string what_;
  std::thread thread_;
};

struct Tally {
  std::size_t loaded = 0, refused = 0;
};

// Feeds `count` mutants of `seed` to `load`, which returns "" or the out-of-range value.
Tally fuzz(const std::string& loader, const std::string& seed, std::uint64_t rng_seed, std::size_t count,
           const std::function<std::string(const std::string& text)>& load) {
  Mutator m(rng_seed);
  Watchdog watchdog;
  Tally tally;
  // The seed itself loads (else the mutants would test nothing).
  EXPECT_EQ(load(seed), "") << loader << ": the seed does not load";
  for (std::size_t i = 0; i < count; ++i) {
    const std::string text = m.mutate(seed);
    watchdog.start(loader + " mutant " + std::to_string(i));
    try {
      const std::string bad = load(text);
      EXPECT_EQ(bad, "") << loader << " mutant " << i << " loaded with '" << bad
                         << "' outside its documented range:\n" << text;
      ++tally.loaded;
    } catch (const InputError&) {
      ++tally.refused;
    } catch (const std::exception& e) {
      ADD_FAILURE() << loader << " mutant " << i << ": " << typeid(e).name() << ": " << e.what() << "\n" << text;
    } catch (...) {
      ADD_FAILURE() << loader << " mutant " << i << ": a non-standard exception\n" << text;
    }
    if (::testing::Test::HasFailure()) break;  // the first failure, with its mutant
  }
  std::printf("fuzz %s: %zu mutants, %zu loaded, %zu refused with InputError\n", loader.c_str(), count,
              tally.loaded, tally.refused);
  return tally;
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

}  // namespace
