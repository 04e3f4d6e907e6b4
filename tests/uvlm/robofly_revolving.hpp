#pragma once
// The Robofly wing revolving at constant speed, the conditions of docs/uvlm.md "Leading
// edge: validation and the default" (test_revolving_wing.cpp, test_revolving_wing_shed.cpp).
#include "uvlm/planform_grid.hpp"
#include "uvlm/vortex_lattice.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace robofly_revolving {

using namespace flapsim::uvlm;

struct Coefficients {
  double lift = 0.0, drag = 0.0;  // vertical and horizontal (against the motion) force coefficients
};

/// wings/outlines/robofly_dickinson_outline.csv (y from the pivot, root at 0.25 R), R = 0.25 m,
/// 6 × 10 panels, revolving about z at 1 rev/s with geometric angle of attack α, free wake
/// with a Lamb–Oseen core of 0.2 mean chords, half a revolution in `steps` steps. `each`
/// is called after every solve with (step, data, lift coefficient, drag coefficient), the
/// coefficients on the speed at r2 (the radius of gyration of the area); it returns false
/// to stop the run. `viscosity` > 0 [m²/s]: the cores grow with age (laminar Lamb–Oseen,
/// core_growth.hpp with a1 = 0); 0: fixed cores. `adjust` may change the model's numerics
/// last (its sums: precision, tree code, far wake).
inline void keep_model(VortexLatticeModel&) {}
template <class Each, class Adjust = void (*)(VortexLatticeModel&)>
void revolve_each(double alpha_deg, LeadingEdge leading_edge, int steps, Each each, double viscosity = 0.0,
                  Adjust adjust = keep_model) {
  const double R = 0.25, omega = 2.0 * M_PI, rho = 1.0;
  std::ifstream in(std::string(FLAPSIM_SOURCE_DIR) + "/wings/outlines/robofly_dickinson_outline.csv");
  std::vector<Eigen::Vector2d> outline;
  double x = 0.0, y = 0.0;
  for (std::string line; std::getline(in, line);)
    if (std::sscanf(line.c_str(), "%lf,%lf", &x, &y) == 2) outline.emplace_back(R * x, R * y);
  PlanformGridOptions o;  // 6 × 10
  const PlanformGrid g = make_planform_grid(outline, o);
  double second_moment = 0.0;  // ∫∫ y² dA of the polygon
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const Eigen::Vector2d a = outline[i], b = outline[(i + 1) % outline.size()];
    second_moment += (a.x() * b.y() - b.x() * a.y()) * (a.y() * a.y() + a.y() * b.y() + b.y() * b.y()) / 12.0;
  }
  const double area = g.outline_area, r2 = std::sqrt(std::abs(second_moment) / area);
  const double q = 0.5 * rho * omega * omega * r2 * r2 * area;
  VortexLatticeModel m;
  m.chordwise = o.chordwise;
  m.spanwise = o.spanwise;
  m.leading_edge = leading_edge;
  const double dt = M_PI / omega / steps;
  m.wake_capacity = steps + 1;
  m.core = {CoreModel::LambOseen, 0.2 * area / R};
  if (viscosity > 0.0) {
    m.core_growth.enabled = true;
    m.core_growth.kinematic_viscosity = viscosity;
    m.core_growth.squire_a1 = 0.0;
  }
  adjust(m);
  VortexLatticeData d(m);
  Eigen::Matrix3Xd X(3, g.nodes.cols()), V(3, g.nodes.cols());
  const Eigen::Vector3d w(0.0, 0.0, -omega);  // the leading edge (+x_W) leads
  for (int k = 0; k <= steps; ++k) {
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(-omega * k * dt, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    X = turn * Eigen::AngleAxisd(-alpha_deg * M_PI / 180.0, Eigen::Vector3d::UnitY()).toRotationMatrix() * g.nodes;
    for (Eigen::Index i = 0; i < X.cols(); ++i) V.col(i) = w.cross(X.col(i));
    solve(m, d, X, V, Eigen::Vector3d::Zero(), dt, rho);
    const Eigen::Vector3d motion = w.cross(turn * Eigen::Vector3d::UnitY()).normalized();
    if (!each(k, d, d.loads.total_force.z() / q, -d.loads.total_force.dot(motion) / q)) return;
    if (k < steps) advance(m, d);
  }
}

/// Mean coefficients over 90°–180° of revolution (revolve_each).
inline Coefficients revolve(double alpha_deg, LeadingEdge leading_edge, int steps = 30, double viscosity = 0.0) {
  Coefficients c;
  int n = 0;
  revolve_each(
      alpha_deg, leading_edge, steps,
      [&](int k, const VortexLatticeData&, double lift, double drag) {
        if (k >= steps / 2) {
          c.lift += lift;
          c.drag += drag;
          ++n;
        }
        return true;
      },
      viscosity);
  c.lift /= n;
  c.drag /= n;
  return c;
}

/// The translational coefficients measured on the Robofly wing, Dickinson et al. 1999's fit.
inline double measured_lift(double alpha_deg) { return 0.225 + 1.58 * std::sin((2.13 * alpha_deg - 7.20) * M_PI / 180.0); }
inline double measured_drag(double alpha_deg) { return 1.92 - 1.55 * std::cos((2.04 * alpha_deg - 9.82) * M_PI / 180.0); }

}  // namespace robofly_revolving
