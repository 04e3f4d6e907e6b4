#include "mbd/chain_kinematics.hpp"

#include <cmath>

namespace flapsim::mbd {

Eigen::Matrix3d joint_rotation(double bend, double twist) {
  const double cb = std::cos(bend), sb = std::sin(bend);
  const double ct = std::cos(twist), st = std::sin(twist);
  Eigen::Matrix3d rx, ry;
  rx << 1, 0, 0, 0, cb, -sb, 0, sb, cb;
  ry << ct, 0, st, 0, 1, 0, -st, 0, ct;
  return rx * ry;
}

void forward_kinematics(const ChainModel& model, ChainData& data, const BasePose& base,
                        const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  const int nb = model.num_bodies();
  const Eigen::Matrix3d root_rot = base.rotation * model.root_rotation;
  const Eigen::Vector3d& wb = base.angular_velocity;
  const Eigen::Vector3d& dwb = base.angular_acceleration;

  // The root frame: rotates with the base about the pivot, which translates with the base.
  Eigen::Matrix3d parent_rot = root_rot;
  Eigen::Vector3d parent_origin = base.position;
  Eigen::Vector3d parent_w = wb, parent_dw = dwb;
  Eigen::Vector3d parent_vel = base.velocity, parent_acc = base.acceleration;
  Eigen::Vector3d joint_in_parent = model.root_offset;  // in W; root_rot maps R coords, so use base

  for (int i = 0; i < nb; ++i) {
    BodyKinematics& b = data.bodies[i];
    const ChainBody& body = model.bodies[i];
    // Joint point: for body 0 the root offset is in W coordinates; otherwise the
    // parent's outboard joint in the parent's frame.
    const Eigen::Vector3d d = (i == 0 ? base.rotation : parent_rot) * joint_in_parent;
    b.origin = parent_origin + d;
    b.origin_velocity = parent_vel + parent_w.cross(d);
    b.origin_acceleration = parent_acc + parent_dw.cross(d) + parent_w.cross(parent_w.cross(d));

    const int k = model.dof_of_body(i);
    if (k < 0) {  // welded to the root frame
      b.rotation = parent_rot;
      b.angular_velocity = parent_w;
      b.angular_acceleration = parent_dw;
      b.bend_axis.setZero();
      b.twist_axis.setZero();
    } else {
      const double th = q(k), al = q(k + 1), dth = v(k), dal = v(k + 1);
      b.rotation = parent_rot * joint_rotation(th, al);
      b.bend_axis = parent_rot.col(0);   // parent's x
      b.twist_axis = b.rotation.col(1);  // child's y (unchanged by Ry)
      const Eigen::Vector3d w_mid = parent_w + b.bend_axis * dth;  // after the bend rotation
      b.angular_velocity = w_mid + b.twist_axis * dal;
      // d/dt(e1 θ̇) = ω_p × e1 θ̇ ; d/dt(e2 α̇) = ω_mid × e2 α̇ (at Φ̈ = 0)
      b.angular_acceleration = parent_dw + parent_w.cross(b.bend_axis * dth) +
                               w_mid.cross(b.twist_axis * dal);
    }
    const Eigen::Vector3d r = b.rotation * body.center_of_mass;
    b.com = b.origin + r;
    b.com_velocity = b.origin_velocity + b.angular_velocity.cross(r);
    b.com_acceleration = b.origin_acceleration + b.angular_acceleration.cross(r) +
                         b.angular_velocity.cross(b.angular_velocity.cross(r));
    b.inertia_ground.noalias() = b.rotation * body.inertia * b.rotation.transpose();

    // Jacobian columns of every joint at or inboard of this body.
    for (int j = model.first_jointed_body(); j <= i; ++j) {
      const BodyKinematics& bj = data.bodies[j];
      const int kj = model.dof_of_body(j);
      const Eigen::Vector3d arm = b.com - bj.origin;
      b.angular_jacobian.col(kj) = bj.bend_axis;
      b.angular_jacobian.col(kj + 1) = bj.twist_axis;
      b.com_jacobian.col(kj) = bj.bend_axis.cross(arm);
      b.com_jacobian.col(kj + 1) = bj.twist_axis.cross(arm);
    }

    parent_rot = b.rotation;
    parent_origin = b.origin;
    parent_w = b.angular_velocity;
    parent_dw = b.angular_acceleration;
    parent_vel = b.origin_velocity;
    parent_acc = b.origin_acceleration;
    joint_in_parent = body.outboard_joint;
  }
}

void update_accelerations(const ChainModel& model, ChainData& data, const Eigen::VectorXd& qdd) {
  for (int i = 0; i < model.num_bodies(); ++i) {
    BodyKinematics& b = data.bodies[i];
    b.angular_acceleration.noalias() += b.angular_jacobian * qdd;
    b.com_acceleration.noalias() += b.com_jacobian * qdd;
    // origin: a_o = a_c − ω̇ × r − ω × (ω × r)
    const Eigen::Vector3d r = b.com - b.origin;
    b.origin_acceleration = b.com_acceleration - b.angular_acceleration.cross(r) -
                            b.angular_velocity.cross(b.angular_velocity.cross(r));
  }
}

Eigen::Vector3d point_position(const ChainData& data, int body, const Eigen::Vector3d& point_body) {
  const BodyKinematics& b = data.bodies[body];
  return b.origin + b.rotation * point_body;
}

Eigen::Vector3d point_velocity(const ChainData& data, int body, const Eigen::Vector3d& point_body) {
  const BodyKinematics& b = data.bodies[body];
  return b.origin_velocity + b.angular_velocity.cross(b.rotation * point_body);
}

Eigen::Vector3d point_acceleration(const ChainData& data, int body,
                                   const Eigen::Vector3d& point_body) {
  const BodyKinematics& b = data.bodies[body];
  const Eigen::Vector3d r = b.rotation * point_body;
  return b.origin_acceleration + b.angular_acceleration.cross(r) +
         b.angular_velocity.cross(b.angular_velocity.cross(r));
}

}  // namespace flapsim::mbd
