// The flexible coupling against an independent answer: a soft chain carrying the flat
// plate in a steady free stream comes to rest where its springs balance the air,
// K (Φ − Φ_rest) = Q, with Q computed here straight from the lattice's panel forces and
// points, Q_j = Σ_p ((P_p − o_j) × F_p) · e_j over the panels outboard of joint j
// (virtual work of the panel forces for a rotation about the joint's axis e_j, through its
// point o_j: docs/multibody.md, "Generalized forces"). A load transfer that moved a
// force to another body or lost its moment arm misses this balance by the moment it
// moved; the chain's own equations are not used for Q.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "fsi/plate_wing_fixtures.hpp"
#include "mbd/angle_units.hpp"
#include "mbd/chain_model.hpp"
#include "pipeline/fsi/chain_structure.hpp"
#include "pipeline/fsi/coupled_step.hpp"

namespace {

using namespace flapsim;

TEST(FsiStaticAeroelastic, AChainAtRestInAFreeStreamBalancesThePanelMomentsAboutItsJoints) {
  const int nc = 3, ns = 8, steps = 240;
  const double speed = 5.0, alpha = 6.0 * kDegToRad, chord = 0.010;  // [m/s], [rad], [m]
  const auto grid = test::plate_grid(nc, ns);
  auto structure = std::make_shared<fsi::ChainStructureModel>();
  // 4 bodies, EI = 2e-5 N m², GJ = 2e-6 N m² over 40 mm: bent about a degree by this air.
  structure->chain = mbd::make_uniform_cantilever_chain(0.040, 2e-5, 2e-6, 0.9e-3, 1e-9, 4);
  for (auto& j : structure->chain.joints) {  // dampers let it come to rest; they act on Φ̇ only
    j.bend_damping = 2e-5;
    j.twist_damping = 2e-6;
  }
  // The wing at incidence α: its leading edge (+x_W) turned up, the air coming from +x.
  mbd::BasePose pose;
  pose.rotation = mbd::rotation_y(-alpha);
  structure->base_motion = [pose](double) { return pose; };
  structure->attachment = fsi::attach_wing(structure->chain, grid.nodes, nc, ns);
  fsi::FsiModel m;
  m.structure = structure;
  m.frequency = speed / chord;  // rate scale of the coupling test only [1/s]
  m.free_stream = Eigen::Vector3d(-speed, 0.0, 0.0);
  m.lattice.chordwise = nc;
  m.lattice.spanwise = ns;
  m.lattice.core.radius = 0.2 * chord;
  m.lattice.wake_capacity = steps;
  m.coupling.tolerance = 1e-9;  // [rad]: 1e-6 of the deflections below
  const double dt = 0.25 * chord / speed;  // a quarter chord of wake per step: 60 chords in all
  fsi::FsiData d(m);
  fsi::initialize(m, d, 0.0);
  for (int n = 0; n < steps; ++n) {
    fsi::coupled_step(m, d, dt);
    if (n + 1 < steps) fsi::shed_wake(m, d);
  }
  const auto& s = fsi::chain_structure(*d.structure);
  const mbd::ChainModel& chain = structure->chain;
  const Eigen::VectorXd deflection = s.state.q - chain.rest_angles();
  ASSERT_GT(d.lattice->loads.total_force.z(), 0.0);  // lift: the plate is at positive incidence
  // At rest (rates below 1e-4 of the static angles per flapping-free time unit c/U).
  EXPECT_LT(s.state.v.lpNorm<Eigen::Infinity>() * chord / speed, 1e-4 * deflection.lpNorm<Eigen::Infinity>());
  EXPECT_GT(std::abs(deflection(deflection.size() - 2)), 1e-3);  // the outer joint bends > 0.06°

  // Q from the panel forces alone.
  const uvlm::PanelLoads& panels = d.lattice->loads;
  const std::vector<double> joint_span = fsi::reference_joint_span(chain);
  Eigen::VectorXd q_aero = Eigen::VectorXd::Zero(chain.num_dofs());
  for (int b = chain.first_jointed_body(); b < chain.num_bodies(); ++b) {
    const mbd::BodyKinematics& joint = s.chain.bodies[static_cast<std::size_t>(b)];
    const int i = 2 * (b - chain.first_jointed_body());
    for (Eigen::Index p = 0; p < panels.force.cols(); ++p) {
      if (structure->attachment.panel_body[static_cast<std::size_t>(p)] < b) continue;
      const Eigen::Vector3d moment = (panels.point.col(p) - joint.origin).cross(panels.force.col(p));
      q_aero(i) += moment.dot(joint.bend_axis);
      q_aero(i + 1) += moment.dot(joint.twist_axis);
    }
  }
  // The springs' moments K (Φ − Φ_rest), K the joints' diagonal springs.
  Eigen::VectorXd spring(chain.num_dofs());
  for (int b = chain.first_jointed_body(); b < chain.num_bodies(); ++b) {
    const int i = 2 * (b - chain.first_jointed_body());
    spring(i) = chain.joints[static_cast<std::size_t>(b)].bend_stiffness * deflection(i);
    spring(i + 1) = chain.joints[static_cast<std::size_t>(b)].twist_stiffness * deflection(i + 1);
  }
  const double scale = q_aero.lpNorm<Eigen::Infinity>();
  for (int i = 0; i < q_aero.size(); ++i)
    EXPECT_NEAR(spring(i), q_aero(i), 1e-4 * scale) << "generalized coordinate " << i;
}

}  // namespace
