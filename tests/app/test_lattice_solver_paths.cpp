// The flexible hawkmoth hover (cases/hover_flexible.toml, the shipped 10-body chain) at
// 12 × 20 panels, shortened to 25 steps: the lattice's circulations by GMRES preconditioned
// by an earlier factorisation (uvlm model.iterative_min_panels, the default at 240 panels)
// against the direct solve (a factorisation of every new influence matrix), the same coupled
// steps otherwise. Issue 29: the mean lift of the two within 1e-8 relative.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "coupled_case_steps.hpp"
#include "pipeline/io/case_file.hpp"

namespace {

struct ShortRun {
  double mean_lift = 0.0;  // [N]
  flapsim::uvlm::LatticeSolverCounts counts;
  long sub_iterations = 0;
};

ShortRun run_short_hover(bool iterative) {
  const std::string source = FLAPSIM_SOURCE_DIR;
  flapsim::io::Case c = flapsim::io::load_case_file(source + "/cases/hover_flexible.toml");
  c.numerics.chordwise_panels = 12;
  c.numerics.spanwise_panels = 20;
  c.numerics.cycles = 1;
  ShortRun r;
  const int steps = 25;
  flapsim::test::run_coupled_steps(
      c, source + "/cases/chains/hawkmoth_10_bodies.toml", steps,
      [&](flapsim::fsi::FsiModel& m) {
        if (!iterative) m.lattice.iterative_min_panels = 0;
      },
      [&](int, const flapsim::app::FsiSetup& setup, const flapsim::fsi::FsiData& data) {
        r.mean_lift += flapsim::test::lattice_lift(setup, data) / steps;
        r.counts = data.lattice->solver_counts;
        r.sub_iterations = data.total_iterations;
      });
  return r;
}

}  // namespace

TEST(LatticeSolverPaths, TheFlexibleHoverAt12By20GivesTheDirectSolvesMeanLift) {
  const ShortRun direct = run_short_hover(false), gmres = run_short_hover(true);
  std::printf("[ value ] 25 steps at 12 x 20: mean lift %.12g N direct, %.12g N by GMRES (%.2g relative); "
              "%ld / %ld lattice solves, GMRES %ld solves, %.2f iterations each, %ld factorisations (direct %ld)\n",
              direct.mean_lift, gmres.mean_lift, gmres.mean_lift / direct.mean_lift - 1.0, direct.counts.solves,
              gmres.counts.solves, gmres.counts.iterative_solves,
              double(gmres.counts.iterations) / std::max(1L, gmres.counts.iterative_solves),
              gmres.counts.factorisations, direct.counts.factorisations);
  ASSERT_GT(direct.mean_lift, 1e-4);  // a hovering hawkmoth wing early in its stroke lifts
  EXPECT_EQ(direct.counts.iterative_solves, 0);
  EXPECT_EQ(direct.counts.factorisations, direct.counts.solves);
  EXPECT_GT(gmres.counts.iterative_solves, gmres.counts.solves / 2);  // the path under test was taken
  EXPECT_LT(gmres.counts.factorisations, direct.counts.factorisations / 4);
  EXPECT_NEAR(gmres.mean_lift / direct.mean_lift, 1.0, 1e-8);  // issue 29
}
