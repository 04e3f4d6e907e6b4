#include "mbd/quasi_static_deflection.hpp"

#include "mbd/chain_data.hpp"
#include "mbd/chain_dynamics.hpp"
#include "mbd/chain_loads.hpp"

#include <Eigen/LU>

#include <cmath>
#include <stdexcept>

namespace flapsim::mbd {

QuasiStaticDeflection peak_quasi_static_deflection(const ChainModel& model, const BaseMotion& base,
                                                   double period, int samples, double t0) {
  return peak_quasi_static_deflection(model, base, period, samples, QuasiStaticLoads{}, t0);
}

QuasiStaticDeflection peak_quasi_static_deflection(const ChainModel& model, const BaseMotion& base,
                                                   double period, int samples,
                                                   const QuasiStaticLoads& loads_at, double t0) {
  const int n = model.num_dofs();
  if (n == 0) throw std::invalid_argument("quasi-static deflection: the chain has no joints");
  if (!(period > 0.0) || samples < 1)
    throw std::invalid_argument("quasi-static deflection: the period must be positive and samples at least 1");
  ChainData data(model);
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(data.stiffness);
  if (!lu.isInvertible()) throw std::invalid_argument("quasi-static deflection: the joint stiffness is singular");
  const Eigen::VectorXd rest = model.rest_angles();
  const Eigen::VectorXd at_rest = Eigen::VectorXd::Zero(n);
  const Loads none(model.num_bodies());
  Loads external(model.num_bodies());
  QuasiStaticDeflection peak;
  const int first = model.first_jointed_body();
  for (int k = 0; k < samples; ++k) {
    const double t = t0 + period * k / samples;
    compute_all_terms(model, data, base(t), rest, at_rest, none);
    if (loads_at) {  // the external loads at this pose, then their generalized forces
      external.clear();
      loads_at(t, data, external);
      compute_generalized_loads(model, data, external);
    }
    // At rest the springs and dampers give nothing: H is the inertial bias.
    const Eigen::VectorXd dq = lu.solve(data.generalized_load - data.inertial_bias - data.spring_force);
    double bend = 0.0, twist = 0.0;
    for (int i = 0; i < n; i += 2) {
      bend += dq(i);
      twist += dq(i + 1);
    }
    if (std::abs(bend) > peak.tip_bend || std::abs(twist) > peak.tip_twist) peak.time = t;
    peak.tip_bend = std::max(peak.tip_bend, std::abs(bend));
    peak.tip_twist = std::max(peak.tip_twist, std::abs(twist));
    for (int i = 0; i < n; ++i)
      if (std::abs(dq(i)) > peak.joint_angle) {
        peak.joint_angle = std::abs(dq(i));
        peak.joint = first + i / 2;
        peak.twist = (i % 2) == 1;
      }
  }
  return peak;
}

}  // namespace flapsim::mbd
