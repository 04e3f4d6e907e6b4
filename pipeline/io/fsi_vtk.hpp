#pragma once
/// \file fsi_vtk.hpp
/// \brief ParaView pictures of a coupled run, one file per written step: the deformed
/// wing surface (quads; cell data pressure jump, its coefficient, circulation, force; point
/// data velocity and displacement from the rigid wing), the wake sheet (quads; cell data
/// circulation; cell and point data age) and the bar chain (one line per body from its
/// inboard to its outboard joint; cell data body index, joint angles and spring moments).
/// Plain PolyDataMesh, written by write_vtp. docs/output_files.md lists the fields.

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

/// \brief Adds the wing's fields of the run's references to a mesh of wing_surface_mesh:
/// cell data "Cp" = Δp / q_ref (the pressure-jump coefficient, from its "pressure_jump_Pa")
/// and point data "displacement_m" = point − \p rigid_nodes (the deformation: from the
/// undeformed wing moved with the base, fsi::StructureModel::rigid_surface).
/// \param dynamic_pressure  q_ref = ½ ρ U_ref² of the run's CL [Pa] (> 0)
/// \param rigid_nodes       the lattice nodes on the rigid wing at the frame's time [m]
/// \throws std::invalid_argument without a pressure field, for q_ref <= 0 or a wrong size
void add_wing_reference_fields(PolyDataMesh& wing, double dynamic_pressure, const Eigen::Matrix3Xd& rigid_nodes);

/// The values of one written step, stored as field data on each of its files so that
/// ParaView shows and plots them in step with the animation. The loads are 0 at t = 0 (no
/// loads before the first solve) and in vacuum.
struct StepValues {
  long step = 0;           ///< 0 for the initial frame
  double t_over_T = 0.0;   ///< t f: time in wingbeat periods from the start of the run [-]
  double lift = 0.0;       ///< [N]
  double cl = 0.0;         ///< lift coefficient [-]
  double drag = 0.0;       ///< [N] (history.csv drag_N)
  double cd = 0.0;         ///< drag coefficient [-]
  double power = 0.0;      ///< aerodynamic power [W] (history.csv power_W)
  double drive_power = 0.0;  ///< power the base supplies [W] (history.csv drive_power_W)
};

/// \brief Adds field data "step", "t_over_T", "lift_N", "CL", "drag_N", "CD", "power_W"
/// and "drive_power_W" to \p mesh.
void add_step_values(PolyDataMesh& mesh, const StepValues& values);

/// \brief The wake sheet (rings between shed rows, the newest row at the trailing edge);
/// with leading_edge = "shed" the leading-edge sheet after it (cell field leading_edge_sheet = 1).
/// "age_s": point data, the time since the node's row left the trailing (leading) edge
/// (0 for the row on the edge); cell data, the mean of its two rows' ages (the ring's
/// vorticity left the edge over that interval; the newest ring dt/2 after a step) [s].
PolyDataMesh wake_mesh(const uvlm::VortexLatticeModel& model,
                               const uvlm::VortexLatticeData& data, double time);

/// \brief The chain as lines, plus each body's centre of mass as a point cell.
PolyDataMesh chain_mesh(const mbd::ChainModel& chain, const mbd::ChainData& data,
                                double time);

/// \brief Adds the joints of a chain_mesh: cell data "bend_rad", "twist_rad" (Φ of the
/// joint inboard of the cell's body, the values of history.csv's bend_<k>_rad,
/// twist_<k>_rad) and "bend_moment_Nm", "twist_moment_Nm" (the joint springs' elastic
/// moment K (Φ − Φ_rest), the full stiffness's coupling included; it acts on the outboard
/// body as −K (Φ − Φ_rest)); 0 on the bodies without a joint (welded to the root).
/// \param q  the chain's Φ [rad] (num_dofs(); empty for a rigid wing)
/// \throws std::invalid_argument if q has neither 0 nor num_dofs() entries
void add_joint_fields(PolyDataMesh& mesh, const mbd::ChainModel& chain, const mbd::ChainData& data,
                      const Eigen::VectorXd& q);

}  // namespace flapsim::io
