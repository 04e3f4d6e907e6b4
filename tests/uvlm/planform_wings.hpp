#pragma once
// Flat wings of any planform in a steady stream, for the load tests: the lattice nodes are
// laid out here directly (span stations, leading edge and chord as functions of the span
// position, and an optional shear of the chordwise grid lines), so the same planform can be
// meshed in different ways. Frame as wing_cases.hpp: leading edge toward +x, span along y,
// V∞ = U(−cos α, 0, sin α), lift along (sin α, 0, cos α), drag along V∞.

#include "uvlm/vortex_lattice.hpp"

#include <cmath>
#include <functional>
#include <vector>

namespace flapsim::uvlm::testing {

struct PlanformWing {
  int chordwise = 8;
  std::vector<double> stations;                           // span stations y_j, j = 0..ns [m]
  std::function<double(double)> leading_edge;             // x of the leading edge at y [m]
  std::function<double(double)> chord;                    // streamwise chord at y [m]
  std::function<double(int)> shear = [](int) { return 0.0; };  // tan of the tilt of grid line j

  int spanwise() const { return static_cast<int>(stations.size()) - 1; }
  /// Node (i, j): fraction i/nc of the chord behind the leading edge at y_j; grid line j is
  /// tilted about its mid-chord point, y = y_j + shear(j) (x − x_mid).
  Eigen::Matrix3Xd nodes() const {
    const int nc = chordwise, ns = spanwise();
    Eigen::Matrix3Xd p(3, (nc + 1) * (ns + 1));
    for (int j = 0; j <= ns; ++j) {
      const double y = stations[j], le = leading_edge(y), c = chord(y);
      for (int i = 0; i <= nc; ++i) {
        const double x = le - c * i / nc;
        p.col(i + (nc + 1) * j) = Eigen::Vector3d(x, y + shear(j) * (x - (le - 0.5 * c)), 0.0);
      }
    }
    return p;
  }
};

inline std::vector<double> uniform_stations(double y0, double y1, int ns) {
  std::vector<double> y(ns + 1);
  for (int j = 0; j <= ns; ++j) y[j] = y0 + (y1 - y0) * j / ns;
  return y;
}

/// Steady coefficients of one lattice: both load routes and the Trefftz plane.
struct SteadyLoads {
  double cl_bernoulli = 0, cd_bernoulli = 0;       // Bernoulli route with the leading-edge force
  double cl_kutta_joukowski = 0, cd_kutta_joukowski = 0;
  double cl_trefftz = 0, cd_trefftz = 0;
  double suction = 0;  // Σ |suction| / (q S), the leading-edge suction coefficient
  double normal = 0;   // Σ F·n / (q S) of the Bernoulli route without the leading-edge force
  double area = 0, span = 0;  // lattice area [m²] and span [m]
  std::vector<double> strip_gamma, strip_mid;  // trailing-edge circulation and mid-span y of each strip
};

/// planar_wake: the wake leaves in the wing's plane (toward −x) instead of along V∞;
/// wake_core: the model's wake core radius [m] (the steady lattice sees its wake through the
/// bound core whatever it is: docs/uvlm.md, "Steady lattice").
inline SteadyLoads steady_loads(const PlanformWing& w, double alpha, LeadingEdge leading_edge,
                                bool planar_wake = false, double wake_core = 1e-6) {
  VortexLatticeModel m;
  m.chordwise = w.chordwise;
  m.spanwise = w.spanwise();
  m.wake_capacity = 2;
  m.wake_model = WakeModel::Prescribed;
  m.core = {CoreModel::LambOseen, wake_core};
  m.leading_edge = leading_edge;
  VortexLatticeData d(m);
  const Eigen::Vector3d v(-std::cos(alpha), 0.0, std::sin(alpha));
  const Eigen::Vector3d lift(std::sin(alpha), 0.0, std::cos(alpha));
  const Eigen::Matrix3Xd nodes = w.nodes();
  solve_steady(m, d, nodes, v, 1.0, 1e4 * (w.stations.back() - w.stations.front()),
               planar_wake ? Eigen::Vector3d(-1.0, 0.0, 0.0) : v);
  SteadyLoads r;
  r.area = d.area.sum();
  r.span = w.stations.back() - w.stations.front();
  const double qs = 0.5 * r.area;  // ρ = 1, U = 1
  compute_kutta_joukowski_loads(m, d);
  r.cl_kutta_joukowski = d.loads.total_force.dot(lift) / qs;
  r.cd_kutta_joukowski = d.loads.total_force.dot(v) / qs;
  compute_bernoulli_loads(m, d);
  r.cl_bernoulli = d.loads.total_force.dot(lift) / qs;
  r.cd_bernoulli = d.loads.total_force.dot(v) / qs;
  r.suction = d.loads.suction.colwise().norm().sum() / qs;
  for (int k = 0; k < m.panels(); ++k)
    r.normal += (d.loads.force.col(k) - d.loads.leading_edge_force.col(k)).dot(d.normal.col(k)) / qs;
  for (int j = 0; j < m.spanwise; ++j) {
    r.strip_gamma.push_back(d.gamma(m.panel(m.chordwise - 1, j)));
    r.strip_mid.push_back(0.5 * (w.stations[j] + w.stations[j + 1]));
  }
  const TrefftzPlaneLoads t = trefftz_plane_loads(m, d);
  r.cl_trefftz = t.lift / qs;
  r.cd_trefftz = t.drag / qs;
  return r;
}

}  // namespace flapsim::uvlm::testing
