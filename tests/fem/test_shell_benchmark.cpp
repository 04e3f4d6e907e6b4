// Curved and twisted shells built from flat facets (MacNeal & Harder 1985
// standard problems): the Scordelis–Lo roof and the twisted beam. Both couple
// membrane and bending action, which the plate tests do not.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fem/constraints.hpp"
#include "fem/static_solver.hpp"
#include "fem_test_helpers.hpp"

namespace flapsim::fem {
namespace {

using testing::shell;

// Scordelis–Lo roof: cylinder R = 25, length 50, 80° arc, h = 0.25,
// E = 4.32e8, ν = 0, self weight 90 per unit area; ends on rigid diaphragms
// (ux = uz = 0), straight edges free. Quarter model (symmetry at the crown and
// at mid-length). Reference: vertical displacement at the middle of the free
// edge 0.3024 (MacNeal & Harder, Finite Elements Anal. Des. 1, 1985).
double scordelis_lo(int n) {
  const double R = 25.0, L = 50.0, phi = 40.0 * std::numbers::pi / 180.0;
  // u along the arc from the crown (θ = 0) to the free edge, v along the axis y
  // from the diaphragm (y = 0) to mid-length (y = L/2).
  const Mesh mesh = grid_mesh(n, n, [&](double u, double v) {
    const double th = u * phi;
    return Eigen::Vector3d(R * std::sin(th), v * L / 2.0, R * std::cos(th));
  });
  const auto sys = assemble(testing::uniform_shell_model(mesh, shell(4.32e8, 0.0, 0.25, 1.0)));
  Constraints c(mesh.num_dofs());
  Eigen::VectorXd F = Eigen::VectorXd::Zero(mesh.num_dofs());
  for (const auto& t : mesh.triangles) {
    const auto& p = mesh.nodes;
    const double A = 0.5 * (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]).norm();
    for (int i : t) F(dof_index(i, UZ)) -= 90.0 * A / 3.0;
  }
  int edge_mid = -1;
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    const Eigen::Vector3d& p = mesh.nodes[i];
    if (std::abs(p.y()) < 1e-9) {  // diaphragm
      c.fix_dof(dof_index(i, UX));
      c.fix_dof(dof_index(i, UZ));
    }
    if (std::abs(p.y() - L / 2.0) < 1e-9) {  // symmetry plane y = L/2
      c.fix_dof(dof_index(i, UY));
      c.fix_dof(dof_index(i, RX));
      c.fix_dof(dof_index(i, RZ));
      if (std::abs(p.x() - R * std::sin(phi)) < 1e-9) edge_mid = i;
    }
    if (std::abs(p.x()) < 1e-9) {  // symmetry plane x = 0 (crown)
      c.fix_dof(dof_index(i, UX));
      c.fix_dof(dof_index(i, RY));
      c.fix_dof(dof_index(i, RZ));
    }
  }
  const StaticSolver solver(sys.stiffness, c);
  return -solver.solve(F)(dof_index(edge_mid, UZ));
}

TEST(ShellBenchmarks, ScordelisLoRoof) {
  const double w = scordelis_lo(20);
  std::printf("  Scordelis-Lo 20x20 quarter: %.4f (0.3024, %+.2f %%)\n", w, 100.0 * (w / 0.3024 - 1.0));
  EXPECT_NEAR(w / 0.3024, 1.0, 0.02);
}

// Twisted beam: length 12, width 1.1, thickness 0.32, twisted 90° root to
// tip, E = 29e6, ν = 0.22, clamped root, unit tip load. Reference tip
// displacements in the load direction: 0.005424 (load along the width at the
// tip, "in-plane") and 0.001754 (load along the thickness at the tip,
// "out-of-plane") (MacNeal & Harder 1985).
Eigen::Vector2d twisted_beam(int nx, int ny) {
  const double L = 12.0, w = 1.1;
  const Mesh mesh = grid_mesh(nx, ny, [&](double u, double v) {
    const double a = 0.5 * std::numbers::pi * u, s = (v - 0.5) * w;
    return Eigen::Vector3d(u * L, s * std::cos(a), s * std::sin(a));
  });
  const auto sys = assemble(testing::uniform_shell_model(mesh, shell(29e6, 0.22, 0.32, 1.0)));
  Constraints c(mesh.num_dofs());
  std::vector<int> root, tip;
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    if (std::abs(mesh.nodes[i].x()) < 1e-9) root.push_back(i);
    if (std::abs(mesh.nodes[i].x() - L) < 1e-9) tip.push_back(i);
  }
  c.clamp_nodes(root);
  const StaticSolver solver(sys.stiffness, c);
  Eigen::Vector2d out;
  // At the tip the width runs along z and the thickness along y.
  for (int k = 0; k < 2; ++k) {
    const int d = k == 0 ? UZ : UY;
    Eigen::VectorXd F = Eigen::VectorXd::Zero(mesh.num_dofs());
    for (int i : tip) F(dof_index(i, d)) = 1.0 / static_cast<double>(tip.size());
    const Eigen::VectorXd u = solver.solve(F);
    double mean = 0.0;
    for (int i : tip) mean += u(dof_index(i, d)) / static_cast<double>(tip.size());
    out(k) = mean;
  }
  return out;
}

TEST(ShellBenchmarks, TwistedBeam) {
  const Eigen::Vector2d u = twisted_beam(48, 8);
  std::printf("  twisted beam 48x8: in-plane %.6f (0.005424, %+.2f %%), out-of-plane %.6f (0.001754, %+.2f %%)\n",
              u(0), 100.0 * (u(0) / 0.005424 - 1.0), u(1), 100.0 * (u(1) / 0.001754 - 1.0));
  EXPECT_NEAR(u(0) / 0.005424, 1.0, 0.02);
  EXPECT_NEAR(u(1) / 0.001754, 1.0, 0.02);
}

}  // namespace
}  // namespace flapsim::fem
