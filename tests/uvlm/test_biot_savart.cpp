// Biot–Savart kernel against closed-form results.
#include "uvlm/biot_savart.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

using namespace flapsim::uvlm;

namespace {
const VortexCore kSharp{CoreModel::LambOseen, 1e-9};  // core far below every distance used
}

TEST(BiotSavart, StraightSegmentMatchesClosedForm) {
  // Segment from (0,0,0) to (L,0,0), point (x0, h, 0). Closed form (Katz & Plotkin eq. 2.68):
  // |v| = Γ/(4πh) [x0/√(x0²+h²) + (L−x0)/√((L−x0)²+h²)], direction +z (r0 × r1).
  const double L = 2.0, gamma = 3.0;
  for (const auto& [x0, h] : {std::pair{0.7, 0.3}, {-1.5, 0.8}, {3.0, 0.05}, {1.0, 10.0}}) {
    const Eigen::Vector3d v = segment_velocity({0, 0, 0}, {L, 0, 0}, gamma, {x0, h, 0}, kSharp);
    const double expected = gamma / (4 * M_PI * h) *
                            (x0 / std::hypot(x0, h) + (L - x0) / std::hypot(L - x0, h));
    EXPECT_NEAR(v.z(), expected, 1e-12 * std::abs(expected)) << "x0 " << x0 << " h " << h;
    EXPECT_NEAR(v.x(), 0.0, 1e-14);
    EXPECT_NEAR(v.y(), 0.0, 1e-14);
  }
}

TEST(BiotSavart, SquareRingAtItsCentre) {
  // Square ring of side a: |v| = 2√2 Γ/(π a) at the centre (4 sides, each Γ/(4π a/2)·2 cos 45°),
  // along the normal given by the right-hand rule.
  const double a = 0.4, gamma = 1.7;
  const Eigen::Vector3d c[4] = {{0, 0, 0}, {a, 0, 0}, {a, a, 0}, {0, a, 0}};
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k) v += segment_velocity(c[k], c[(k + 1) % 4], gamma, {a / 2, a / 2, 0}, kSharp);
  EXPECT_NEAR(v.z(), 2 * std::sqrt(2.0) * gamma / (M_PI * a), 1e-12);
  EXPECT_NEAR(v.head<2>().norm(), 0.0, 1e-13);
}

TEST(BiotSavart, CoreModelsNearALongSegment) {
  // A segment 2e4 r_c long seen from its middle at distance h is a line vortex:
  // v = Γ/(2πh)·f(h²/r_c²). Lamb–Oseen at h = r_c: f = 1 − e^(−1.25643) = 0.715301;
  // Vatistas n = 2 at h = r_c: f = 1/√2; cut-off: f = 0 inside r_c, 1 outside.
  const double rc = 1e-3, gamma = 1.0, L = 2e4 * rc;
  const auto v_at = [&](CoreModel m, double h) {
    return segment_velocity({-L / 2, 0, 0}, {L / 2, 0, 0}, gamma, {0, h, 0}, {m, rc}).z();
  };
  const double line = gamma / (2 * M_PI * rc);
  EXPECT_NEAR(v_at(CoreModel::LambOseen, rc) / line, 1 - std::exp(-1.25643), 1e-6);
  EXPECT_NEAR(v_at(CoreModel::Vatistas, rc) / line, 1 / std::sqrt(2.0), 1e-6);
  EXPECT_EQ(v_at(CoreModel::CutOff, 0.5 * rc), 0.0);
  EXPECT_NEAR(v_at(CoreModel::CutOff, 2 * rc) / (line / 2), 1.0, 1e-7);
  // Far from the core every model is the singular finite-segment kernel,
  // Γ/(2πh)·cos β with cos β = (L/2)/√((L/2)² + h²).
  const double h = 50 * rc, finite = gamma / (2 * M_PI * h) * (L / 2) / std::hypot(L / 2, h);
  for (CoreModel m : {CoreModel::CutOff, CoreModel::LambOseen, CoreModel::Vatistas})
    EXPECT_NEAR(v_at(m, h) / finite, 1.0, 1e-6);  // Vatistas tail: 1/(2x²) = 8e-8 at x = 2500
}

