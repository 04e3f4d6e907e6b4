// The search of flapsim optimize (pipeline/app/optimize/nlopt_search.hpp): --max-evaluations
// counts the points run, not NLopt's asks. NLopt asks again for points it has had (a step
// clamped back onto a bound); each is run once and served again from the points seen, but
// NLopt's own cap counted every ask. Measured (4 Dec 2026, Debian's NLopt 2.7, the
// objectives below): COBYLA with a cap of 14 asks ran 11 points (it asked for 3 again), so
// a search "stopped at 14 evaluations" listed 11 runs in evaluations.csv.

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <set>
#include <vector>

#include "pipeline/app/optimize/nlopt_search.hpp"

namespace flapsim::optimize {
namespace {

struct Search {
  std::vector<std::vector<double>> runs;
  SearchResult result;
  Search(Algorithm algorithm, int max_evaluations, const std::function<double(double, double)>& f) {
    SearchOptions options;
    options.algorithm = algorithm;
    options.max_evaluations = max_evaluations;
    result = search({0.0, 0.0}, {1.0, 1.0}, {0.5, 0.5}, 0, options, [&](const std::vector<double>& x) {
      runs.push_back(x);
      return PointValue{f(x[0], x[1]), {}};
    });
  }
  bool each_point_once() const {
    return std::set<std::vector<double>>(runs.begin(), runs.end()).size() == runs.size();
  }
};

// A paraboloid whose top (0.9, 1.2) lies beyond the bound y = 1: COBYLA's steps toward it are
// clamped onto the bound, points it had already.
double beyond_the_bound(double x, double y) { return -(x - 0.9) * (x - 0.9) - (y - 1.2) * (y - 1.2); }

TEST(NloptSearch, MaxEvaluationsCountsThePointsRunNotNloptsAsks) {
  const Search s(Algorithm::cobyla, 14, beyond_the_bound);
  EXPECT_EQ(s.runs.size(), 14u);  // 11 before (NLopt's asks 10, 12 and 14 were repeats)
  EXPECT_TRUE(s.each_point_once());
  EXPECT_TRUE(s.result.max_evaluations_reached);
  EXPECT_EQ(s.result.stop_reason, "the maximum number of evaluations was reached");
}

TEST(NloptSearch, ASmallMaximumStopsAfterThatManyRuns) {
  for (const int n : {1, 2, 3, 5, 10})
    for (const Algorithm a : {Algorithm::bobyqa, Algorithm::cobyla}) {
      const Search s(a, n, beyond_the_bound);
      EXPECT_EQ(s.runs.size(), static_cast<std::size_t>(n)) << n;
      EXPECT_TRUE(s.each_point_once()) << n;
      EXPECT_TRUE(s.result.max_evaluations_reached) << n;
    }
}

TEST(NloptSearch, ASearchThatConvergesWithinTheMaximumSaysItConverged) {
  // x + y: BOBYQA reaches the corner (1, 1) and converges after 13 points, its 14th ask a
  // repeat: the larger cap on NLopt's asks does not keep a converged search going.
  const Search s(Algorithm::bobyqa, 14, [](double x, double y) { return x + y; });
  EXPECT_EQ(s.runs.size(), 13u);
  EXPECT_TRUE(s.each_point_once());
  EXPECT_FALSE(s.result.max_evaluations_reached);
  EXPECT_EQ(s.result.stop_reason, "the step fell below the x tolerance (converged)");
  double best = 0.0;
  for (const auto& x : s.runs) best = std::max(best, x[0] + x[1]);
  EXPECT_DOUBLE_EQ(best, 2.0);  // the corner was run
}

}  // namespace
}  // namespace flapsim::optimize
