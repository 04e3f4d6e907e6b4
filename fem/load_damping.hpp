#pragma once
/// \file load_damping.hpp
/// \brief A load that answers the nodes' translational velocities: f = −s D (v − v_ref) at
/// some nodes, D a symmetric positive semi-definite 3 × 3 block per node [N s/m]. A coupled
/// run's FEM takes the air's added mass in this form, linearised by the lattice and lumped
/// to the nodes (pipeline/fsi/fem_added_mass.hpp): at the coupling's fixed point v = v_ref,
/// the load vanishes, and the coupled answer is the one without it (docs/fsi.md, "Added
/// mass in the coupling"). In a step (nonlinear_dynamics.hpp) it adds −s D (v_{n+1} − v_ref)
/// to the residual and s (γ/(βh)) D (∂v_{n+1}/∂u = γ/(βh)) to a Newton matrix made in it.

#include <Eigen/Core>

#include <vector>

namespace flapsim::fem {

struct NodalLoadDamping {
  std::vector<int> nodes;               ///< the nodes it acts on, each once
  std::vector<Eigen::Matrix3d> blocks;  ///< D of each node, ground axes [N s/m]
  /// Velocities the load is measured from, 3 × the model's nodes [m/s] (not owned).
  const Eigen::Matrix3Xd* reference_velocity = nullptr;
  double scale = 1.0;  ///< s [-]
};

}  // namespace flapsim::fem
