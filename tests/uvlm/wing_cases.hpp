#pragma once
// Flat rectangular wings in a uniform stream, shared by the uvlm verification tests.
// Wing frame = ground frame: leading edge at x = 0, trailing edge at x = −c, span along +y;
// the air moves from the leading to the trailing edge with incidence α:
// V∞ = U(−cos α, 0, sin α); lift is the force along e_L = (sin α, 0, cos α) ⟂ V∞.

#include "uvlm/planform_grid.hpp"
#include "uvlm/vortex_lattice.hpp"

#include <cmath>

namespace flapsim::uvlm::testing {

struct RectangularWing {
  double chord = 1.0;         // [m]
  double aspect_ratio = 4.0;  // span / chord
  double alpha = 5.0 * M_PI / 180.0;
  double speed = 1.0;         // [m/s]
  double rho = 1.0;           // [kg/m³]
  int chordwise = 8, spanwise = 16;
  double wake_core = 1e-6;  // wake core radius / chord: effectively the singular kernel

  double span() const { return aspect_ratio * chord; }
  double area() const { return chord * span(); }
  Eigen::Vector3d free_stream() const { return speed * Eigen::Vector3d(-std::cos(alpha), 0.0, std::sin(alpha)); }
  Eigen::Vector3d lift_direction() const { return {std::sin(alpha), 0.0, std::cos(alpha)}; }
  PlanformGrid grid() const {
    PlanformGridOptions o;
    o.chordwise = chordwise;
    o.spanwise = spanwise;
    return make_rectangular_grid(chord, span(), o);
  }
  VortexLatticeModel model(int wake_capacity, WakeModel wake = WakeModel::Prescribed) const {
    VortexLatticeModel m;
    m.chordwise = chordwise;
    m.spanwise = spanwise;
    m.wake_capacity = wake_capacity;
    m.wake_model = wake;
    m.core = {CoreModel::LambOseen, wake_core * chord};
    return m;
  }
  double lift_coefficient(const PanelLoads& loads) const {
    return loads.total_force.dot(lift_direction()) / (0.5 * rho * speed * speed * area());
  }
};

/// Steady lift coefficients (Bernoulli, Kutta–Joukowski) with a wake 1000 spans long.
struct SteadyResult {
  double cl_bernoulli = 0.0, cl_kutta_joukowski = 0.0;
};
inline SteadyResult steady_lift(const RectangularWing& w) {
  const VortexLatticeModel m = w.model(2);
  VortexLatticeData d(m);
  solve_steady(m, d, w.grid().nodes, w.free_stream(), w.rho, 1000.0 * std::max(w.chord, w.span()));
  SteadyResult r;
  compute_bernoulli_loads(m, d);
  r.cl_bernoulli = w.lift_coefficient(d.loads);
  compute_kutta_joukowski_loads(m, d);
  r.cl_kutta_joukowski = w.lift_coefficient(d.loads);
  return r;
}

}  // namespace flapsim::uvlm::testing
