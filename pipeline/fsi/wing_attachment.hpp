#pragma once
/// \file wing_attachment.hpp
/// \brief How the aerodynamic surface rides on the bar chain: every lattice node and
/// every panel's point of action is carried by one host body, at fixed coordinates in
/// that body's frame (docs/fsi.md, "Attachment").
///
/// The host is found once, in the reference configuration (base frame W = ground, every
/// joint at its rest angles): the span coordinate of a point along the chain's axis
/// (y of the root frame R) picks the body whose joint interval [s_k, s_{k+1}) holds it;
/// points inboard of the first joint go to body 0, points beyond the last joint to the
/// last body. Each step the deformed surface is then exact rigid-body motion of those
/// points: x = o_k + R_k p, v = v_k + ω_k × R_k p (mbd point_position / point_velocity).

#include <Eigen/Core>

#include <vector>

#include "mbd/chain_data.hpp"
#include "mbd/chain_model.hpp"

namespace flapsim::fsi {

/// A point fixed in a body of the chain.
struct BodyPoint {
  int body = 0;                                     ///< 0-based host body
  Eigen::Vector3d local = Eigen::Vector3d::Zero();  ///< coordinates in the body frame [m]
};

/// Host bodies and body coordinates of the lattice nodes (and of the reference panel
/// mid-points, which decide the host body of each panel's load).
struct WingAttachment {
  std::vector<BodyPoint> nodes;  ///< one per lattice node, lattice order
  std::vector<int> panel_body;   ///< host body of each panel's load, lattice panel order
  std::vector<double> joint_span;  ///< span coordinate s_k of each body's inboard joint [m]
  int num_bodies = 0;
  /// The lattice nodes in W as attached [m]: where the chain at its rest angles, base at
  /// the identity, carries them (the undeformed wing; StructureModel::reference_surface).
  Eigen::Matrix3Xd reference_nodes;
};

/// Span coordinates [m] of the bodies' inboard joints along the root frame's y axis in
/// the reference configuration (rest angles, base = identity).
std::vector<double> reference_joint_span(const mbd::ChainModel& chain);

/// Host body of a point with span coordinate s [m] along the chain axis.
int host_body(const std::vector<double>& joint_span, double s);

/// \brief Attaches a lattice to a chain.
/// \param chain           the bar chain (root frame R placed in the wing frame W)
/// \param nodes_wing      lattice nodes in the wing frame W, (nc+1)(ns+1) columns [m]
/// \param chordwise       nc panels
/// \param spanwise        ns panels
/// \throws std::invalid_argument if the node count does not match nc, ns
WingAttachment attach_wing(const mbd::ChainModel& chain, const Eigen::Matrix3Xd& nodes_wing,
                           int chordwise, int spanwise);

/// \brief Deformed lattice from the chain's current kinematics (after
/// mbd::forward_kinematics or mbd::advance).
/// \param positions   output, ground frame [m] (sized by the caller, 3 × nodes)
/// \param velocities  output, ground frame [m/s]
void deformed_nodes(const WingAttachment& attachment, const mbd::ChainData& data,
                    Eigen::Matrix3Xd& positions, Eigen::Matrix3Xd& velocities);

}  // namespace flapsim::fsi
