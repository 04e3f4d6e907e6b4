// A solve with a shed leading edge sums the wake and the sheet at the collocation points
// again after its strips shed; between the two sums only the leading-edge rings' strengths
// change, whose segments are all among the edge's double-precision ones, so the second sum
// starts from the first one's part before them (VortexLatticeData::collocation_older;
// docs/performance.md, "The shed leading edge against `separated`"; detail::OlderPart). That must give the
// bits of the whole sum: checked on the revolving Robofly wing at 50°, whose strips shed at
// every step, against the whole sum over the solve's final segments.
#include "robofly_revolving.hpp"
#include "uvlm/lattice_internal.hpp"

#include <gtest/gtest.h>

#include <cstdio>

using namespace robofly_revolving;

TEST(SheetCollocationReuse, TheSumAfterSheddingIsTheWholeSumBitForBit) {
  VortexLatticeModel model;
  long compared = 0, different = 0, reused = 0;
  revolve_each(
      50.0, LeadingEdge::Shed, 60,
      [&](int k, VortexLatticeData& d, double, double) {
        const int np = model.panels();
        const Eigen::Matrix3Xd solved = d.wake_velocity;  // the solve's, the last sum reused
        for (int i = 0; i < np; ++i) d.eval.set(i, d.collocation.col(i));
        flapsim::uvlm::detail::induced_at_eval_points(model, d, static_cast<std::size_t>(np), false);
        for (int i = 0; i < np; ++i) {
          ++compared;
          if (!(solved.col(i) == d.eval.velocity(i))) ++different;
        }
        reused = d.solver_counts.reused_collocation_sums;
        return k < 40;
      },
      0.0, [&](VortexLatticeModel& m) { model = m; });
  std::printf("[ value ] %ld of 41 solves reused the first sum's part; %ld of %ld velocities differ\n", reused,
              different, compared);
  EXPECT_GT(reused, 30);  // the premise: the strips shed and the part was reused (41 solves)
  EXPECT_EQ(compared, 41 * 60);
  EXPECT_EQ(different, 0) << "of " << compared << " collocation points' velocities";
}
