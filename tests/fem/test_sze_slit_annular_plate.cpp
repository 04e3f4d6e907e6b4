// Benchmark 3.3 of [Sze et al. 2004] (docs/references.md): the slit annular
// plate under a lifting line force. Geometrically nonlinear statics of the
// co-rotational DKT+drilling shell (fem/nonlinear_static_solver.hpp) against
// the published load–deflection curves of points A and B.
//
// Problem (Sze et al. 2004, §3.3): an annular plate, inner radius Ri = 6, outer
// Ro = 10, thickness h = 0.03, E = 21e6, ν = 0, cut along one radius. One side
// of the cut is clamped; on the other a vertical line force q acts, up to
// q_max = 0.8 per unit length. A and B are the inner and outer corners of the
// loaded edge; W their vertical deflections (consistent units). The deflection
// reaches 58 h at B: rotations of about 1.4 rad, a test of the large-rotation
// kinematics of the shell, with bending and twisting coupled to membrane action.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "fem/nonlinear_static_solver.hpp"
#include "fem/structured_mesh.hpp"
#include "fem_test_helpers.hpp"

namespace flapsim::fem {
namespace {

struct SlitPlateRow {
  double load_fraction;  // q / q_max
  double w_a, w_b;       // vertical deflections of A (r = Ri) and B (r = Ro)
};

// Sze, Liu & Lo 2004, §3.3, the tabulated W_A and W_B (ABAQUS S4R, 10 × 80
// mesh), every load level of the table. Transcribed also in MBDyn's test
// tests/plates/sze2004/sze33/sze33_ref.dat (used to check the transcription).
constexpr SlitPlateRow kSzeSlitPlateTable[] = {
    {0.025, 1.305, 1.789},  {0.05, 2.455, 3.370},   {0.075, 3.435, 4.720},  {0.10, 4.277, 5.876},
    {0.125, 5.007, 6.872},  {0.15, 5.649, 7.736},   {0.20, 6.725, 9.160},   {0.25, 7.602, 10.288},
    {0.30, 8.340, 11.213},  {0.35, 8.974, 11.992},  {0.40, 9.529, 12.661},  {0.45, 10.023, 13.247},
    {0.50, 10.468, 13.768}, {0.55, 10.876, 14.240}, {0.60, 11.257, 14.674}, {0.65, 11.620, 15.081},
    {0.70, 11.970, 15.469}, {0.75, 12.310, 15.842}, {0.80, 12.642, 16.202}, {0.85, 12.966, 16.550},
    {0.90, 13.282, 16.886}, {0.95, 13.590, 17.212}, {1.00, 13.891, 17.528}};

TEST(SzeSlitAnnularPlate, LoadDeflectionOfPointsAAndBWithinTwoPercentOfSze) {
  const double Ri = 6.0, Ro = 10.0, h = 0.03, E = 21e6, q_max = 0.8;
  // Sze's mesh of the table: 10 cells radially, 80 around (each cell split
  // into two DKT triangles, alternating diagonals). The 6 × 30 mesh of earlier
  // studies ends 4.1 % (A) and 3.4 % (B) below the table at q_max with these
  // triangles: the table belongs to the finer mesh.
  const int n_radial = 10, n_around = 80;
  // u → radius, v → angle from the loaded side (θ = 0) to the clamped side
  // (θ = 2π): the two sides of the cut are distinct nodes; normals along +z.
  const StructuralModel sm = testing::uniform_shell_model(
      grid_mesh(n_radial, n_around,
                [&](double u, double v) {
                  const double r = Ri + u * (Ro - Ri), th = 2.0 * std::numbers::pi * v;
                  return Eigen::Vector3d(r * std::cos(th), r * std::sin(th), 0.0);
                }),
      testing::shell(E, 0.0, h, 1.0));
  const CorotationalModel model = make_corotational_model(sm);
  auto node = [&](int i, int j) { return j * (n_radial + 1) + i; };
  Constraints clamp(model.num_dofs());
  std::vector<int> clamped;
  for (int i = 0; i <= n_radial; ++i) clamped.push_back(node(i, n_around));
  clamp.clamp_nodes(clamped);
  // The line force q_max on the loaded edge, lumped by the trapezoidal rule
  // (exact for a constant line load on straight two-node edges): a dead load.
  Eigen::VectorXd F_max = Eigen::VectorXd::Zero(model.num_dofs());
  for (int i = 0; i <= n_radial; ++i)
    F_max(dof_index(node(i, 0), UZ)) = q_max * (Ro - Ri) / n_radial * ((i == 0 || i == n_radial) ? 0.5 : 1.0);
  const int A = node(0, 0), B = node(n_radial, 0);

  // Load control, two equal Newton load steps between table levels (a single
  // step of 0.025 q_max from the flat plate diverges). The relative residual
  // of this thin plate (membrane/bending stiffness ratio (Ro/h)² ≈ 1e5) stalls
  // near 3e-6; 1e-5 is asked. Tightened to 4e-6, no W changes by 1e-3.
  NonlinearStaticOptions opt;
  opt.load_steps = 1;
  opt.tolerance = 1e-5;
  CorotationalState state = reference_state(model);
  double previous = 0.0, worst = 0.0;
  int iterations = 0;
  for (const SlitPlateRow& row : kSzeSlitPlateTable) {
    const int substeps = 2;
    for (int k = 1; k <= substeps; ++k) {
      const double lambda = previous + (row.load_fraction - previous) * k / substeps;
      const NonlinearStaticResult r = solve_nonlinear_static(model, clamp, Eigen::VectorXd(lambda * F_max), state, opt);
      ASSERT_TRUE(r.converged) << "q/q_max = " << lambda << ": " << r.failure;
      iterations += r.total_iterations;
    }
    previous = row.load_fraction;
    const double wa = state.position[A].z(), wb = state.position[B].z();
    std::printf("  q/q_max %.3f  W_A %7.3f (Sze %7.3f, %+.2f %%)  W_B %7.3f (Sze %7.3f, %+.2f %%)\n",
                row.load_fraction, wa, row.w_a, 100.0 * (wa / row.w_a - 1.0), wb, row.w_b,
                100.0 * (wb / row.w_b - 1.0));
    // Within 2 % of Sze's table (issue 28, "Done when").
    EXPECT_NEAR(wa / row.w_a, 1.0, 0.02) << "W_A at q/q_max = " << row.load_fraction;
    EXPECT_NEAR(wb / row.w_b, 1.0, 0.02) << "W_B at q/q_max = " << row.load_fraction;
    worst = std::max({worst, std::abs(wa / row.w_a - 1.0), std::abs(wb / row.w_b - 1.0)});
  }
  std::printf("  worst deviation from Sze's table %.2f %%, %d Newton iterations\n", 100.0 * worst, iterations);
}

}  // namespace
}  // namespace flapsim::fem
