#pragma once
// The rotation-phase paper's 3-body system (chain_test_models.hpp) integrated by
// flapsim's multibody code alone: the trajectory that tests/mbd checks against Simbody
// and tests/app checks `flapsim run cases/three_body.toml` against.

#include <Eigen/Core>

#include <vector>

#include "chain_test_models.hpp"
#include "mbd/chain_data.hpp"
#include "mbd/chain_kinematics.hpp"
#include "mbd/generalized_alpha.hpp"

namespace flapsim::mbd::test {

struct Trajectory {
  std::vector<double> t;
  std::vector<Eigen::Vector3d> a;  // point A [m]
  std::vector<Eigen::Vector4d> q;  // θ₂, α₂, θ₃, α₃ [rad]
};

// Generalized-α (ρ∞ = 0.9, the default), the eq. 6 loads at each step's end time;
// samples every steps_per_sample steps, from t = 0 to t_end.
inline Trajectory integrate_three_body(const ChainModel& model, double t_end, int samples,
                                       int steps_per_sample) {
  ChainData data(model);
  const BaseMotion base = make_base_motion(three_body_kinematics());
  Loads loads(model.num_bodies());
  GeneralizedAlphaSettings settings;
  settings.rho_infinity = 0.9;
  const int n = model.num_dofs();
  three_body_loads(0.0, loads);
  ChainState state = make_initial_state(model, data, base, 0.0, Eigen::VectorXd::Zero(n),
                                        Eigen::VectorXd::Zero(n), loads);
  const double dt = t_end / (samples * steps_per_sample);
  const Eigen::Vector3d tip(0.0, model.bodies[2].length, 0.0);
  Trajectory out;
  out.t.push_back(0.0);
  out.a.push_back(point_position(data, 2, tip));
  out.q.push_back(state.q);
  for (int k = 1; k <= samples; ++k) {
    for (int s = 0; s < steps_per_sample; ++s) {
      three_body_loads(state.time + dt, loads);
      advance(model, data, base, settings, state, dt, loads, state);
    }
    out.t.push_back(state.time);
    out.a.push_back(point_position(data, 2, tip));
    out.q.push_back(state.q);
  }
  return out;
}

}  // namespace flapsim::mbd::test
