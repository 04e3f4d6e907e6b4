// Mode names from shapes, on a cantilever plate strip whose mode order beam
// theory predicts: 40 × 10 mm, 0.2 mm PET (E = 4 GPa, ν = 0.38, ρ = 1390).
// Euler–Bernoulli: f₁ = 1.8751²/(2π L²) √(EI/ρA) ≈ 35 Hz (37 Hz with the plate D),
// f₂ = (4.6941/1.8751)² f₁ ≈ 232 Hz; St Venant torsion of a thin strip
// (GJ = G b h³/3, ρI_p ≈ ρ b³h/12): f_t = (1/4L)(2h/b)√(G/ρ) ≈ 255 Hz.
// So the order is bending, bending, torsion, and the third-lowest
// out-of-plane mode twists the section about its mid-chord.

#include <gtest/gtest.h>

#include "fem/constraints.hpp"
#include "fem/modal_solver.hpp"
#include "fem/mode_classification.hpp"
#include "fem_test_helpers.hpp"

namespace flapsim::fem {
namespace {

TEST(ModeClassification, PlateStripBendingBendingTorsion) {
  const Mesh mesh = rectangle_mesh(-5e-3, 0.0, 10e-3, 40e-3, 6, 24);
  const auto sys = assemble(testing::uniform_shell_model(mesh, testing::shell(4e9, 0.38, 0.2e-3, 1390.0)));
  ModalOptions opt;
  opt.num_modes = 3;
  const ModalResult r = solve_modes(sys.stiffness, sys.mass, root_clamp(mesh, 0.0), opt);
  const auto kinds = classify_modes(mesh, sys, r.shapes, r.frequencies_hz, 0.0);
  std::printf("  strip modes: %.1f Hz %s, %.1f Hz %s, %.1f Hz %s\n", r.frequencies_hz(0), to_string(kinds[0]).c_str(),
              r.frequencies_hz(1), to_string(kinds[1]).c_str(), r.frequencies_hz(2), to_string(kinds[2]).c_str());
  EXPECT_EQ(kinds[0], ModeKind::Bending);
  EXPECT_EQ(kinds[1], ModeKind::Bending);
  EXPECT_EQ(kinds[2], ModeKind::Torsion);
  // The first bending mode has no nodal line along the span, the second one.
  const auto w = nodal_masses(mesh, sys);
  EXPECT_EQ(measure_mode_shape(mesh, w, r.shapes.col(0)).spanwise_sign_changes, 0);
  EXPECT_EQ(measure_mode_shape(mesh, w, r.shapes.col(1)).spanwise_sign_changes, 1);
  // Node masses add up to the total mass.
  double sum = 0.0;
  for (double m : w) sum += m;
  EXPECT_NEAR(sum / sys.total_mass, 1.0, 1e-12);
}

}  // namespace
}  // namespace flapsim::fem
