// The influence coefficients of a rigidly moving wing (model.reuse_rigid_influence,
// uvlm/rigid_motion.hpp): a(i, k) = v_k(x_i)·n_i is invariant under a rotation and a
// translation of the whole lattice (velocity and normal turn alike), so the columns of the
// rings off the last chordwise row are kept while the wing moves rigidly; the last row's
// rings end on the trailing-edge vortex, which follows the edge's speed, and are recomputed.
#include "uvlm/planform_grid.hpp"
#include "uvlm/rigid_motion.hpp"
#include "uvlm/vortex_lattice.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace flapsim::uvlm;

namespace {

/// A cambered 6 × 8 lattice (not planar, so a mirror image is not a rigid motion of it).
Eigen::Matrix3Xd cambered_lattice() {
  PlanformGridOptions o;
  o.chordwise = 6;
  o.spanwise = 8;
  Eigen::Matrix3Xd x = make_rectangular_grid(0.02, 0.05, o).nodes;
  for (Eigen::Index k = 0; k < x.cols(); ++k) x(2, k) = 0.1 * x(0, k) * (0.02 + x(0, k)) / 0.02;
  return x;
}

Eigen::Matrix3d rotation(double a, double b, double c) {
  return (Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(b, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(c, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

}  // namespace

TEST(RigidMotion, RotationsAndTranslationsAreRigidDeformationsAndMirrorsAreNot) {
  const Eigen::Matrix3Xd x = cambered_lattice();
  const Eigen::Vector3d t(0.3, -0.1, 0.2);
  const Eigen::Matrix3Xd moved = (rotation(1.1, -0.4, 2.5) * x).colwise() + t;
  EXPECT_TRUE(is_rigid_motion(x, x));
  EXPECT_TRUE(is_rigid_motion(x, moved));
  // One node moved by 1e-9 of the lattice's size (0.054 m): a deformation, far above the
  // tolerance (1e-12 of the size) and far below anything a structure would do.
  Eigen::Matrix3Xd bent = moved;
  bent(2, 40) += 0.054e-9;
  EXPECT_FALSE(is_rigid_motion(x, bent));
  // A wing bent like a flexible one: tip nodes raised 1 mm.
  Eigen::Matrix3Xd flexed = x;
  for (Eigen::Index k = 0; k < x.cols(); ++k) flexed(2, k) += 1e-3 * std::pow(x(1, k) / 0.05, 2);
  EXPECT_FALSE(is_rigid_motion(x, flexed));
  // Mirror image (z → −z): every distance is kept, the orientation is not.
  Eigen::Matrix3Xd mirror = x;
  mirror.row(2) *= -1.0;
  EXPECT_FALSE(is_rigid_motion(x, mirror));
  EXPECT_FALSE(is_rigid_motion(x, x.leftCols(10)));  // different point sets
  Eigen::Matrix3Xd nan = moved;
  nan(0, 3) = std::nan("");
  EXPECT_FALSE(is_rigid_motion(x, nan));
}

namespace {

struct FlapRun {
  std::vector<Eigen::Vector3d> force;
  bool reused = true;  // the influence matrix's nodes stayed those of the first solve
};

/// The lattice above flapping rigidly (stroke ±60° about z at 25 Hz, pitch ±45° about the
/// span axis, the wing's root 5 mm from the axis) or, with flex > 0, bending as well (tip
/// raised by flex·sin), free wake with a Lamb–Oseen core of 0.2 chords, 24 steps of 1/100
/// of the period: the total force of every step.
FlapRun flap(bool reuse, double flex) {
  const Eigen::Matrix3Xd x0 = (cambered_lattice().colwise() + Eigen::Vector3d(0.0, 0.005, 0.0)).eval();
  const double f = 25.0, dt = 1.0 / (100 * f), rho = 1.225;
  VortexLatticeModel m;
  m.chordwise = 6;
  m.spanwise = 8;
  m.wake_capacity = 30;
  m.core = {CoreModel::LambOseen, 0.2 * 0.02};
  m.reuse_rigid_influence = reuse;
  VortexLatticeData d(m);
  auto pose = [&](double t) {
    const double w = 2 * M_PI * f;
    Eigen::Matrix3Xd x = x0;
    for (Eigen::Index k = 0; k < x.cols(); ++k) x(2, k) += flex * std::sin(w * t) * std::pow(x(1, k) / 0.055, 2);
    return Eigen::Matrix3Xd(rotation(M_PI / 3 * std::cos(w * t), 0.0, 0.0) *
                            Eigen::AngleAxisd(M_PI / 4 * std::sin(w * t), Eigen::Vector3d::UnitY()).toRotationMatrix() * x);
  };
  FlapRun r;
  for (int k = 0; k < 24; ++k) {
    const double t = k * dt, h = 1e-6 * dt;
    const Eigen::Matrix3Xd X = pose(t), V = (pose(t + h) - pose(t - h)) / (2 * h);
    solve(m, d, X, V, Eigen::Vector3d::Zero(), dt, rho);
    r.force.push_back(d.loads.total_force);
    advance(m, d);
  }
  r.reused = d.influence_nodes == pose(0.0);  // still the first solve's nodes
  return r;
}

}  // namespace

TEST(RigidInfluence, ARigidlyFlappingWingGivesTheSameLoadsToRoundOff) {
  const FlapRun kept = flap(true, 0.0), fresh = flap(false, 0.0);
  EXPECT_TRUE(kept.reused);    // the columns off the last row were kept from the first step
  EXPECT_FALSE(fresh.reused);  // recomputed at every solve
  double peak = 0.0, worst = 0.0;
  for (std::size_t k = 0; k < fresh.force.size(); ++k) {
    peak = std::max(peak, fresh.force[k].norm());
    worst = std::max(worst, (kept.force[k] - fresh.force[k]).norm());
  }
  std::printf("rigid flap, 24 steps: peak force %.3g N, largest difference %.2g N (%.2g of the peak)\n", peak,
              worst, worst / peak);
  ASSERT_GT(peak, 1e-4);  // a loaded wing
  // Kept and recomputed coefficients differ by their rounding (~1e-16 relative); the
  // solution amplifies it by the matrix's condition number and 24 steps of wake
  // convection: 1e-11 of the peak force leaves room for that and fails on any real change
  // (a coefficient off by 1e-6 moves the force by about that fraction).
  EXPECT_LT(worst, 1e-11 * peak);
}

TEST(RigidInfluence, AFlexingWingIsRecomputedAtEverySolve) {
  // The same flap with the tip bending 1 mm: no reuse, the loads bit for bit those of the
  // run that recomputes the matrix at every solve.
  const FlapRun kept = flap(true, 1e-3), fresh = flap(false, 1e-3);
  EXPECT_FALSE(kept.reused);
  ASSERT_EQ(kept.force.size(), fresh.force.size());
  for (std::size_t k = 0; k < fresh.force.size(); ++k) EXPECT_EQ(kept.force[k], fresh.force[k]) << "step " << k;
}
