#include "pipeline/io/fsi_vtk.hpp"

#include "mbd/chain_kinematics.hpp"

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

void add_step_values(PolyDataMesh& mesh, const StepValues& v) {
  mesh.field_data.add_number("step", static_cast<double>(v.step));
  mesh.field_data.add_number("t_over_T", v.t_over_T);
  mesh.field_data.add_number("lift_N", v.lift);
  mesh.field_data.add_number("CL", v.cl);
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
  Eigen::VectorXd gamma(static_cast<Eigen::Index>(rows + le_rings) * ns);
  for (int r = 0; r < rows; ++r)
    for (int j = 0; j < ns; ++j) {
      const int a = r * n1 + j;
      mesh.polygons.push_back({a, a + 1, a + n1 + 1, a + n1});
      gamma(r * ns + j) = d.wake_gamma[static_cast<std::size_t>(r) * ns + j];
    }
  for (int r = 0; r < le_rings; ++r)
    for (int j = 0; j < ns; ++j) {
      const int a = static_cast<int>(nodes) + r * n1 + j;
      mesh.polygons.push_back({a, a + 1, a + n1 + 1, a + n1});
      gamma((rows + r) * ns + j) = r < le.rows ? le.gamma[static_cast<std::size_t>(r) * ns + j] : le.accepted(j);
    }
  mesh.cell_data.add_scalar("circulation_m2_s", gamma);
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

}  // namespace flapsim::io
