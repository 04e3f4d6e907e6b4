#include "pipeline/io/fem_run_vtk.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>

namespace flapsim::io {

double triangle_membrane_strain(const Eigen::Vector3d& A, const Eigen::Vector3d& B, const Eigen::Vector3d& C,
                                const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  // Metric tensors of the two edges: G (reference) and g (current); E = ½ (G⁻¹ g − I) in the
  // reference's covariant basis, whose eigenvalues are the principal Green–Lagrange strains.
  const Eigen::Vector3d E1 = B - A, E2 = C - A, e1 = b - a, e2 = c - a;
  Eigen::Matrix2d G, g;
  G << E1.dot(E1), E1.dot(E2), E2.dot(E1), E2.dot(E2);
  g << e1.dot(e1), e1.dot(e2), e2.dot(e1), e2.dot(e2);
  if (!(std::abs(G.determinant()) > 0.0)) return 0.0;
  const Eigen::Matrix2d strain = 0.5 * (G.inverse() * g - Eigen::Matrix2d::Identity());
  const Eigen::Vector2cd ev = strain.eigenvalues();
  const double s1 = ev(0).real(), s2 = ev(1).real();
  return std::abs(s1) >= std::abs(s2) ? s1 : s2;
}

PolyDataMesh fem_frame_mesh(const fem::Mesh& mesh, const Eigen::Matrix3Xd& positions,
                            const Eigen::Matrix3d& base_rotation, const Eigen::Vector3d& base_position,
                            double time) {
  PolyDataMesh out;
  out.time = time;
  out.points = positions;
  const int nn = mesh.num_nodes();
  Eigen::Matrix3Xd displacement(3, nn);
  for (int n = 0; n < nn; ++n)
    displacement.col(n) =
        positions.col(n) - (base_position + base_rotation * mesh.nodes[static_cast<std::size_t>(n)]);
  out.point_data.add_vector("displacement_m", std::move(displacement));
  const std::size_t nl = mesh.beams.size(), np = mesh.triangles.size();
  Eigen::VectorXd strain = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(nl + np));
  Eigen::VectorXd vein = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(nl + np), -1.0);
  // Cell order of a .vtp: lines, then polygons (vtk_writers.hpp).
  for (std::size_t k = 0; k < nl; ++k) {
    const fem::BeamElement& e = mesh.beams[k];
    out.lines.push_back({e.nodes[0], e.nodes[1]});
    vein(static_cast<Eigen::Index>(k)) = e.vein;
  }
  for (std::size_t k = 0; k < np; ++k) {
    const auto& t = mesh.triangles[k];
    out.polygons.push_back({t[0], t[1], t[2]});
    const auto& N = mesh.nodes;
    strain(static_cast<Eigen::Index>(nl + k)) = triangle_membrane_strain(
        N[static_cast<std::size_t>(t[0])], N[static_cast<std::size_t>(t[1])], N[static_cast<std::size_t>(t[2])],
        positions.col(t[0]), positions.col(t[1]), positions.col(t[2]));
  }
  out.cell_data.add_scalar("membrane_strain", std::move(strain));
  out.cell_data.add_scalar("vein", std::move(vein));
  return out;
}

}  // namespace flapsim::io
