#pragma once
/// \file fsi_vtk.hpp
/// \brief ParaView pictures of a coupled run, one file per written step: the deformed
/// wing surface (quads; cell data pressure jump, circulation, force; point data
/// velocity), the wake sheet (quads; cell data circulation) and the bar chain (one line
/// per body from its inboard to its outboard joint; cell data body index). Plain
/// PolyDataMesh, written by write_vtp.

#include "mbd/chain_data.hpp"
#include "mbd/chain_model.hpp"
#include "pipeline/io/vtk_writers.hpp"
#include "uvlm/vortex_lattice.hpp"

namespace flapsim::io {

/// \brief The lattice surface of the last solve as quads (normals along the panel normals).
PolyDataMesh wing_surface_mesh(const uvlm::VortexLatticeModel& model,
                                       const uvlm::VortexLatticeData& data, double time);

/// \brief The lattice surface at \p nodes before its first solve (the t = 0 frame):
/// the same fields as wing_surface_mesh, zero pressure jump, circulation and force.
PolyDataMesh wing_surface_mesh(const uvlm::VortexLatticeModel& model, const Eigen::Matrix3Xd& nodes,
                               const Eigen::Matrix3Xd& node_velocities, double time);

/// The values of one written step, stored as field data on each of its files so that
/// ParaView shows and plots them in step with the animation.
struct StepValues {
  long step = 0;           ///< 0 for the initial frame
  double t_over_T = 0.0;   ///< t f: time in wingbeat periods from the start of the run [-]
  double lift = 0.0;       ///< [N] (0 at t = 0: no loads before the first solve)
  double cl = 0.0;         ///< lift coefficient [-]
};

/// \brief Adds field data "step", "t_over_T", "lift_N" and "CL" to \p mesh.
void add_step_values(PolyDataMesh& mesh, const StepValues& values);

/// \brief The wake sheet (rings between shed rows, the newest row at the trailing edge);
/// with leading_edge = "shed" the leading-edge sheet after it (cell field leading_edge_sheet = 1).
PolyDataMesh wake_mesh(const uvlm::VortexLatticeModel& model,
                               const uvlm::VortexLatticeData& data, double time);

/// \brief The chain as lines, plus each body's centre of mass as a point cell.
PolyDataMesh chain_mesh(const mbd::ChainModel& chain, const mbd::ChainData& data,
                                double time);

}  // namespace flapsim::io
