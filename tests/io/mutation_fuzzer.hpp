#pragma once
/// \file mutation_fuzzer.hpp
/// \brief The mutation fuzzer of the input tests (tests/io/test_fuzz_loaders.cpp,
/// tests/app/test_fuzz_sweep_arguments.cpp): from a valid seed text, a fixed-seed generator
/// makes mutants (bytes flipped, inserted, deleted; lines dropped, doubled, swapped; numbers
/// replaced by edge values; pieces of TOML structure inserted; truncation), and `fuzz`
/// feeds them to a loader, which must load each one with its values in their documented
/// ranges or refuse it with flapsim::InputError: any other exception, a crash or a hang
/// (over 10 s: the process aborts naming the mutant) fails the test.

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <typeinfo>
#include <utility>
#include <vector>

#include "wings/loader/input_error.hpp"

namespace flapsim::test {

/// Mutants per loader: 600 in `make test`, FLAPSIM_FUZZ_MUTANTS in `make fuzz`.
inline std::size_t mutants_per_loader() {
  if (const char* n = std::getenv("FLAPSIM_FUZZ_MUTANTS")) return std::strtoul(n, nullptr, 10);
  return 600;
}

// --- the mutator --------------------------------------------------------------------------

inline const std::vector<std::string> kEdgeValues = {
    "0", "-0", "0.0", "1", "-1", "1e-320", "-4.9e-324", "2.2250738585072014e-308", "1e-300", "1e308",
    "1.7976931348623157e308", "1e400", "inf", "-inf", "nan", "9007199254740992", "9007199254740993",
    "9223372036854775807", "-9223372036854775808", "2147483647", "2147483648", "-2147483649", "4294967296",
    "65536", "1000000", "100000000", "3.0", "1e-6", "0.5", "\"x\"", "[]", "[1, 2]", "true", "{}"};

// Pieces of TOML's structure (headers, multi-line strings, escapes, non-ASCII text, a date
// and a space) where toml++ 3.x has assertions and undefined behaviour of its own
// (wings/loader/toml_preflight.hpp).
inline const std::vector<std::string> kPieces = {"\n[", "\n[[", "[#", "]]", "\"\"\"", "'''", "\\\n ", "\xC2\xA7", "\xE2\x80\xA8",
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
inline Tally fuzz(const std::string& loader, const std::string& seed, std::uint64_t rng_seed, std::size_t count,
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
    } catch (const flapsim::InputError&) {
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

}  // namespace flapsim::test
