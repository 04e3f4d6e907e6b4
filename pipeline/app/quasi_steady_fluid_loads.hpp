#pragma once
/// \file quasi_steady_fluid_loads.hpp
/// \brief A cheap estimate, made before a run, of the fluid's loads on a wing that follows
/// its base motion rigidly: on each lattice panel the normal force of a wing translating
/// through the fluid at the panel's speed and angle of attack, with the translational force
/// coefficients measured on a revolving wing ([Dickinson et al. 1999], their fit
/// CL = 0.225 + 1.58 sin(2.13α − 7.20°), CD = 1.92 − 1.55 cos(2.04α − 9.82°); the normal
/// coefficient C_N = CL cos α + CD sin α, 3.46 at 90°, 2.48 at 45°). No wake, no added
/// mass, no rotational lift: an order of magnitude for the chain's quasi-static deflection
/// (flexibility_warnings.hpp), not a load of the run.

#include <Eigen/Core>

#include "mbd/chain_data.hpp"
#include "mbd/chain_loads.hpp"
#include "pipeline/fsi/wing_attachment.hpp"

namespace flapsim::app {

/// The normal-force coefficient C_N(α) = CL cos α + CD sin α of [Dickinson et al. 1999]'s fit,
/// for an angle of attack α [rad] in [0, π/2] (clamped there).
double revolving_wing_normal_coefficient(double alpha);

/// \brief Adds to \p loads, on each panel's host body at the panel's centroid, the force
/// ½ ρ |u|² C_N(α) A along the panel's normal, toward where the fluid flows relative to it
/// (u = freestream − the centroid's velocity; α the angle between u and the panel's plane).
/// \param attachment  the lattice on the chain (nodes i + (nc + 1) j, panels i + nc j)
/// \param chordwise, spanwise  nc, ns panels
/// \param data        the chain's kinematics (after forward kinematics)
/// \param density     ρ [kg/m³]
/// \param freestream  U∞ [m/s], ground frame
void add_quasi_steady_fluid_loads(const fsi::WingAttachment& attachment, int chordwise, int spanwise,
                                  const mbd::ChainData& data, double density,
                                  const Eigen::Vector3d& freestream, mbd::Loads& loads);

}  // namespace flapsim::app
