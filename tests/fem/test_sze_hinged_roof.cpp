// Benchmark 3.8 of [Sze et al. 2004] (docs/references.md): the hinged
// cylindrical roof under a central point load, isotropic, thickness 12.7. The
// load passes a limit point and the roof snaps through; followed here under
// displacement control of the loaded point (fem/displacement_control.hpp)
// through the snap, against the published load–deflection curve.
//
// Problem (Sze et al. 2004, §3.8): a cylindrical panel of radius R = 2540,
// length 2L = 508 along its axis and opening angle 2θ = 0.2 rad; its straight
// edges hinged (translations fixed, rotations free), its curved edges free;
// E = 3102.75, ν = 0.3, h = 12.7; a point load P at the centre C, P_max = 3000.
// W_C is the downward deflection of C. The crown rises 12.7 above the hinges:
// at W_C = 29 the roof is turned inside out.
//
// Asserted: every tabulated point within 2 % of P_max, and the limit load and
// the lowest load after the snap within 2 % of Sze's. Relative to its own P,
// a point differs by up to 3.2 % (W_C = 15.7, the steep descending branch,
// where 3.2 % of P is a shift of W_C by 0.1); the first point is 1.7 % stiffer,
// and refining the mesh does not close that (24 × 24: 1.85 %, 32 × 32: 1.9 %):
// the Kirchhoff (DKT) shell has no transverse shear flexibility, which Sze's
// ABAQUS S4R has (h / 2L = 1/40, under a point load).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "fem/displacement_control.hpp"
#include "fem/structured_mesh.hpp"
#include "fem_test_helpers.hpp"

namespace flapsim::fem {
namespace {

struct RoofRow {
  double load_fraction;  // P / P_max
  double w_c;            // downward deflection of the centre
};

// Sze, Liu & Lo 2004, §3.8, the table of the isotropic roof of thickness 12.7
// (P/P_max against W_C). Transcribed also in MBDyn's test
// tests/plates/sze2004/sze38/sze38_ref_a.dat (used to check the transcription).
constexpr RoofRow kSzeRoofTable[] = {
    {0.0877, 0.693},  {0.1980, 1.638},  {0.3473, 3.087},  {0.4686, 4.477},  {0.5647, 5.802},  {0.6381, 7.057},
    {0.6908, 8.237},  {0.7246, 9.339},  {0.7412, 10.358}, {0.7421, 11.293}, {0.7286, 12.141}, {0.7023, 12.903},
    {0.6649, 13.583}, {0.6182, 14.188}, {0.5643, 14.728}, {0.5055, 15.217}, {0.4442, 15.676}, {0.3830, 16.125},
    {0.3245, 16.590}, {0.2717, 17.094}, {0.2272, 17.657}, {0.1940, 18.299}, {0.1750, 19.028}, {0.1729, 19.852},
    {0.1905, 20.771}, {0.2303, 21.780}, {0.2950, 22.875}, {0.3871, 24.049}, {0.4443, 24.663}, {0.5093, 25.293},
    {0.5826, 25.940}, {0.6644, 26.601}, {0.7551, 27.276}, {0.8549, 27.964}, {0.9643, 28.663}, {1.0835, 29.374}};

TEST(SzeHingedRoof, SnapThroughLoadDeflectionWithinTwoPercentOfSze) {
  const double R = 2540.0, L = 254.0, theta = 0.1, h = 12.7, E = 3102.75, nu = 0.3, P_max = 3000.0;
  // 16 × 16 cells over the whole roof (512 DKT triangles, alternating
  // diagonals). Refined to 24 × 24, P moves by at most 0.4 % of P_max; at
  // 32 × 32 the path leaves the symmetric branch after W_C = 15 (an asymmetric
  // equilibrium: controlling one point does not hold the symmetry).
  const int n = 16;
  const StructuralModel sm = testing::uniform_shell_model(
      grid_mesh(n, n,
                [&](double u, double v) {
                  const double phi = theta * (2.0 * v - 1.0);
                  return Eigen::Vector3d(L * (2.0 * u - 1.0), R * std::sin(phi), R * (std::cos(phi) - 1.0));
                }),
      testing::shell(E, nu, h, 1.0));
  const CorotationalModel model = make_corotational_model(sm);
  auto node = [&](int i, int j) { return j * (n + 1) + i; };
  Constraints hinges(model.num_dofs());
  for (int i = 0; i <= n; ++i)
    for (int j : {0, n})
      for (int d : {UX, UY, UZ}) hinges.fix_dof(dof_index(node(i, j), d));
  const int C = dof_index(node(n / 2, n / 2), UZ);
  CorotationalState state = reference_state(model);
  // Displacement control: W_C prescribed at every tabulated value (two equal
  // increments between them), P read from the reaction.
  double previous = 0.0, worst = 0.0, worst_of_max = 0.0, p_limit = 0.0, p_min = 1e300;
  int iterations = 0;
  for (const RoofRow& row : kSzeRoofTable) {
    const int substeps = 2;
    DisplacementControlResult r;
    for (int k = 1; k <= substeps; ++k) {
      const double w = previous + (row.w_c - previous) * k / substeps;
      r = solve_displacement_controlled(model, hinges, C, -w, state);
      ASSERT_TRUE(r.converged) << "W_C = " << w << ": " << r.failure;
      iterations += r.iterations;
    }
    previous = row.w_c;
    const double p = -r.reaction / P_max;
    std::printf("  W_C %7.3f  P/P_max %7.4f (Sze %7.4f, %+.2f %%)\n", row.w_c, p, row.load_fraction,
                100.0 * (p / row.load_fraction - 1.0));
    worst = std::max(worst, std::abs(p / row.load_fraction - 1.0));
    worst_of_max = std::max(worst_of_max, std::abs(p - row.load_fraction));
    // Every point within 2 % of P_max (the load scale of the table).
    EXPECT_NEAR(p, row.load_fraction, 0.02) << "W_C = " << row.w_c;
    if (row.w_c < 12.0) p_limit = std::max(p_limit, p);  // the limit point, before the snap
    if (row.w_c > 17.0 && row.w_c < 22.0) p_min = std::min(p_min, p);  // the lowest load after it
  }
  // The limit load and the lowest load after the snap within 2 % of Sze's
  // (table: 0.7421 at W_C = 11.293 and 0.1729 at 19.852).
  std::printf("  limit load %.4f P_max (Sze 0.7421, %+.2f %%), lowest %.4f P_max (Sze 0.1729, %+.2f %%); "
              "worst point %.2f %% of its P, %.2f %% of P_max; %d Newton iterations\n",
              p_limit, 100.0 * (p_limit / 0.7421 - 1.0), p_min, 100.0 * (p_min / 0.1729 - 1.0), 100.0 * worst,
              100.0 * worst_of_max, iterations);
  EXPECT_NEAR(p_limit / 0.7421, 1.0, 0.02);
  EXPECT_NEAR(p_min / 0.1729, 1.0, 0.02);
}

}  // namespace
}  // namespace flapsim::fem
