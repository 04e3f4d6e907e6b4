// The panels' laminar skin friction (uvlm/skin_friction.hpp): Blasius' mean coefficient
// 1.328/√Re_c per side of a flat plate (Schlichting & Gersten, Boundary-Layer Theory, ch. 6).
#include "wing_cases.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "uvlm/skin_friction.hpp"

using namespace flapsim::uvlm;
using flapsim::uvlm::testing::RectangularWing;

TEST(SkinFriction, BlasiusMeanCoefficient) {
  // 1.328/√Re (Schlichting & Gersten, ch. 6): Re = 1e4 gives 0.01328.
  EXPECT_DOUBLE_EQ(blasius_mean_skin_friction(1e4), 0.01328);
  EXPECT_NEAR(blasius_mean_skin_friction(100.0), 0.1328, 1e-15);
}

TEST(SkinFriction, APlateAlongTheStreamFeelsBlasiusDragOnBothSidesAndNoLift) {
  // AR 4 plate of chord 1 m at zero incidence, U = 1 m/s, ρ = 1, ν = 1e-3: no circulation,
  // no induced velocity, the air along the chord everywhere: D = ρ U² S · 1.328/√(U c/ν)
  // = 4 · 0.041995 = 0.16798 N (two sides of ½ ρ U² S c_f), along the stream.
  RectangularWing w;
  w.alpha = 0.0;
  VortexLatticeModel m = w.model(2);
  m.skin_friction_viscosity = 1e-3;
  VortexLatticeData d(m);
  solve_steady(m, d, w.grid().nodes, w.free_stream(), w.rho, 1000.0 * w.span());
  const double expected = w.rho * w.speed * w.speed * w.area() * 1.328 / std::sqrt(w.speed * w.chord / 1e-3);
  EXPECT_NEAR(expected, 0.16798, 1e-5);
  const Eigen::Vector3d along = w.free_stream().normalized();
  EXPECT_NEAR(d.loads.total_force.dot(along), expected, 1e-12 * expected);
  EXPECT_NEAR(d.loads.total_force.z(), 0.0, 1e-12);
  EXPECT_NEAR((d.loads.skin_friction_force.rowwise().sum() - d.loads.total_force).norm(), 0.0, 1e-14);
  // Without it the inviscid plate feels nothing.
  m.skin_friction_viscosity = 0.0;
  VortexLatticeData inviscid(m);
  solve_steady(m, inviscid, w.grid().nodes, w.free_stream(), w.rho, 1000.0 * w.span());
  EXPECT_NEAR(inviscid.loads.total_force.norm(), 0.0, 1e-12);
}

TEST(SkinFriction, AnInclinedPlateFeelsItAlongTheChordOnlyAndGrowsItsDrag) {
  // At 10° the friction acts along the chord (tangential to the plate): the normal force,
  // and with it the pressure jump, are the inviscid plate's; the drag grows, the lift falls
  // by the friction's component across the stream.
  RectangularWing w;
  w.alpha = 10.0 * M_PI / 180.0;
  VortexLatticeModel m = w.model(2);
  VortexLatticeData inviscid(m);
  solve_steady(m, inviscid, w.grid().nodes, w.free_stream(), w.rho, 1000.0 * w.span());
  m.skin_friction_viscosity = 1e-3;
  VortexLatticeData viscous(m);
  solve_steady(m, viscous, w.grid().nodes, w.free_stream(), w.rho, 1000.0 * w.span());
  const Eigen::Vector3d n = Eigen::Vector3d::UnitZ();  // the plate's normal (in z = 0)
  EXPECT_NEAR(viscous.loads.total_force.dot(n), inviscid.loads.total_force.dot(n),
              1e-12 * std::abs(inviscid.loads.total_force.dot(n)));
  EXPECT_NEAR((viscous.loads.pressure_jump - inviscid.loads.pressure_jump).norm(), 0.0,
              1e-12 * inviscid.loads.pressure_jump.norm());
  const Eigen::Vector3d along = w.free_stream().normalized();
  EXPECT_GT(viscous.loads.total_force.dot(along), inviscid.loads.total_force.dot(along) + 0.1);
  EXPECT_LT(viscous.loads.total_force.dot(w.lift_direction()),
            inviscid.loads.total_force.dot(w.lift_direction()));
}
