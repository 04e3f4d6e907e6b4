// The reduction's tip zone must carry a bending moment: a zone whose nodes lie on one
// line (a straight tip edge oblique to the chain axis) cannot, and the bending-moment load
// case came out as no load at all (reduction/tip_loads).
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cmath>
#include <vector>

#include "reduction/tip_loads.hpp"

namespace {

using namespace flapsim::reduction;

// The resultant of a load vector about the zone's centroid: Σ f, Σ f (s − s̄), −Σ f (n − n̄)
// (the definition in tip_loads.hpp).
Eigen::Vector3d resultant(const TipZone& z, const Eigen::VectorXd& s, const Eigen::VectorXd& n,
                          const Eigen::VectorXd& load) {
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    const double f = load[6 * i + 2];
    r += Eigen::Vector3d(f, f * (s[i] - z.s_centroid), -f * (n[i] - z.n_centroid));
  }
  return r;
}

// A plate of 11 × 11 nodes, chord n ∈ [0, 10] mm, whose tip edge is oblique to the axis:
// node (j, k) at n = k mm, s = j mm + 0.05 k (the tip row j = 10 runs from s = 10 to 10.5 mm
// along a straight line). A zone 0.6 mm long holds only that row: 11 nodes, spread in s
// (0.5 mm) and in n (10 mm), on one line.
TEST(TipZoneOnALine, TheZoneOfAnObliqueStraightTipEdgeCarriesTheBendingMoment) {
  const int rows = 11, cols = 11;
  Eigen::VectorXd s(rows * cols), n(rows * cols);
  for (int j = 0; j < rows; ++j)
    for (int k = 0; k < cols; ++k) {
      s[j * cols + k] = 1e-3 * (j + 0.05 * k);
      n[j * cols + k] = 1e-3 * k;
    }
  const TipZone zone = make_tip_zone(s, n, 0.6e-3, {});
  TipWrench moment;
  moment.moment_n = 1e-6;  // 1 µN m, the reduction's unit bending moment
  const Eigen::Vector3d r = resultant(zone, s, n, tip_load_vector(zone, s, n, moment));
  // The wrench asked for is the wrench applied (before: the moment came out 0).
  EXPECT_NEAR(r[1], 1e-6, 1e-12);
  EXPECT_NEAR(r[0], 0.0, 1e-12);
  EXPECT_NEAR(r[2], 0.0, 1e-12);
  TipWrench torque;
  torque.moment_s = 1e-6;
  const Eigen::Vector3d t = resultant(zone, s, n, tip_load_vector(zone, s, n, torque));
  EXPECT_NEAR(t[2], 1e-6, 1e-12);
  EXPECT_NEAR(t[1], 0.0, 1e-12);
  EXPECT_GT(zone.nodes.size(), 11u);  // the zone reaches past the tip row
}

}  // namespace
