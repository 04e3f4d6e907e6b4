// Frame element verification against Euler–Bernoulli beam theory: cantilever
// bending frequencies (β L = 1.8751, 4.6941, 7.8548), tip deflection P L³ / 3EI
// and torsion frequencies ω = (2k − 1) π / (2L) √(GJ / (ρ I_p)).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fem/constraints.hpp"
#include "fem/modal_solver.hpp"
#include "fem/section_properties.hpp"
#include "fem/static_solver.hpp"
#include "fem_test_helpers.hpp"

namespace flapsim::fem {
namespace {

constexpr double kL = 0.05;  // [m], a vein-like length

FrameProperties vein_like() {
  wings::Section sec;
  sec.outer_diameter = 0.4e-3;
  sec.wall = 0.05e-3;
  FrameProperties f;
  f.youngs_modulus = 6e9;
  f.shear_modulus = 6e9 / (2.0 * 1.3);
  f.density = 1200.0;
  f.section = section_properties(sec);
  return f;
}

// Cantilever along x, clamped at x = 0; keep only the DOFs listed in `keep`.
Constraints cantilever(const Mesh& mesh, std::initializer_list<int> keep) {
  Constraints c(mesh.num_dofs());
  c.clamp_nodes({0});
  for (int i = 1; i < mesh.num_nodes(); ++i)
    for (int d = 0; d < 6; ++d)
      if (std::find(keep.begin(), keep.end(), d) == keep.end()) c.fix_dof(dof_index(i, d));
  return c;
}

TEST(CantileverBeam, BendingFrequencies) {
  const FrameProperties f = vein_like();
  const Mesh mesh = line_mesh(Eigen::Vector3d::Zero(), Eigen::Vector3d(kL, 0, 0), 40);
  const auto sys = assemble(testing::uniform_beam_model(mesh, f));
  ModalOptions opt;
  opt.num_modes = 3;
  const ModalResult r = solve_modes(sys.stiffness, sys.mass, cantilever(mesh, {UZ, RY}), opt);
  // Roots of cos βL cosh βL = −1 (e.g. Blevins, Formulas for Natural Frequency, Table 8-1).
  const double beta_l[3] = {1.8751, 4.6941, 7.8548};
  const double c = std::sqrt(f.youngs_modulus * f.section.I_y / (f.density * f.section.area)) / (kL * kL);
  for (int k = 0; k < 3; ++k) {
    const double expected = beta_l[k] * beta_l[k] * c / (2.0 * std::numbers::pi);
    std::printf("  bending mode %d: %.3f Hz (theory %.3f, %+.3f %%)\n", k + 1, r.frequencies_hz(k), expected,
                100.0 * (r.frequencies_hz(k) / expected - 1.0));
    EXPECT_NEAR(r.frequencies_hz(k) / expected, 1.0, 0.005);
  }
}

TEST(CantileverBeam, TorsionFrequencies) {
  const FrameProperties f = vein_like();
  const Mesh mesh = line_mesh(Eigen::Vector3d::Zero(), Eigen::Vector3d(kL, 0, 0), 40);
  const auto sys = assemble(testing::uniform_beam_model(mesh, f));
  ModalOptions opt;
  opt.num_modes = 3;
  const ModalResult r = solve_modes(sys.stiffness, sys.mass, cantilever(mesh, {RX}), opt);
  for (int k = 1; k <= 3; ++k) {
    // Fixed–free shaft: ω_k = (2k − 1) π / (2L) √(GJ / (ρ I_p)).
    const double expected = (2 * k - 1) * std::numbers::pi / (2.0 * kL) *
                            std::sqrt(f.shear_modulus * f.section.torsion_constant /
                                      (f.density * f.section.polar_moment)) / (2.0 * std::numbers::pi);
    std::printf("  torsion mode %d: %.1f Hz (theory %.1f, %+.3f %%)\n", k, r.frequencies_hz(k - 1), expected,
                100.0 * (r.frequencies_hz(k - 1) / expected - 1.0));
    EXPECT_NEAR(r.frequencies_hz(k - 1) / expected, 1.0, 0.005);
  }
}

TEST(CantileverBeam, TipDeflectionOfAllSixDofModel) {
  // A beam along a skew direction in the xy plane, all 6 DOFs free: tip force
  // normal to the plane gives P L³ / 3EI, in-plane normal force P L³ / 3EI_z,
  // axial force P L / EA.
  wings::Section rect;
  rect.shape = wings::Section::Shape::Rectangle;
  rect.width = 0.3e-3;
  rect.height = 0.1e-3;
  FrameProperties f = vein_like();
  f.section = section_properties(rect);
  const Eigen::Vector3d dir = Eigen::Vector3d(1.0, 2.0, 0.0).normalized();
  const Mesh mesh = line_mesh(Eigen::Vector3d::Zero(), kL * dir, 10);
  const auto sys = assemble(testing::uniform_beam_model(mesh, f));
  Constraints c(mesh.num_dofs());
  c.clamp_nodes({0});
  const StaticSolver solver(sys.stiffness, c);
  const int tip = mesh.num_nodes() - 1;
  const double P = 1e-3;
  const double E = f.youngs_modulus;
  const Eigen::Vector3d inplane_normal = Eigen::Vector3d::UnitZ().cross(dir);

  Eigen::VectorXd F = Eigen::VectorXd::Zero(mesh.num_dofs());
  F(dof_index(tip, UZ)) = P;
  const double w = solver.solve(F)(dof_index(tip, UZ));
  const double w_ref = P * kL * kL * kL / (3.0 * E * f.section.I_y);  // Gere & Timoshenko
  EXPECT_NEAR(w / w_ref, 1.0, 1e-9);

  F.setZero();
  F.segment<3>(dof_index(tip, UX)) = P * inplane_normal;
  const Eigen::VectorXd u = solver.solve(F);
  const double v = u.segment<3>(dof_index(tip, UX)).dot(inplane_normal);
  EXPECT_NEAR(v / (P * kL * kL * kL / (3.0 * E * f.section.I_z)), 1.0, 1e-9);

  F.setZero();
  F.segment<3>(dof_index(tip, UX)) = P * dir;
  const double ax = solver.solve(F).segment<3>(dof_index(tip, UX)).dot(dir);
  EXPECT_NEAR(ax / (P * kL / (E * f.section.area)), 1.0, 1e-9);
}

TEST(SectionProperties, HollowCircleAndRectangle) {
  wings::Section c;
  c.outer_diameter = 2.0;
  c.wall = 0.5;  // inner diameter 1
  const auto p = section_properties(c);
  EXPECT_NEAR(p.area, std::numbers::pi / 4.0 * 3.0, 1e-14);          // π/4 (D² − d²)
  EXPECT_NEAR(p.I_y, std::numbers::pi / 64.0 * 15.0, 1e-14);         // π/64 (D⁴ − d⁴)
  EXPECT_NEAR(p.torsion_constant, std::numbers::pi / 32.0 * 15.0, 1e-14);
  wings::Section r;
  r.shape = wings::Section::Shape::Rectangle;
  r.width = 1.0;
  r.height = 1.0;
  // Square: J = 0.1406 a⁴ (Roark, Table 10.1, exact series 0.1406).
  EXPECT_NEAR(section_properties(r).torsion_constant, 0.1406, 0.0015);
}

}  // namespace
}  // namespace flapsim::fem
