// The modal solve has no absolute scale: a cantilever plate and its copy 2^-15 times the
// size (30 µm, a fairyfly's wing) have the same modes, the frequencies 2^15 times higher
// (f ∝ h / a² with h ∝ a). Spectra's Lanczos has absolute thresholds; before the pencil
// was rescaled (fem/modal_solver.cpp) the small plate's modes 4 … 12 were off by up to 20 %.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fem/constraints.hpp"
#include "fem/modal_solver.hpp"
#include "fem_test_helpers.hpp"

namespace flapsim::fem {
namespace {

using testing::plate_D;
using testing::shell;

/// Twelve clamped-root modes of a square plate (E, ρ of PET; ν = 0.3) of side a [m], h = a / 200.
ModalResult square_plate_modes(double a) {
  const ShellProperties s = shell(4e9, 0.3, a / 200.0, 1390.0);
  // 16 × 16: node coordinates i·a/16, so the small plate's mesh is the large one's
  // times a power of two, exactly.
  const Mesh mesh = rectangle_mesh(0.0, 0.0, a, a, 16, 16);
  const auto sys = assemble(testing::uniform_shell_model(mesh, s));
  ModalOptions opt;
  opt.num_modes = 12;
  return solve_modes(sys.stiffness, sys.mass, root_clamp(mesh, 1e-9 * a), opt);
}

TEST(ModalSolverScale, AThirtyMicrometrePlateHasTheModesOfItsLargeCopy) {
  const double k = std::ldexp(1.0, 15);
  const ModalResult large = square_plate_modes(1.0);
  const ModalResult small = square_plate_modes(1.0 / k);
  ASSERT_EQ(small.frequencies_hz.size(), 12);
  for (int m = 0; m < 12; ++m)  // exact in exact arithmetic; round-off only
    EXPECT_NEAR(small.frequencies_hz(m) / (k * large.frequencies_hz(m)), 1.0, 1e-9) << "mode " << m + 1;
  // And the small plate against Leissa (1969), NASA SP-160, Table 4.53 (ν = 0.3):
  // ω a² √(ρh/D), the first five within 1 % on this 16 × 16 mesh (as test CantileverPlate).
  const double a = 1.0 / k, h = a / 200.0;
  const double leissa[5] = {3.492, 8.525, 21.43, 27.33, 31.11};
  const double scale = a * a * std::sqrt(1390.0 * h / plate_D(shell(4e9, 0.3, h, 1390.0)));
  for (int m = 0; m < 5; ++m)
    EXPECT_NEAR(2.0 * std::numbers::pi * small.frequencies_hz(m) * scale / leissa[m], 1.0, 0.01)
        << "mode " << m + 1;
}

TEST(ModalSolverScale, AFreePlateOfThirtyMicrometresHasItsLargeCopysElasticModes) {
  // Free–free (the negative shift and the Sturm check): six rigid-body modes near 0 Hz,
  // then the elastic ones, 2^15 times the large plate's.
  const double k = std::ldexp(1.0, 15);
  auto free_modes = [](double a) {
    const ShellProperties s = shell(4e9, 0.3, a / 200.0, 1390.0);
    const Mesh mesh = rectangle_mesh(0.0, 0.0, a, a, 16, 16);
    const auto sys = assemble(testing::uniform_shell_model(mesh, s));
    ModalOptions opt;
    opt.num_modes = 10;
    return solve_modes(sys.stiffness, sys.mass, Constraints(mesh.num_dofs()), opt);
  };
  const ModalResult large = free_modes(1.0), small = free_modes(1.0 / k);
  for (int m = 0; m < 6; ++m)  // rigid: far below the first elastic mode
    EXPECT_LT(std::abs(small.frequencies_hz(m)), 1e-3 * small.frequencies_hz(6)) << "mode " << m + 1;
  for (int m = 6; m < 10; ++m)
    EXPECT_NEAR(small.frequencies_hz(m) / (k * large.frequencies_hz(m)), 1.0, 1e-9) << "mode " << m + 1;
}

TEST(ModalSolverScale, ModeShapesStayMassNormalisedAtAnyScale) {
  // φᵀ M φ = 1 (modal_solver.hpp) after the rescaled solve: the shapes are returned in
  // the unscaled pencil's units.
  for (const double a : {1.0, std::ldexp(1.0, -15)}) {
    const ShellProperties s = shell(4e9, 0.3, a / 200.0, 1390.0);
    const Mesh mesh = rectangle_mesh(0.0, 0.0, a, a, 16, 16);
    const auto sys = assemble(testing::uniform_shell_model(mesh, s));
    ModalOptions opt;
    opt.num_modes = 4;
    const ModalResult r = solve_modes(sys.stiffness, sys.mass, root_clamp(mesh, 1e-9 * a), opt);
    for (int m = 0; m < 4; ++m) {
      const Eigen::VectorXd phi = r.shapes.col(m);
      EXPECT_NEAR(phi.dot(sys.mass * phi), 1.0, 1e-9) << "a = " << a << ", mode " << m + 1;
      EXPECT_NEAR(phi.dot(sys.stiffness * phi) / r.eigenvalues(m), 1.0, 1e-6)
          << "a = " << a << ", mode " << m + 1;
    }
  }
}

}  // namespace
}  // namespace flapsim::fem
