// The lattice on the FEM's shell (pipeline/fsi/fem_attachment.hpp, docs/fsi.md "Attachment
// to the FEM"): a rigid motion of the FEM carries the lattice rigidly, and the panel loads
// reach the FEM nodes with their total force and moment kept, whatever the deformation.

#include <gtest/gtest.h>

#include <random>

#include "fem/structured_mesh.hpp"
#include "fsi/plate_wing_fixtures.hpp"
#include "pipeline/fsi/fem_attachment.hpp"

namespace {

using namespace flapsim;

// The plate wing's FEM: the rectangle of plate_grid (x 2.5 … 12.5 mm, y 0 … 40 mm), meshed
// coarser than the lattice spanwise and finer chordwise, so neither follows the other.
fem::Mesh plate_mesh() { return fem::rectangle_mesh(0.0025, 0.0, 0.010, 0.040, 7, 5); }

Eigen::Matrix3Xd reference_nodes(const fem::Mesh& mesh) {
  Eigen::Matrix3Xd x(3, mesh.num_nodes());
  for (int n = 0; n < mesh.num_nodes(); ++n) x.col(n) = mesh.nodes[static_cast<std::size_t>(n)];
  return x;
}

TEST(FsiFemAttachment, ARigidMotionOfTheFemCarriesTheLatticeRigidly) {
  // Mechanics: x = R p + t, v = ω × (x − t) + u for every lattice node p of the flat plate,
  // to round-off (each node is an affine combination of its triangle's nodes).
  const auto grid = test::plate_grid(4, 9);
  const fem::Mesh mesh = plate_mesh();
  const fsi::FemAttachment a = fsi::attach_wing_to_fem(mesh, grid.nodes, 4, 9);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  const Eigen::Vector3d t(0.01, -0.02, 0.005), omega(3.0, -1.0, 2.0), u(0.4, 0.1, -0.3);
  const Eigen::Matrix3Xd ref = reference_nodes(mesh);
  Eigen::Matrix3Xd xf = (R * ref).colwise() + t, vf(3, ref.cols());
  for (Eigen::Index n = 0; n < ref.cols(); ++n) vf.col(n) = omega.cross(xf.col(n) - t) + u;
  Eigen::Matrix3Xd x, v;
  fsi::fem_surface_nodes(a, mesh, xf, vf, x, v);
  for (Eigen::Index k = 0; k < grid.nodes.cols(); ++k) {
    const Eigen::Vector3d expected = R * grid.nodes.col(k) + t;
    EXPECT_LT((x.col(k) - expected).norm(), 1e-15) << "node " << k;
    EXPECT_LT((v.col(k) - (omega.cross(expected - t) + u)).norm(), 1e-14) << "node " << k;
  }
}

TEST(FsiFemAttachment, PanelLoadsKeepTheirTotalForceAndMomentOnADeformedFem) {
  // Statics: Σ nodal forces = Σ F_p and Σ (x_i − c) × f_i + Σ m_i = Σ (P_p − c) × F_p for any
  // c, for a strongly deformed FEM and panel points off its facets, to round-off.
  const int nc = 3, ns = 8;
  const auto grid = test::plate_grid(nc, ns);
  const fem::Mesh mesh = plate_mesh();
  const fsi::FemAttachment a = fsi::attach_wing_to_fem(mesh, grid.nodes, nc, ns);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  Eigen::Matrix3Xd xf = reference_nodes(mesh);
  for (Eigen::Index n = 0; n < xf.cols(); ++n) {  // bent and twisted, and shaken by 1 mm
    const double y = xf(1, n), x = xf(0, n) - 0.0075;
    xf(2, n) += 2.0 * y * y + 0.6 * x * y + 1e-3 * r(rng);
  }
  uvlm::PanelLoads panels;
  panels.force.resize(3, nc * ns);
  panels.point.resize(3, nc * ns);
  for (int p = 0; p < nc * ns; ++p) {
    const fsi::ShellPoint& s = a.panels[static_cast<std::size_t>(p)];
    const auto& tri = mesh.triangles[static_cast<std::size_t>(s.triangle)];
    Eigen::Vector3d foot = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) foot += s.weights[static_cast<std::size_t>(k)] * xf.col(tri[k]);
    panels.point.col(p) = foot + 1e-3 * Eigen::Vector3d(r(rng), r(rng), r(rng));  // off the facet
    panels.force.col(p) = 1e-3 * Eigen::Vector3d(r(rng), r(rng), r(rng));
  }
  Eigen::VectorXd nodal = Eigen::VectorXd::Zero(mesh.num_dofs());
  fsi::add_panel_loads_to_fem(a, mesh, xf, panels, nodal);
  const Eigen::Vector3d c(0.02, -0.01, 0.03);
  Eigen::Vector3d f_sum = Eigen::Vector3d::Zero(), m_sum = Eigen::Vector3d::Zero();
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const Eigen::Vector3d f = nodal.segment<3>(fem::dof_index(n, fem::UX));
    f_sum += f;
    m_sum += (xf.col(n) - c).cross(f) + nodal.segment<3>(fem::dof_index(n, fem::RX));
  }
  const Eigen::Vector3d f_total = panels.force.rowwise().sum();
  const Eigen::Vector3d m_total = uvlm::moment_about(panels, c);
  EXPECT_LT((f_sum - f_total).norm(), 1e-15 * nc * ns);
  EXPECT_LT((m_sum - m_total).norm(), 1e-14 * m_total.norm());
}

TEST(FsiFemAttachment, APointJustOutsideTheMeshTakesTheNearestTriangle) {
  // A lattice node 0.1 mm beyond the plate's tip (an outline the mesh cuts by a chord): its
  // triangle is one at the tip edge and its weights extrapolate the plane (one negative).
  const fem::Mesh mesh = plate_mesh();
  const fsi::ShellPoint s = fsi::locate_on_shell(mesh, Eigen::Vector3d(0.006, 0.0401, 0.0));
  const auto& tri = mesh.triangles[static_cast<std::size_t>(s.triangle)];
  double y_max = 0.0;
  for (int k = 0; k < 3; ++k) y_max = std::max(y_max, mesh.nodes[static_cast<std::size_t>(tri[k])].y());
  EXPECT_DOUBLE_EQ(y_max, 0.040);
  EXPECT_NEAR(s.weights[0] + s.weights[1] + s.weights[2], 1.0, 1e-15);
  EXPECT_LT(std::min({s.weights[0], s.weights[1], s.weights[2]}), 0.0);
}

}  // namespace