TEST(BiotSavart, ZeroOnTheSegmentItsLineAndForZeroLength) {
  const VortexCore core{CoreModel::LambOseen, 1e-3};
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0);
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(0.5, 0, 0), Eigen::Vector3d(0, 0, 0),
                                   Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(2, 0, 0)}) {
    const Eigen::Vector3d v = segment_velocity(a, b, 1.0, p, core);
    EXPECT_TRUE(v.allFinite());
    EXPECT_EQ(v.norm(), 0.0);
  }
  const Eigen::Vector3d v = segment_velocity(a, a, 1.0, {0.3, 0.2, 0.1}, core);
  EXPECT_TRUE(v.allFinite());
  EXPECT_EQ(v.norm(), 0.0);
}

TEST(BiotSavart, BatchKernelEqualsSumOfSegmentsOnAnyThreadCount) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  SegmentSet s;
  s.reserve(300);
  for (int k = 0; k < 300; ++k) s.push(u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), u(rng));
  PointSet p;
  p.reserve(200);
  p.size = 200;
  for (int i = 0; i < 200; ++i) p.set(i, {u(rng), u(rng), u(rng)});
  const VortexCore core{CoreModel::Vatistas, 0.01};
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    p.zero_velocity();
    add_induced_velocity(s, p, core);
    for (int i = 0; i < 200; i += 17) {
      Eigen::Vector3d ref = Eigen::Vector3d::Zero();
      for (std::size_t k = 0; k < s.size(); ++k)
        ref += segment_velocity({s.ax()[k], s.ay()[k], s.az()[k]}, {s.bx()[k], s.by()[k], s.bz()[k]},
                                s.gamma()[k], p.position(i), core);
      EXPECT_NEAR((p.velocity(i) - ref).norm(), 0.0, 1e-12 * (1 + ref.norm()));
    }
  }
}

TEST(BiotSavart, SegmentSetRefusesToGrowPastItsCapacity) {
  SegmentSet s;
  s.reserve(1);
  s.push(0, 0, 0, 1, 0, 0, 1);
  EXPECT_THROW(s.push(0, 0, 0, 1, 0, 0, 1), std::length_error);
}

TEST(BiotSavart, OneSegmentOfASetIsWhatTheSumHoldsOfIt) {
  // segment_velocity(set, k, p) is segment k's term of add_induced_velocity(set, ...): the
  // loads take a bound segment's own velocity out of the sum at its midpoint this way
  // (uvlm/lattice_internal.hpp, induced_at_bound_midpoints). There the exact velocity is 0,
  // but the rounded midpoint of a skewed segment lies off its line by ~1e-18 m, and inside a
  // 1e-11 m Lamb–Oseen core the kernel's velocity is Γ 1.26 h/(2π r_c²): up to ~1 m/s for
  // Γ = 1e-3 m²/s, h = 1e-18 m, not a rounding error of the sum.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.03, 0.03);  // [m], a 6 cm wing's box
  const VortexCore tiny{CoreModel::LambOseen, 1e-11};
  SegmentSet s;
  s.reserve(200);
  for (int k = 0; k < 200; ++k) s.push(u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), 1e-3);
  PointSet p;
  p.reserve(200);
  p.size = 200;
  for (std::size_t k = 0; k < 200; ++k)
    p.set(k, {0.5 * (s.ax()[k] + s.bx()[k]), 0.5 * (s.ay()[k] + s.by()[k]), 0.5 * (s.az()[k] + s.bz()[k])});
  add_induced_velocity(s, p, tiny);
  double largest_own = 0.0;
  for (std::size_t k = 0; k < 200; ++k) {
    const Eigen::Vector3d own = segment_velocity(s, k, p.position(k), tiny);
    const Eigen::Vector3d a(s.ax()[k], s.ay()[k], s.az()[k]), b(s.bx()[k], s.by()[k], s.bz()[k]);
    EXPECT_EQ(own, segment_velocity(a, b, s.gamma()[k], p.position(k), tiny));  // the same kernel
    Eigen::Vector3d others = Eigen::Vector3d::Zero();  // the sum without segment k, one by one
    for (std::size_t l = 0; l < 200; ++l)
      if (l != k) others += segment_velocity(s, l, p.position(k), tiny);
    EXPECT_NEAR((p.velocity(k) - own - others).norm(), 0.0, 1e-9 * (1.0 + own.norm() + others.norm()));
    largest_own = std::max(largest_own, own.norm());
  }
  EXPECT_GT(largest_own, 1e-3);  // [m/s]: the own velocity is there to take out
  EXPECT_THROW(segment_velocity(s, 200, p.position(0), tiny), std::out_of_range);
}
