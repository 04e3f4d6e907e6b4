// Displacement-controlled statics (fem/displacement_control.hpp): the reaction
// at a prescribed tip deflection of a cantilever is the beam-theory load, and
// bad input is refused.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "fem/displacement_control.hpp"
#include "fem/section_properties.hpp"
#include "fem/structured_mesh.hpp"
#include "fem_test_helpers.hpp"

namespace flapsim::fem {
namespace {

// A solid steel rod, L = 1 m, 8 frame elements, clamped at x = 0.
StructuralModel prescribed_tip_rod() {
  wings::Section sec;
  sec.outer_diameter = 0.01;
  sec.wall = 0.005;  // solid
  FrameProperties f;
  f.youngs_modulus = 210e9;
  f.shear_modulus = 210e9 / 2.6;
  f.density = 7800.0;
  f.section = section_properties(sec);
  return testing::uniform_beam_model(line_mesh({0, 0, 0}, {1, 0, 0}, 8), f);
}

TEST(DisplacementControl, SmallTipDeflectionNeedsTheBeamTheoryLoad) {
  // Tip deflection δ = 1e-6 L: the load is 3 E I δ / L³ (Gere & Timoshenko
  // 1997; the Hermite frame element is exact for an end load), within 1e-5
  // (the geometric nonlinearity is of order (δ/L)²).
  const StructuralModel sm = prescribed_tip_rod();
  const CorotationalModel model = make_corotational_model(sm);
  Constraints clamp(model.num_dofs());
  clamp.clamp_nodes({0});
  CorotationalState state = reference_state(model);
  const double delta = 1e-6, EI = sm.frame[0].youngs_modulus * sm.frame[0].section.I_y;
  const DisplacementControlResult r = solve_displacement_controlled(model, clamp, dof_index(8, UZ), delta, state);
  ASSERT_TRUE(r.converged) << r.failure;
  EXPECT_NEAR(r.reaction / (3.0 * EI * delta), 1.0, 1e-5);
  EXPECT_DOUBLE_EQ(state.position[8].z(), delta);
  // Converged on the size of the Newton correction: the residual's round-off
  // floor, k_axial ε L / (3EIδ/L³) ~ 1e-4, lies above the 1e-8 asked.
  std::printf("  reaction %.6e N (beam theory %.6e N), %d iterations, relative residual %.1e\n", r.reaction,
              3.0 * EI * delta, r.iterations, r.residual);
}

TEST(DisplacementControl, RefusesRotationsAndFixedDofs) {
  const CorotationalModel model = make_corotational_model(prescribed_tip_rod());
  Constraints clamp(model.num_dofs());
  clamp.clamp_nodes({0});
  CorotationalState state = reference_state(model);
  EXPECT_THROW(solve_displacement_controlled(model, clamp, dof_index(8, RY), 0.1, state), std::invalid_argument);
  EXPECT_THROW(solve_displacement_controlled(model, clamp, dof_index(0, UZ), 0.1, state), std::invalid_argument);
}

}  // namespace
}  // namespace flapsim::fem
