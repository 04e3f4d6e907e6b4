#include "pipeline/fsi/fem_attachment.hpp"

#include <limits>
#include <stdexcept>
#include <string>

namespace flapsim::fsi {

namespace {

// Barycentric weights of p projected on the plane of triangle (a, b, c).
std::array<double, 3> barycentric(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                  const Eigen::Vector3d& p) {
  const Eigen::Vector3d e1 = b - a, e2 = c - a, r = p - a;
  const double d11 = e1.dot(e1), d12 = e1.dot(e2), d22 = e2.dot(e2);
  const double r1 = r.dot(e1), r2 = r.dot(e2);
  const double det = d11 * d22 - d12 * d12;
  const double w1 = (d22 * r1 - d12 * r2) / det;
  const double w2 = (d11 * r2 - d12 * r1) / det;
  return {1.0 - w1 - w2, w1, w2};
}

Eigen::Vector3d node_of(const Eigen::Matrix3Xd& x, int n) { return x.col(n); }

}  // namespace

ShellPoint locate_on_shell(const fem::Mesh& mesh, const Eigen::Vector3d& p) {
  if (mesh.triangles.empty()) throw std::invalid_argument("attach to the FEM: the mesh has no shell triangles");
  ShellPoint best;
  double best_outside = std::numeric_limits<double>::infinity();
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3d& a = mesh.nodes[static_cast<std::size_t>(tri[0])];
    const Eigen::Vector3d& b = mesh.nodes[static_cast<std::size_t>(tri[1])];
    const Eigen::Vector3d& c = mesh.nodes[static_cast<std::size_t>(tri[2])];
    const std::array<double, 3> w = barycentric(a, b, c, p);
    // How far outside the triangle, in its own measure (0 inside), then the distance to its
    // plane: a cambered or bent mesh has several triangles that hold p in their plane.
    const double outside = std::max({0.0, -w[0], -w[1], -w[2]});
    const Eigen::Vector3d foot = w[0] * a + w[1] * b + w[2] * c;
    const double distance = (p - foot).norm();
    if (outside < best_outside || (outside == best_outside && distance < best_distance)) {
      best_outside = outside;
      best_distance = distance;
      best.triangle = static_cast<int>(t);
      best.weights = w;
    }
  }
  return best;
}

FemAttachment attach_wing_to_fem(const fem::Mesh& mesh, const Eigen::Matrix3Xd& nodes_wing, int chordwise,
                                 int spanwise) {
  const int nn = (chordwise + 1) * (spanwise + 1);
  if (chordwise < 1 || spanwise < 1 || nodes_wing.cols() != nn)
    throw std::invalid_argument("attach_wing_to_fem: expected " + std::to_string(nn) + " lattice nodes, got " +
                                std::to_string(nodes_wing.cols()));
  FemAttachment a;
  a.num_fem_nodes = mesh.num_nodes();
  a.nodes.reserve(static_cast<std::size_t>(nn));
  for (int n = 0; n < nn; ++n) a.nodes.push_back(locate_on_shell(mesh, nodes_wing.col(n)));
  a.reference_nodes.setZero(3, nn);
  for (int n = 0; n < nn; ++n) {
    const ShellPoint& sp = a.nodes[static_cast<std::size_t>(n)];
    const auto& tri = mesh.triangles[static_cast<std::size_t>(sp.triangle)];
    for (int i = 0; i < 3; ++i)
      a.reference_nodes.col(n) += sp.weights[static_cast<std::size_t>(i)] * mesh.nodes[static_cast<std::size_t>(tri[static_cast<std::size_t>(i)])];
  }
  // A panel's point of action: quarter chord, mid-span (uvlm::PanelLoads::point).
  const auto node = [&](int i, int j) -> Eigen::Vector3d { return nodes_wing.col(i + (chordwise + 1) * j); };
  a.panels.reserve(static_cast<std::size_t>(chordwise * spanwise));
  for (int j = 0; j < spanwise; ++j)
    for (int i = 0; i < chordwise; ++i) {
      const Eigen::Vector3d p = 0.5 * (node(i, j) + 0.25 * (node(i + 1, j) - node(i, j)) + node(i, j + 1) +
                                       0.25 * (node(i + 1, j + 1) - node(i, j + 1)));
      a.panels.push_back(locate_on_shell(mesh, p));
    }
  return a;
}

void fem_surface_nodes(const FemAttachment& attachment, const fem::Mesh& mesh,
                       const Eigen::Matrix3Xd& fem_positions, const Eigen::Matrix3Xd& fem_velocities,
                       Eigen::Matrix3Xd& positions, Eigen::Matrix3Xd& velocities) {
  const Eigen::Index nn = static_cast<Eigen::Index>(attachment.nodes.size());
  if (positions.cols() != nn) positions.resize(3, nn);
  if (velocities.cols() != nn) velocities.resize(3, nn);
  for (Eigen::Index n = 0; n < nn; ++n) {
    const ShellPoint& s = attachment.nodes[static_cast<std::size_t>(n)];
    const auto& tri = mesh.triangles[static_cast<std::size_t>(s.triangle)];
    positions.col(n) = s.weights[0] * node_of(fem_positions, tri[0]) + s.weights[1] * node_of(fem_positions, tri[1]) +
                       s.weights[2] * node_of(fem_positions, tri[2]);
    velocities.col(n) = s.weights[0] * node_of(fem_velocities, tri[0]) +
                        s.weights[1] * node_of(fem_velocities, tri[1]) + s.weights[2] * node_of(fem_velocities, tri[2]);
  }
}

void add_panel_loads_to_fem(const FemAttachment& attachment, const fem::Mesh& mesh,
                            const Eigen::Matrix3Xd& fem_positions, const uvlm::PanelLoads& panels,
                            Eigen::VectorXd& nodal_loads) {
  add_panel_forces_to_fem(attachment, mesh, fem_positions, panels.force, panels.point, nodal_loads);
}

void add_panel_forces_to_fem(const FemAttachment& attachment, const fem::Mesh& mesh,
                             const Eigen::Matrix3Xd& fem_positions, const Eigen::Matrix3Xd& forces,
                             const Eigen::Matrix3Xd& points, Eigen::VectorXd& nodal_loads) {
  const Eigen::Index np = forces.cols();
  if (static_cast<std::size_t>(np) != attachment.panels.size() || points.cols() != np ||
      nodal_loads.size() != fem::kDofsPerNode * attachment.num_fem_nodes)
    throw std::invalid_argument("add_panel_loads_to_fem: panel or node count does not match the attachment");
  for (Eigen::Index p = 0; p < np; ++p) {
    const ShellPoint& s = attachment.panels[static_cast<std::size_t>(p)];
    const auto& tri = mesh.triangles[static_cast<std::size_t>(s.triangle)];
    const Eigen::Vector3d f = forces.col(p);
    Eigen::Vector3d foot = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) foot += s.weights[static_cast<std::size_t>(k)] * node_of(fem_positions, tri[k]);
    const Eigen::Vector3d offset_moment = (points.col(p) - foot).cross(f) / 3.0;
    for (int k = 0; k < 3; ++k) {
      const int base = fem::dof_index(tri[k], fem::UX);
      nodal_loads.segment<3>(base) += s.weights[static_cast<std::size_t>(k)] * f;
      nodal_loads.segment<3>(base + 3) += offset_moment;
    }
  }
}

}  // namespace flapsim::fsi
