// Plate verification: free vibration of a square cantilever plate (Leissa)
// and the centre deflection of square plates under uniform pressure
// (Timoshenko & Woinowsky-Krieger). The cantilever runs at h/a = 1/100 and at
// the insect-wing ratio 1/4000: a locking element would fail the thin case.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fem/constraints.hpp"
#include "fem/modal_solver.hpp"
#include "fem/static_solver.hpp"
#include "fem_test_helpers.hpp"

namespace flapsim::fem {
namespace {

using testing::plate_D;
using testing::shell;

class CantileverPlate : public ::testing::TestWithParam<double> {};

TEST_P(CantileverPlate, FirstFiveFrequenciesMatchLeissa) {
  const double a = 1.0, h = a * GetParam(), rho = 1000.0;
  const ShellProperties s = shell(1e9, 0.3, h, rho);
  const Mesh mesh = rectangle_mesh(0.0, 0.0, a, a, 20, 20);
  const auto sys = assemble(testing::uniform_shell_model(mesh, s));
  const Constraints c = root_clamp(mesh, 1e-9);  // edge y = 0 clamped
  ModalOptions opt;
  opt.num_modes = 5;
  const ModalResult r = solve_modes(sys.stiffness, sys.mass, c, opt);
  // Leissa (1969), NASA SP-160, Table 4.53 (ν = 0.3): ω a² √(ρh/D).
  const double leissa[5] = {3.492, 8.525, 21.43, 27.33, 31.11};
  const double scale = a * a * std::sqrt(rho * h / plate_D(s));
  for (int k = 0; k < 5; ++k) {
    const double lam = 2.0 * std::numbers::pi * r.frequencies_hz(k) * scale;
    std::printf("  h/a = %.6g  mode %d: %.4f (Leissa %.3f, %+.2f %%)\n", GetParam(), k + 1, lam,
                leissa[k], 100.0 * (lam / leissa[k] - 1.0));
    EXPECT_NEAR(lam / leissa[k], 1.0, 0.01) << "mode " << k + 1;
  }
}

INSTANTIATE_TEST_SUITE_P(ThicknessToSide, CantileverPlate, ::testing::Values(1.0 / 100.0, 1.0 / 4000.0));

// Uniform pressure q on a square plate, centre deflection. Boundary DOFs:
// simply supported = w and the rotation along the edge fixed ("hard" support,
// the Kirchhoff condition w = 0 along the edge); clamped = w and both rotations.
double centre_deflection_coefficient(bool clamped, int n) {
  const double a = 1.0, q = 1.0;
  const ShellProperties s = shell(1e9, 0.3, 0.01, 1000.0);
  const Mesh mesh = rectangle_mesh(0.0, 0.0, a, a, n, n);
  const auto sys = assemble(testing::uniform_shell_model(mesh, s));
  Constraints c(mesh.num_dofs());
  Eigen::VectorXd F = Eigen::VectorXd::Zero(mesh.num_dofs());
  for (const auto& t : mesh.triangles) {  // lumped pressure: qA/3 per corner
    const auto& p = mesh.nodes;
    const double A = 0.5 * (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]).norm();
    for (int i : t) F(dof_index(i, UZ)) += q * A / 3.0;
  }
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    const Eigen::Vector3d& p = mesh.nodes[i];
    for (int d : {UX, UY, RZ}) c.fix_dof(dof_index(i, d));  // flat plate: membrane unloaded
    const bool xedge = std::abs(p.x()) < 1e-9 || std::abs(p.x() - a) < 1e-9;
    const bool yedge = std::abs(p.y()) < 1e-9 || std::abs(p.y() - a) < 1e-9;
    if (!xedge && !yedge) continue;
    c.fix_dof(dof_index(i, UZ));
    if (clamped || xedge) c.fix_dof(dof_index(i, RX));  // x = const edge: ∂w/∂y = 0
    if (clamped || yedge) c.fix_dof(dof_index(i, RY));  // y = const edge: ∂w/∂x = 0
  }
  const StaticSolver solver(sys.stiffness, c);
  const Eigen::VectorXd u = solver.solve(F);
  const int centre = (n / 2) * (n + 1) + n / 2;
  return u(dof_index(centre, UZ)) * plate_D(s) / (q * std::pow(a, 4));
}

// Navier's double series for the centre of a simply supported square plate under uniform
// load q (Timoshenko & Woinowsky-Krieger, Theory of Plates and Shells, §30, eq. 136):
// w = 16 q a⁴ / (π⁶ D) Σ_{m,n odd} (−1)^((m+n)/2 − 1) / (m n (m² + n²)²); Table 8 rounds it to
// 0.00406. Summed here to m, n ≤ 401 (the terms fall as 1/(m n (m² + n²)²): a tail below 1e-10).
double navier_centre_coefficient() {
  double sum = 0.0;
  for (int m = 1; m <= 401; m += 2)
    for (int n = 1; n <= 401; n += 2) {
      const double sign = ((m + n) / 2 - 1) % 2 == 0 ? 1.0 : -1.0;
      const double mn2 = static_cast<double>(m * m + n * n);
      sum += sign / (static_cast<double>(m) * n * mn2 * mn2);
    }
  return 16.0 / std::pow(std::numbers::pi, 6) * sum;
}

TEST(SquarePlateUniformLoad, SimplySupportedCentreDeflection) {
  const double reference = navier_centre_coefficient();  // 0.00406235 qa⁴/D
  EXPECT_NEAR(reference, 0.00406, 0.000005);              // the value Table 8 prints
  const double w = centre_deflection_coefficient(false, 24);
  std::printf("  simply supported: %.6f (%.8f, %+.2f %%)\n", w, reference, 100.0 * (w / reference - 1.0));
  EXPECT_NEAR(w / reference, 1.0, 0.01);
}

TEST(SquarePlateUniformLoad, ClampedCentreDeflection) {
  // 0.0012653 qa⁴/D: Taylor & Govindjee 2004 (their series solution, 0.00126532); Timoshenko &
  // Woinowsky-Krieger, Table 35, print it rounded as 0.00126.
  const double reference = 0.0012653;
  const double w = centre_deflection_coefficient(true, 24);
  std::printf("  clamped: %.6f (%.7f, %+.2f %%)\n", w, reference, 100.0 * (w / reference - 1.0));
  EXPECT_NEAR(w / reference, 1.0, 0.01);
}

}  // namespace
}  // namespace flapsim::fem
