// Geometrically nonlinear statics (fem/nonlinear_static_solver.hpp): the
// cantilever under an end moment M = 2πEI/L rolls into a full circle of radius
// R = EI/M = L/(2π) (the Euler elastica: constant curvature M/EI; benchmark 1
// of Sze, Liu & Lo 2004, and Battini & Pacoste 2002 §7.1), with frame elements
// and with a shell strip; and a whole model moved rigidly by a large rotation
// carries no internal force.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "fem/nodal_rotation.hpp"
#include "fem/nonlinear_static_solver.hpp"
#include "fem/section_properties.hpp"
#include "fem/structured_mesh.hpp"
#include "fem_test_helpers.hpp"

namespace flapsim::fem {
namespace {

constexpr double kPiRoll = std::numbers::pi;

// Largest distance of the nodes from the exact circle x = R sin(s/R),
// z = R (1 − cos(s/R)) (s = X, the arc length), over R; y must not move.
double worst_circle_error(const CorotationalState& s, const std::vector<Eigen::Vector3d>& X, double R) {
  double worst = 0.0;
  for (size_t i = 0; i < X.size(); ++i) {
    const double arc = X[i].x();
    const Eigen::Vector3d exact(R * std::sin(arc / R), X[i].y(), R * (1.0 - std::cos(arc / R)));
    worst = std::max(worst, (s.position[i] - exact).norm() / R);
  }
  return worst;
}

TEST(NonlinearStatic, FrameCantileverRollsIntoCircle) {
  const double L = 1.0;
  wings::Section sec;
  sec.outer_diameter = 0.02;
  sec.wall = 0.01;  // solid
  FrameProperties f;
  f.youngs_modulus = 1e8;
  f.shear_modulus = 1e8 / 2.6;
  f.density = 1000.0;
  f.section = section_properties(sec);
  const int n = 32;
  const StructuralModel sm = testing::uniform_beam_model(line_mesh({0, 0, 0}, {L, 0, 0}, n), f);
  const CorotationalModel model = make_corotational_model(sm);
  Constraints c(model.num_dofs());
  c.clamp_nodes({0});
  const double EI = f.youngs_modulus * f.section.I_y;
  const double M = 2.0 * kPiRoll * EI / L;
  Eigen::VectorXd F = Eigen::VectorXd::Zero(model.num_dofs());
  F(dof_index(n, RY)) = -M;  // a moment about −y bends x toward +z
  CorotationalState s = reference_state(model);
  NonlinearStaticOptions opt;
  opt.load_steps = 20;
  const NonlinearStaticResult r = solve_nonlinear_static(model, c, F, s, opt);
  ASSERT_TRUE(r.converged) << r.failure;
  const double R = EI / M;
  const double err = worst_circle_error(s, model.reference_positions, R);
  const double tip_gap = s.position[n].norm() / R;
  // Tip rotation 2π: the tip's R is the identity again, and the middle node is
  // turned by π about −y.
  const double tip_rot = rotation_vector(s.rotation[n]).norm();
  const Eigen::Vector3d mid = rotation_vector(s.rotation[n / 2]);
  std::printf("  frame: %d iterations, worst node off circle %.2e R, tip gap %.2e R, |θ_tip| %.2e, θ_mid %.4f\n",
              r.total_iterations, err, tip_gap, tip_rot, mid.norm());
  EXPECT_LT(err, 0.01);
  EXPECT_LT(tip_gap, 0.01);
  EXPECT_LT(tip_rot, 0.01 * 2.0 * kPiRoll);
  EXPECT_NEAR(mid.norm(), kPiRoll, 0.01 * kPiRoll);
}

TEST(NonlinearStatic, ShellStripRollsIntoCircle) {
  const double L = 1.0, b = 0.1, h = 0.01, E = 1.2e6;
  const int nx = 32, ny = 2;
  const StructuralModel sm =
      testing::uniform_shell_model(rectangle_mesh(0.0, -b / 2, L, b, nx, ny), testing::shell(E, 0.0, h, 1000.0));
  const CorotationalModel model = make_corotational_model(sm);
  Constraints c(model.num_dofs());
  std::vector<int> root, tip;
  for (int i = 0; i < model.num_nodes(); ++i) {
    if (model.reference_positions[i].x() < 1e-12) root.push_back(i);
    if (model.reference_positions[i].x() > L - 1e-12) tip.push_back(i);
  }
  c.clamp_nodes(root);
  const double EI = E * b * h * h * h / 12.0;  // ν = 0: no anticlastic stiffening
  const double M = 2.0 * kPiRoll * EI / L;
  // The end moment as a line moment M/b on the tip edge, lumped by the
  // trapezoidal rule (exact for a constant line load on linear edges).
  Eigen::VectorXd F = Eigen::VectorXd::Zero(model.num_dofs());
  for (int i : tip) {
    const double y = model.reference_positions[i].y();
    const double w = (std::abs(std::abs(y) - b / 2) < 1e-12 ? 0.5 : 1.0) * b / ny;
    F(dof_index(i, RY)) = -M / b * w;
  }
  CorotationalState s = reference_state(model);
  NonlinearStaticOptions opt;
  opt.load_steps = 20;
  const NonlinearStaticResult r = solve_nonlinear_static(model, c, F, s, opt);
  ASSERT_TRUE(r.converged) << r.failure;
  const double R = EI / M;
  const double err = worst_circle_error(s, model.reference_positions, R);
  double tip_gap = 0.0, tip_rot = 0.0;
  for (int i : tip) {
    tip_gap = std::max(tip_gap, (s.position[i] - Eigen::Vector3d(0, model.reference_positions[i].y(), 0)).norm() / R);
    tip_rot = std::max(tip_rot, rotation_vector(s.rotation[i]).norm());
  }
  std::printf("  shell: %d iterations, worst node off circle %.2e R, tip gap %.2e R, |θ_tip| %.2e\n",
              r.total_iterations, err, tip_gap, tip_rot);
  EXPECT_LT(err, 0.01);
  EXPECT_LT(tip_gap, 0.01);
  EXPECT_LT(tip_rot, 0.01 * 2.0 * kPiRoll);
}

TEST(NonlinearStatic, RigidRotationOfWholeModelIsStressFree) {
  // A plate with a stiffening beam along one edge, unclamped, turned by 2.7 rad
  // about a skew axis and moved: every internal force vanishes to round-off.
  // Measure: max |f_int| over the max of the spurious force K u that the
  // linear model gives for the same motion.
  Mesh mesh = rectangle_mesh(0.0, 0.0, 0.05, 0.02, 10, 4);
  for (int i = 0; i < 10; ++i) mesh.beams.push_back({{i, i + 1}, 0});
  mesh.vein_names.push_back("edge");
  StructuralModel sm;
  sm.shell.assign(mesh.triangles.size(), testing::shell(4e9, 0.3, 20e-6, 1400.0));
  wings::Section sec;
  sec.outer_diameter = 1e-3;
  sec.wall = 0.5e-3;
  FrameProperties f;
  f.youngs_modulus = 1e11;
  f.shear_modulus = 1e11 / 2.6;
  f.density = 1500.0;
  f.section = section_properties(sec);
  sm.frame.assign(mesh.beams.size(), f);
  sm.mesh = mesh;
  const CorotationalModel model = make_corotational_model(sm);
  const Eigen::Matrix3d Q = rotation_matrix(2.7 * Eigen::Vector3d(1.0, 2.0, -0.5).normalized());
  CorotationalState s = reference_state(model);
  for (int i = 0; i < model.num_nodes(); ++i) {
    s.position[i] = Q * model.reference_positions[i] + Eigen::Vector3d(0.01, -0.03, 0.2);
    s.rotation[i] = Q;
  }
  NonlinearAssembler asmb(model, Constraints(model.num_dofs()));
  Eigen::VectorXd fint;
  const double energy = asmb.evaluate(s, fint, false);
  const Eigen::VectorXd u = displacement_vector(model, s);
  const double linear = (assemble(sm).stiffness * u).cwiseAbs().maxCoeff();
  std::printf("  rigid 2.7 rad: max|f_int| %.3e, linear K u %.3e (ratio %.1e), energy %.1e J\n",
              fint.cwiseAbs().maxCoeff(), linear, fint.cwiseAbs().maxCoeff() / linear, energy);
  EXPECT_LT(fint.cwiseAbs().maxCoeff(), 1e-12 * linear);
}

}  // namespace
}  // namespace flapsim::fem
