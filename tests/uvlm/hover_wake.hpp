#pragma once
// A small flapping (hovering) wing that sheds a wake rolling up under it, shared by the
// wake tests: rectangular, aspect ratio 4, 6 × 10 panels, sweep ±60° about the root
// (z axis) and pitch ±45° about its mid-chord line, 26.1 Hz, no free stream.

#include "uvlm/planform_grid.hpp"
#include "uvlm/vortex_lattice.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <vector>

namespace flapsim::uvlm::testing {

struct HoverWing {
  double chord = 0.017;  // [m], about the hawkmoth's mean chord
  double root = 0.005;   // root offset from the sweep axis [m]
  double frequency = 26.1;
  int steps_per_cycle = 50;
  VortexLatticeModel model(int cycles) const {
    VortexLatticeModel m;
    m.chordwise = 6;
    m.spanwise = 10;
    m.wake_capacity = cycles * steps_per_cycle;
    m.core = {CoreModel::LambOseen, 0.2 * chord};
    return m;
  }
  double dt() const { return 1.0 / (frequency * steps_per_cycle); }
  /// Surface nodes and their velocities at time t [s].
  void pose(const PlanformGrid& grid, double t, Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& v) const {
    const double w = 2 * M_PI * frequency, deg = M_PI / 180;
    const double phi = 60 * deg * std::cos(w * t), dphi = -60 * deg * w * std::sin(w * t);
    const double th = -45 * deg * std::sin(w * t), dth = -45 * deg * w * std::cos(w * t);
    const Eigen::Matrix3d Rz = Eigen::AngleAxisd(phi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Matrix3d Ry = Eigen::AngleAxisd(th, Eigen::Vector3d::UnitY()).toRotationMatrix();
    const Eigen::Vector3d mid(-0.5 * chord, 0, 0);
    for (Eigen::Index k = 0; k < grid.nodes.cols(); ++k) {
      const Eigen::Vector3d p0 = grid.nodes.col(k) + Eigen::Vector3d(0, root, 0);
      const Eigen::Vector3d local = mid + Ry * (p0 - mid);  // pitched about the mid-chord line
      x.col(k) = Rz * local;
      // d/dt: sweep rate about z, pitch rate about the (swept) mid-chord line
      const Eigen::Vector3d pitch_vel = Rz * (Eigen::Vector3d::UnitY() * dth).cross(local - mid);
      v.col(k) = Eigen::Vector3d::UnitZ().cross(x.col(k)) * dphi + pitch_vel;
    }
  }
  PlanformGrid grid() const {
    PlanformGridOptions o;
    o.chordwise = 6;
    o.spanwise = 10;
    return make_rectangular_grid(chord, 4 * chord, o);
  }
  /// Run `cycles` cycles with model m into d; returns the lift (z force) of every step [N].
  std::vector<double> run(const VortexLatticeModel& m, VortexLatticeData& d, int cycles) const {
    const PlanformGrid g = grid();
    Eigen::Matrix3Xd x(3, m.nodes()), v(3, m.nodes());
    std::vector<double> lift;
    for (int k = 0; k < cycles * steps_per_cycle; ++k) {
      pose(g, k * dt(), x, v);
      solve(m, d, x, v, Eigen::Vector3d::Zero(), dt(), 1.225);
      lift.push_back(d.loads.total_force.z());
      advance(m, d);
    }
    return lift;
  }
};

}  // namespace flapsim::uvlm::testing
