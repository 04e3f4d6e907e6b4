#pragma once
/// \file chain_loads.hpp
/// \brief External point forces and moments on the bodies, filled by the caller
/// each step (the air, a case file's point loads), and their generalized forces.
///
/// A force is applied at a point fixed in a body (body coordinates); its components
/// are either fixed in the ground frame (e.g. the aerodynamic force of the current
/// step) or fixed in the body frame (a follower load). Loads are stored as a few
/// per-body sums whose resultant is exact for any body pose, so the implicit
/// integrator can re-evaluate them while it iterates on the end-of-step pose and any
/// number of point loads costs O(bodies) storage. No allocation after construction.

#include "mbd/chain_data.hpp"
#include "mbd/chain_model.hpp"

#include <Eigen/Core>

#include <vector>

namespace flapsim::mbd {

enum class LoadFrame {
  ground,  ///< components in the ground frame G
  body,    ///< components in the loaded body's frame (follows the body)
};

class Loads {
 public:
  /// \param num_bodies  number of bodies of the chain
  explicit Loads(int num_bodies = 0);

  /// Removes every load (keeps the storage).
  void clear();

  /// Adds a force.
  /// \param body        0-based body index
  /// \param point_body  point of application in body coordinates [m]
  /// \param force       [N], components in `frame`
  void add_force(int body, const Eigen::Vector3d& point_body, const Eigen::Vector3d& force,
                 LoadFrame frame);

  /// Adds a pure moment [N m], components in `frame`.
  void add_moment(int body, const Eigen::Vector3d& moment, LoadFrame frame);

  /// Resultant on a body for a given pose: force [N] and moment about the body origin
  /// [N m], both in ground components.
  /// \param rotation  R_GB of that body
  void resultant(int body, const Eigen::Matrix3d& rotation, Eigen::Vector3d& force,
                 Eigen::Vector3d& moment_about_origin) const;

  int num_bodies() const { return static_cast<int>(per_body_.size()); }

 private:
  struct BodySums {
    Eigen::Vector3d force_ground = Eigen::Vector3d::Zero();    // Σ F (ground components)
    Eigen::Matrix3d arm_force_ground = Eigen::Matrix3d::Zero();  // Σ p F^T (p body, F ground)
    Eigen::Vector3d moment_ground = Eigen::Vector3d::Zero();   // Σ pure moments (ground)
    Eigen::Vector3d force_body = Eigen::Vector3d::Zero();      // Σ F (body components)
    Eigen::Vector3d moment_body = Eigen::Vector3d::Zero();     // Σ (p × F + M), body components
  };
  std::vector<BodySums> per_body_;
};

/// Generalized forces Q = Σ J_vᵀ F + J_ωᵀ N of the loads and of gravity at the pose of
/// the last forward_kinematics, into data.generalized_load [N m].
void compute_generalized_loads(const ChainModel& model, ChainData& data, const Loads& loads);

/// Power of the loads [W] at the state of the last forward_kinematics.
double load_power(const ChainModel& model, const ChainData& data, const Loads& loads);

}  // namespace flapsim::mbd
