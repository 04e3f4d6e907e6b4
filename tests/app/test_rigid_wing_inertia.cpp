// The rigid wing's body (make_rigid_chain) carries the wing's own mass distribution: the
// inertial part of the drive moment and power depends on it. Before: the mass sat at the
// outline's centroid with the inertia of a rectangle of span R and chord c̄ = S/R, so a
// triangular plate's I_xx was m R²/12 instead of m R²/18 (its peak drive moment +17 %,
// its drive power +17.5 % in a hover), and veins added mass but no moment.
#include <gtest/gtest.h>

#include <cmath>

#include "pipeline/app/fsi_setup.hpp"
#include "wings/loader/wing_model.hpp"

namespace w = flapsim::wings;

namespace {

// Right-triangle plate: root chord c along −x at y = 0, leading edge x = 0 from the pivot
// to the tip (0, R); membrane 100 µm of density 1000 kg/m³.
w::Wing triangle_wing(double chord, double span) {
  w::Wing wing;
  wing.name = "triangle";
  wing.outline = {{0.0, 0.0}, {-chord, 0.0}, {0.0, span}};  // counter-clockwise
  wing.span = span;
  wing.membrane.thickness = 100e-6;
  wing.membrane.material.density = 1000.0;
  return wing;
}

}  // namespace

TEST(RigidWingInertia, ATriangularPlateHasTheTrianglesMoments) {
  const double c = 0.01, R = 0.04;
  const flapsim::mbd::ChainModel chain = flapsim::app::make_rigid_chain(triangle_wing(c, R));
  ASSERT_EQ(chain.bodies.size(), 1u);
  const auto& body = chain.bodies[0];
  // m = ρ h S = 1000 · 1e-4 · (c R / 2).
  const double m = 1000.0 * 100e-6 * c * R / 2.0;
  EXPECT_NEAR(body.mass, m, 1e-12 * m);
  // Centroid at the mean of the vertices (−c/3, R/3).
  EXPECT_NEAR(body.center_of_mass.x(), -c / 3.0, 1e-12 * c);
  EXPECT_NEAR(body.center_of_mass.y(), R / 3.0, 1e-12 * R);
  // Right triangle with legs a, b about its centroid (Gere & Goodno, Mechanics of Materials,
  // Appendix E): ∫ y'² dA = A b²/18, ∫ x'² dA = A a²/18, ∫ x'y' dA = −A a b/36 for legs along
  // +x and +y; the leg along −x flips the product's sign: I_xy = −∫ x'y' dm = −m c R/36.
  EXPECT_NEAR(body.inertia(0, 0), m * R * R / 18.0, 1e-9 * m * R * R);
  EXPECT_NEAR(body.inertia(1, 1), m * c * c / 18.0, 1e-9 * m * R * R);
  EXPECT_NEAR(body.inertia(2, 2), m * (R * R + c * c) / 18.0, 1e-9 * m * R * R);
  EXPECT_NEAR(body.inertia(0, 1), -m * c * R / 36.0, 1e-9 * m * R * R);
  EXPECT_NEAR(body.inertia(1, 0), body.inertia(0, 1), 1e-20);
}

TEST(RigidWingInertia, AVeinAddsItsLineMassAndItsMoments) {
  // The triangle plus a solid rod of 0.2 mm diameter along its leading edge (x = 0,
  // 0 ≤ y ≤ R), density 1200 kg/m³: a line mass m_v = ρ π D²/4 R with ∫ y² dm = m_v R²/3.
  const double c = 0.01, R = 0.04, D = 0.2e-3;
  w::Wing wing = triangle_wing(c, R);
  w::Vein rod;
  rod.name = "costa";
  rod.points = {{0.0, 0.0}, {0.0, R / 2.0}, {0.0, R}};
  rod.root_section.outer_diameter = rod.tip_section.outer_diameter = D;
  rod.root_section.wall = rod.tip_section.wall = D;  // solid
  rod.material.density = 1200.0;
  wing.veins = {rod};
  const flapsim::mbd::ChainModel chain = flapsim::app::make_rigid_chain(wing);
  const auto& body = chain.bodies[0];
  const double mp = 1000.0 * 100e-6 * c * R / 2.0;
  const double mv = 1200.0 * M_PI * D * D / 4.0 * R;
  const double m = mp + mv;
  EXPECT_NEAR(body.mass, m, 1e-12 * m);
  // Centre of mass: plate at (−c/3, R/3), rod at (0, R/2).
  const double xc = mp * (-c / 3.0) / m, yc = (mp * R / 3.0 + mv * R / 2.0) / m;
  EXPECT_NEAR(body.center_of_mass.x(), xc, 1e-12 * c);
  EXPECT_NEAR(body.center_of_mass.y(), yc, 1e-12 * R);
  // About the origin: plate ∫ y² dm = mp R²/6, ∫ x² dm = mp c²/6, ∫ x y dm = −mp c R/12
  // (triangle moments about its right-angle vertex); rod ∫ y² dm = mv R²/3, no x moments.
  const double yy = mp * R * R / 6.0 + mv * R * R / 3.0, xx = mp * c * c / 6.0;
  const double xy = -mp * c * R / 12.0;
  EXPECT_NEAR(body.inertia(0, 0), yy - m * yc * yc, 1e-9 * m * R * R);
  EXPECT_NEAR(body.inertia(1, 1), xx - m * xc * xc, 1e-9 * m * R * R);
  EXPECT_NEAR(body.inertia(0, 1), -(xy - m * xc * yc), 1e-9 * m * R * R);
}
