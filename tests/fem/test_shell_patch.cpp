// Patch tests and rigid-body checks of the flat shell (DKT + OPT membrane).
// A patch of distorted triangles under a displacement field the element must
// represent exactly (linear in-plane, quadratic w) reproduces it at the
// interior nodes to round-off (Irons' patch test; [Batoz et al. 1980] for DKT,
// [Felippa 2003] for OPT; docs/references.md).

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <initializer_list>
#include <vector>

#include "fem/shell_element.hpp"
#include "fem_test_helpers.hpp"

namespace flapsim::fem {
namespace {

using testing::shell;

// A 3×3-cell patch on [0, 2] × [0, 1.5] with interior nodes moved off the grid.
Mesh distorted_patch() {
  Mesh m = rectangle_mesh(0.0, 0.0, 2.0, 1.5, 3, 3, Diagonal::Alternating);
  const double shift[4][2] = {{0.11, -0.07}, {-0.09, 0.05}, {0.06, 0.08}, {-0.05, -0.1}};
  int k = 0;
  for (int j = 1; j <= 2; ++j)
    for (int i = 1; i <= 2; ++i) {
      m.nodes[static_cast<size_t>(j * 4 + i)] += Eigen::Vector3d(shift[k][0], shift[k][1], 0.0);
      ++k;
    }
  return m;
}

bool on_boundary(const Eigen::Vector3d& p) {
  return std::abs(p.x()) < 1e-12 || std::abs(p.x() - 2.0) < 1e-12 || std::abs(p.y()) < 1e-12 ||
         std::abs(p.y() - 1.5) < 1e-12;
}

using NodalField = Eigen::Matrix<double, 6, 1>;

// Solves the patch with the `field` DOFs prescribed to the exact field on the boundary
// and the `other` DOFs held at zero everywhere (the field has none of them), and expects
// the exact field at every interior node to round-off.
template <typename Exact>
void expect_patch_reproduces(const Mesh& mesh, const Exact& exact, std::initializer_list<int> field,
                             std::initializer_list<int> other) {
  const auto sys = assemble(testing::uniform_shell_model(mesh, shell(70e9, 0.3, 0.01, 2700)));
  const Eigen::MatrixXd K(sys.stiffness);
  const int n = mesh.num_dofs();
  std::vector<bool> pres(static_cast<size_t>(n), false);
  Eigen::VectorXd val = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    const NodalField e = exact(mesh.nodes[i]);
    for (int d : other) pres[dof_index(i, d)] = true;
    if (on_boundary(mesh.nodes[i]))
      for (int d : field) {
        pres[dof_index(i, d)] = true;
        val(dof_index(i, d)) = e(d);
      }
  }
  const Eigen::VectorXd u = testing::solve_prescribed(K, Eigen::VectorXd::Zero(n), pres, val);
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    if (on_boundary(mesh.nodes[i])) continue;
    const NodalField e = exact(mesh.nodes[i]);
    for (int d : field) EXPECT_NEAR(u(dof_index(i, d)), e(d), 1e-15) << "node " << i << " dof " << d;
  }
}

TEST(ShellPatch, MembraneLinearFieldIsExact) {
  // u = 1e-3 (1 + 2x + 3y), v = 1e-3 (−1 + 0.5x − 1.5y): constant strain, rotation
  // θz = ½(∂v/∂x − ∂u/∂y) = ½(0.5 − 3)·1e-3.
  auto exact = [](const Eigen::Vector3d& p) {
    NodalField d = NodalField::Zero();
    d(0) = 1e-3 * (1.0 + 2.0 * p.x() + 3.0 * p.y());
    d(1) = 1e-3 * (-1.0 + 0.5 * p.x() - 1.5 * p.y());
    d(5) = 0.5 * (0.5 - 3.0) * 1e-3;
    return d;
  };
  expect_patch_reproduces(distorted_patch(), exact, {UX, UY, RZ}, {UZ, RX, RY});
}

TEST(ShellPatch, BendingQuadraticFieldIsExact) {
  // w = 1e-3 (0.3 + 0.2x − 0.1y + x² + 0.7xy − 0.4y²): constant curvature.
  auto exact = [](const Eigen::Vector3d& p) {
    const double x = p.x(), y = p.y();
    NodalField d = NodalField::Zero();
    d(2) = 1e-3 * (0.3 + 0.2 * x - 0.1 * y + x * x + 0.7 * x * y - 0.4 * y * y);
    d(3) = 1e-3 * (-0.1 + 0.7 * x - 0.8 * y);   // θx = ∂w/∂y
    d(4) = -1e-3 * (0.2 + 2.0 * x + 0.7 * y);   // θy = −∂w/∂x
    return d;
  };
  expect_patch_reproduces(distorted_patch(), exact, {UZ, RX, RY}, {UX, UY, RZ});
}

TEST(ShellElement, RigidBodyMotionsAreStressFreeInAnyOrientation) {
  // A skewed triangle in a general 3-D position: K annihilates the six rigid
  // motions (u = t + r × p, rotations = r) and has rank 18 − 6 = 12.
  const std::array<Eigen::Vector3d, 3> p{Eigen::Vector3d(0.1, 0.2, 0.3), Eigen::Vector3d(1.2, 0.4, -0.2),
                                         Eigen::Vector3d(0.5, 1.1, 0.6)};
  const auto em = shell_element(p, shell(1e9, 0.3, 0.01, 1000));
  const double scale = em.stiffness.norm();
  for (int mode = 0; mode < 6; ++mode) {
    Eigen::Matrix<double, 18, 1> u = Eigen::Matrix<double, 18, 1>::Zero();
    Eigen::Vector3d t = Eigen::Vector3d::Zero(), r = Eigen::Vector3d::Zero();
    (mode < 3 ? t : r)(mode % 3) = 1.0;
    for (int a = 0; a < 3; ++a) {
      u.segment<3>(6 * a) = t + r.cross(p[a]);
      u.segment<3>(6 * a + 3) = r;
    }
    EXPECT_LT((em.stiffness * u).norm() / scale, 1e-14) << "rigid mode " << mode;
  }
  Eigen::SelfAdjointEigenSolver<Matrix18d> es(em.stiffness);
  int zero = 0;
  for (int i = 0; i < 18; ++i) zero += es.eigenvalues()(i) < 1e-10 * es.eigenvalues().maxCoeff();
  EXPECT_EQ(zero, 6);  // no spurious zero-energy mode (drilling included)
  // The consistent mass carries the element mass ρhA in each direction.
  const double area = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
  Eigen::Matrix<double, 18, 1> ux = Eigen::Matrix<double, 18, 1>::Zero();
  for (int a = 0; a < 3; ++a) ux(6 * a) = 1.0;
  EXPECT_NEAR(ux.dot(em.mass * ux), 1000 * 0.01 * area, 1e-12);
}

}  // namespace
}  // namespace flapsim::fem
