#include "pipeline/fsi/wing_attachment.hpp"

#include <stdexcept>
#include <string>

#include "mbd/chain_kinematics.hpp"

namespace flapsim::fsi {

namespace {

// The chain in its reference configuration: base frame W = ground, rest angles, at rest.
mbd::ChainData reference_kinematics(const mbd::ChainModel& chain) {
  mbd::ChainData data(chain);
  const Eigen::VectorXd q = chain.rest_angles();
  const Eigen::VectorXd v = Eigen::VectorXd::Zero(chain.num_dofs());
  mbd::forward_kinematics(chain, data, mbd::BasePose{}, q, v);
  return data;
}

double span_coordinate(const mbd::ChainModel& chain, const Eigen::Vector3d& p_wing) {
  return (chain.root_rotation.transpose() * (p_wing - chain.root_offset)).y();
}

}  // namespace

std::vector<double> reference_joint_span(const mbd::ChainModel& chain) {
  const mbd::ChainData data = reference_kinematics(chain);
  std::vector<double> s(chain.bodies.size());
  for (std::size_t k = 0; k < s.size(); ++k) s[k] = span_coordinate(chain, data.bodies[k].origin);
  return s;
}

int host_body(const std::vector<double>& joint_span, double s) {
  int host = 0;
  for (std::size_t k = 1; k < joint_span.size(); ++k)
    if (s >= joint_span[k]) host = static_cast<int>(k);
  return host;
}

WingAttachment attach_wing(const mbd::ChainModel& chain, const Eigen::Matrix3Xd& nodes_wing,
                           int chordwise, int spanwise) {
  const int nn = (chordwise + 1) * (spanwise + 1);
  if (chordwise < 1 || spanwise < 1 || nodes_wing.cols() != nn)
    throw std::invalid_argument("attach_wing: expected " + std::to_string(nn) +
                                " lattice nodes, got " + std::to_string(nodes_wing.cols()));
  chain.validate();
  const mbd::ChainData ref = reference_kinematics(chain);
  WingAttachment a;
  a.num_bodies = chain.num_bodies();
  a.reference_nodes = nodes_wing;
  a.joint_span.resize(chain.bodies.size());
  for (std::size_t k = 0; k < a.joint_span.size(); ++k)
    a.joint_span[k] = span_coordinate(chain, ref.bodies[k].origin);

  a.nodes.resize(static_cast<std::size_t>(nn));
  for (int n = 0; n < nn; ++n) {
    const Eigen::Vector3d p = nodes_wing.col(n);
    BodyPoint& bp = a.nodes[static_cast<std::size_t>(n)];
    bp.body = host_body(a.joint_span, span_coordinate(chain, p));
    const mbd::BodyKinematics& b = ref.bodies[static_cast<std::size_t>(bp.body)];
    bp.local = b.rotation.transpose() * (p - b.origin);
  }

  // A panel's load goes to the body holding the panel's reference centre (the centre,
  // not the quarter-chord point, so a panel whose nodes share one host keeps that host).
  a.panel_body.resize(static_cast<std::size_t>(chordwise * spanwise));
  const auto node = [&](int i, int j) { return nodes_wing.col(i + (chordwise + 1) * j); };
  for (int j = 0; j < spanwise; ++j)
    for (int i = 0; i < chordwise; ++i) {
      const Eigen::Vector3d c =
          0.25 * (node(i, j) + node(i + 1, j) + node(i, j + 1) + node(i + 1, j + 1));
      a.panel_body[static_cast<std::size_t>(i + chordwise * j)] =
          host_body(a.joint_span, span_coordinate(chain, c));
    }
  return a;
}

void deformed_nodes(const WingAttachment& attachment, const mbd::ChainData& data,
                    Eigen::Matrix3Xd& positions, Eigen::Matrix3Xd& velocities) {
  const Eigen::Index nn = static_cast<Eigen::Index>(attachment.nodes.size());
  if (positions.cols() != nn) positions.resize(3, nn);
  if (velocities.cols() != nn) velocities.resize(3, nn);
  for (Eigen::Index n = 0; n < nn; ++n) {
    const BodyPoint& bp = attachment.nodes[static_cast<std::size_t>(n)];
    positions.col(n) = mbd::point_position(data, bp.body, bp.local);
    velocities.col(n) = mbd::point_velocity(data, bp.body, bp.local);
  }
}

}  // namespace flapsim::fsi
