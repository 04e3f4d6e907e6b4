#include "pipeline/io/fsi_vtk.hpp"

#include "mbd/chain_kinematics.hpp"

#include <stdexcept>
#include <string>

namespace flapsim::io {

PolyDataMesh wing_surface_mesh(const uvlm::VortexLatticeModel& m,
                                       const uvlm::VortexLatticeData& d, double time) {
  PolyDataMesh mesh;
  mesh.time = time;
  mesh.points = d.nodes;
  const int nc = m.chordwise, ns = m.spanwise, np = m.panels();
  mesh.polygons.reserve(static_cast<std::size_t>(np));
  Eigen::VectorXd gamma(np), pressure(np);
  Eigen::Matrix3Xd force(3, np);
  for (int j = 0; j < ns; ++j)
    for (int i = 0; i < nc; ++i) {
      const int k = m.panel(i, j);
      // Counter-clockwise seen from the panel normal n = span × (chord toward the trailing edge).
      mesh.polygons.push_back({m.node(i, j), m.node(i, j + 1), m.node(i + 1, j + 1), m.node(i + 1, j)});
      gamma(static_cast<Eigen::Index>(mesh.polygons.size() - 1)) = d.gamma(k);
      pressure(static_cast<Eigen::Index>(mesh.polygons.size() - 1)) = d.loads.pressure_jump(k);
      force.col(static_cast<Eigen::Index>(mesh.polygons.size() - 1)) = d.loads.force.col(k);
    }
  mesh.cell_data.add_scalar("pressure_jump_Pa", pressure);
  mesh.cell_data.add_scalar("circulation_m2_s", gamma);
  mesh.cell_data.add_vector("force_N", force);
  mesh.point_data.add_vector("velocity_m_s", d.node_velocities);
  return mesh;
}

PolyDataMesh wing_surface_mesh(const uvlm::VortexLatticeModel& m, const Eigen::Matrix3Xd& nodes,
                               const Eigen::Matrix3Xd& node_velocities, double time) {
  PolyDataMesh mesh;
  mesh.time = time;
  mesh.points = nodes;
  const int nc = m.chordwise, ns = m.spanwise, np = m.panels();
  for (int j = 0; j < ns; ++j)
    for (int i = 0; i < nc; ++i)
      mesh.polygons.push_back({m.node(i, j), m.node(i, j + 1), m.node(i + 1, j + 1), m.node(i + 1, j)});
  mesh.cell_data.add_scalar("pressure_jump_Pa", Eigen::VectorXd::Zero(np));
  mesh.cell_data.add_scalar("circulation_m2_s", Eigen::VectorXd::Zero(np));
  mesh.cell_data.add_vector("force_N", Eigen::Matrix3Xd::Zero(3, np));
  mesh.point_data.add_vector("velocity_m_s", node_velocities);
  return mesh;
}

void add_wing_reference_fields(PolyDataMesh& wing, double q_ref, const Eigen::Matrix3Xd& rigid_nodes) {
  if (!(q_ref > 0.0)) throw std::invalid_argument("add_wing_reference_fields: q_ref must be > 0");
  if (rigid_nodes.cols() != wing.points.cols())
    throw std::invalid_argument("add_wing_reference_fields: " + std::to_string(rigid_nodes.cols()) +
                                " rigid nodes for " + std::to_string(wing.points.cols()) + " points");
  const ScalarField* pressure = nullptr;
  for (const ScalarField& f : wing.cell_data.scalars)
    if (f.name == "pressure_jump_Pa") pressure = &f;
  if (!pressure) throw std::invalid_argument("add_wing_reference_fields: the mesh has no pressure_jump_Pa");
  Eigen::VectorXd cp = pressure->values / q_ref;
  wing.cell_data.add_scalar("Cp", std::move(cp));
  wing.point_data.add_vector("displacement_m", wing.points - rigid_nodes);
}

void add_step_values(PolyDataMesh& mesh, const StepValues& v) {
  mesh.field_data.add_number("step", static_cast<double>(v.step));
  mesh.field_data.add_number("t_over_T", v.t_over_T);
  mesh.field_data.add_number("lift_N", v.lift);
  mesh.field_data.add_number("CL", v.cl);
  mesh.field_data.add_number("drag_N", v.drag);
  mesh.field_data.add_number("CD", v.cd);
  mesh.field_data.add_number("power_W", v.power);
  mesh.field_data.add_number("drive_power_W", v.drive_power);
}

PolyDataMesh wake_mesh(const uvlm::VortexLatticeModel& m, const uvlm::VortexLatticeData& d,
                               double time) {
  PolyDataMesh mesh;
  mesh.time = time;
  const int ns = m.spanwise, rows = d.wake_rows;
  const int n1 = ns + 1;
  const std::size_t nodes = rows > 0 ? static_cast<std::size_t>(rows + 1) * n1 : 0;
  // The leading-edge sheet (leading_edge = "shed"): its node rows 0 … rows (the last the
  // release row) and the first bound vortex's row, rings 0 … rows (the last: the
  // leading-edge ring), after the trailing-edge wake; cell field leading_edge_sheet = 1.
  const uvlm::LeadingEdgeSheet& le = d.le_sheet;
  const int le_rings = le.active() && (le.rows > 0 || le.accepted.cwiseAbs().maxCoeff() > 0.0) ? le.rows + 1 : 0;
  const std::size_t le_nodes = le_rings > 0 ? static_cast<std::size_t>(le_rings + 1) * n1 : 0;
  mesh.points.resize(3, static_cast<Eigen::Index>(nodes + le_nodes));
  for (std::size_t k = 0; k < nodes; ++k)
    mesh.points.col(static_cast<Eigen::Index>(k)) = d.wake_nodes.position(k);
  for (std::size_t k = 0; k + n1 < le_nodes; ++k)
    mesh.points.col(static_cast<Eigen::Index>(nodes + k)) = le.nodes.position(k);
  for (int j = 0; le_nodes > 0 && j < n1; ++j)
    mesh.points.col(static_cast<Eigen::Index>(nodes + le_nodes - n1 + j)) = d.ring_nodes.col(m.node(0, j));
  // Age of each node row [s]: the trailing-edge wake's rows 0 … rows, then the sheet's rows
  // 0 … le.rows and the leading edge's own row (age 0).
  const int te_node_rows = nodes > 0 ? rows + 1 : 0, le_node_rows = le_rings > 0 ? le_rings + 1 : 0;
  std::vector<double> row_age(static_cast<std::size_t>(te_node_rows + le_node_rows), 0.0);
  for (int r = 0; r < te_node_rows; ++r) row_age[static_cast<std::size_t>(r)] = d.wake_row_age[static_cast<std::size_t>(r)];
  for (int r = 0; r + 1 < le_node_rows; ++r)
    row_age[static_cast<std::size_t>(te_node_rows + r)] = le.row_age[static_cast<std::size_t>(r)];
  Eigen::VectorXd point_age(mesh.points.cols());
  for (Eigen::Index k = 0; k < point_age.size(); ++k) point_age(k) = row_age[static_cast<std::size_t>(k / n1)];
  Eigen::VectorXd gamma(static_cast<Eigen::Index>(rows + le_rings) * ns), age(gamma.size());
  for (int r = 0; r < rows; ++r)
    for (int j = 0; j < ns; ++j) {
      const int a = r * n1 + j;
      mesh.polygons.push_back({a, a + 1, a + n1 + 1, a + n1});
      gamma(r * ns + j) = d.wake_gamma[static_cast<std::size_t>(r) * ns + j];
      age(r * ns + j) = 0.5 * (row_age[static_cast<std::size_t>(r)] + row_age[static_cast<std::size_t>(r + 1)]);
    }
  for (int r = 0; r < le_rings; ++r)
    for (int j = 0; j < ns; ++j) {
      const int a = static_cast<int>(nodes) + r * n1 + j;
      mesh.polygons.push_back({a, a + 1, a + n1 + 1, a + n1});
      gamma((rows + r) * ns + j) = r < le.rows ? le.gamma[static_cast<std::size_t>(r) * ns + j] : le.accepted(j);
      const std::size_t row = static_cast<std::size_t>(te_node_rows + r);
      age((rows + r) * ns + j) = 0.5 * (row_age[row] + row_age[row + 1]);
    }
  mesh.cell_data.add_scalar("circulation_m2_s", gamma);
  mesh.cell_data.add_scalar("age_s", age);
  mesh.point_data.add_scalar("age_s", point_age);
  if (le.active()) {
    Eigen::VectorXd sheet = Eigen::VectorXd::Zero(gamma.size());
    sheet.tail(static_cast<Eigen::Index>(le_rings) * ns).setOnes();
    mesh.cell_data.add_scalar("leading_edge_sheet", sheet);
  }
  return mesh;
}

PolyDataMesh chain_mesh(const mbd::ChainModel& chain, const mbd::ChainData& data,
                                double time) {
  PolyDataMesh mesh;
  mesh.time = time;
  const int nb = chain.num_bodies();
  mesh.points.resize(3, 3 * nb);
  Eigen::VectorXd body_index(2 * nb);
  for (int k = 0; k < nb; ++k) {
    const mbd::BodyKinematics& b = data.bodies[static_cast<std::size_t>(k)];
    mesh.points.col(3 * k) = b.origin;
    mesh.points.col(3 * k + 1) = mbd::point_position(data, k, chain.bodies[static_cast<std::size_t>(k)].outboard_joint);
    mesh.points.col(3 * k + 2) = b.com;
    mesh.lines.push_back({3 * k, 3 * k + 1});
    body_index(k) = k + 1;
  }
  // Centre-of-mass markers as degenerate polygons would confuse readers; use short lines
  // from the joint line to the centre of mass instead.
  for (int k = 0; k < nb; ++k) {
    mesh.lines.push_back({3 * k, 3 * k + 2});
    body_index(nb + k) = k + 1;
  }
  mesh.cell_data.add_scalar("body", body_index);
  return mesh;
}

void add_joint_fields(PolyDataMesh& mesh, const mbd::ChainModel& chain, const mbd::ChainData& data,
                      const Eigen::VectorXd& q) {
  const int nb = chain.num_bodies(), n = chain.num_dofs();
  if (q.size() != 0 && q.size() != n)
    throw std::invalid_argument("add_joint_fields: " + std::to_string(q.size()) + " joint angles for " +
                                std::to_string(n) + " degrees of freedom");
  Eigen::VectorXd moment = Eigen::VectorXd::Zero(n);
  if (q.size() == n && n > 0) moment = data.stiffness * (q - data.rest);
  Eigen::VectorXd bend = Eigen::VectorXd::Zero(2 * nb), twist = bend, bend_moment = bend, twist_moment = bend;
  for (int k = 0; k < nb; ++k) {
    const int dof = chain.dof_of_body(k);
    if (dof < 0 || q.size() == 0) continue;
    for (int cell : {k, nb + k}) {  // the body's joint line and its centre-of-mass line
      bend(cell) = q(dof);
      twist(cell) = q(dof + 1);
      bend_moment(cell) = moment(dof);
      twist_moment(cell) = moment(dof + 1);
    }
  }
  mesh.cell_data.add_scalar("bend_rad", bend);
  mesh.cell_data.add_scalar("twist_rad", twist);
  mesh.cell_data.add_scalar("bend_moment_Nm", bend_moment);
  mesh.cell_data.add_scalar("twist_moment_Nm", twist_moment);
}

}  // namespace flapsim::io
