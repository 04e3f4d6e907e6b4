// The hover of cases/hover_periodic.toml, shortened (4 x 6 panels, 40 steps per cycle,
// 5 cycles), gives the same history.csv bit for bit with 1, 2 and 3 OpenMP threads, for
// each of the three ways the wake is summed: the convected far wake by the tree code (the
// case), the convected far wake by the direct sum, and the whole free wake by the tree
// code, and the case with the shed leading edge (its far wake by the tree). Each
// wake-velocity sum runs in parallel over its target points (the direct sum once points x
// segments > 1e5, the tree always) and adds every point's terms in a fixed order, so the
// thread count may not change a single bit (docs/performance.md,
// "Portable build, runtime-dispatched kernels").
// Adding one ulp to one wake node's velocity per step when more than one thread runs makes
// the far-wake-by-tree variant fail (checked); multiplying one sheet node's velocity by
// 1 + 1e-7 (a single-precision sum's rounding) when more than one thread runs makes the
// shed variant fail (checked, 1 Dec). About 9 CPU seconds.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace {

const std::string kSource = FLAPSIM_SOURCE_DIR;

/// `text` with the one line that starts with `key` replaced by `line`.
std::string with_line(std::string text, const std::string& key, const std::string& line) {
  const std::size_t at = text.find("\n" + key);
  EXPECT_NE(at, std::string::npos) << key << " not in cases/hover_periodic.toml";
  if (at == std::string::npos) return text;
  const std::size_t end = text.find('\n', at + 1);
  return text.replace(at + 1, end - at - 1, line);
}

/// The first line where a and b differ, as "line N: <a's> / <b's>"; "" if they are equal.
std::string first_difference(const std::string& a, const std::string& b) {
  std::istringstream sa(a), sb(b);
  std::string la, lb;
  for (int n = 1;; ++n) {
    const bool more_a = static_cast<bool>(std::getline(sa, la)), more_b = static_cast<bool>(std::getline(sb, lb));
    if (!more_a && !more_b) return "";
    if (more_a != more_b || la != lb) return "line " + std::to_string(n) + ": " + la + " / " + lb;
  }
}

}  // namespace

TEST(HoverPeriodicThreads, HistoryIsBitIdenticalForOneTwoAndThreeThreads) {
  flapsim::test::ScratchDir dir("hover_periodic_threads");
  std::string short_case = flapsim::test::read_text(kSource + "/cases/hover_periodic.toml");
  short_case = with_line(short_case, "wing =", "wing = \"" + kSource + "/wings/hawkmoth.toml\"");
  short_case = with_line(short_case, "cycles =", "cycles = 5");
  short_case = with_line(short_case, "steps_per_cycle =", "steps_per_cycle = 40");
  short_case = with_line(short_case, "chordwise_panels =", "chordwise_panels = 4");
  short_case = with_line(short_case, "spanwise_panels =", "spanwise_panels = 6");
  struct Variant {
    const char* name;
    std::string text;
  };
  // The whole wake goes to the tree once it has 2000 segments (tree_min_segments): here
  // from about step 155 of 200 on.
  const std::vector<Variant> variants = {
      {"far_wake_tree", short_case},
      {"far_wake_direct", with_line(short_case, "wake_sum =", "wake_sum = \"direct\"")},
      {"free_wake_tree", with_line(short_case, "far_wake_cycles =", "far_wake_cycles = 0")},
      // The shed leading edge (its sheet summed with the wake, the shedding's bordered solve,
      // the merges): a flow whose cycles do not repeat, where one rounding difference would
      // grow into a different history within a few steps.
      {"shed", with_line(short_case, "[numerics]", "[numerics]\nleading_edge = \"shed\"")},
  };
  for (const Variant& v : variants) {
    const auto case_file = dir / (std::string(v.name) + ".toml");
    std::ofstream(case_file) << v.text;
    std::string history[3];
    for (int threads = 1; threads <= 3; ++threads) {
      const auto out = dir / (std::string(v.name) + "_" + std::to_string(threads));
      ASSERT_EQ(flapsim::test::run_flapsim("run '" + case_file.string() + "' -o '" + out.string() +
                                           "' --threads " + std::to_string(threads)),
                0)
          << v.name;
      history[threads - 1] = flapsim::test::read_text(out / "history.csv");
    }
    ASSERT_GT(history[0].size(), 200u * 100u) << v.name << ": history.csv missing or short";
    EXPECT_EQ(first_difference(history[0], history[1]), "") << v.name << ": 1 and 2 threads differ";
    EXPECT_EQ(first_difference(history[0], history[2]), "") << v.name << ": 1 and 3 threads differ";
  }
}
