// The angle of attack the air meets in a free stream (io::angle_of_attack_in_stream), and
// the column `flapsim check` adds for it (docs/case_file.md, "What flapsim check prints").
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "inline_case.hpp"
#include "mbd/angle_units.hpp"
#include "pipeline/io/case_file.hpp"
#include "pipeline/io/case_summary.hpp"

namespace p = flapsim::io;
using flapsim::kDegToRad;
using flapsim::kRadToDeg;

namespace {

/// A wing flapped up and down in a vertical stroke plane (β = 90°: the stroke plane's normal
/// along +x_G, the direction of flight), chord along +x_G (α = 90°), sweep 30° cos 2π·4t.
const std::string kFlappingInForwardFlight =
    "wing = \"valid_tiny_wing.toml\"\n"
    "[kinematics]\n"
    "frequency_hz = 4.0\n"
    "stroke_plane_deg = 90.0\n"
    "sweep = { cos_deg = [30.0] }\n"
    "rotation = 90.0\n"
    "[air]\n"
    "freestream = [-6.0, 0.0, 0.0]\n"
    "[structure]\n"
    "kind = \"rigid\"\n";

}  // namespace

TEST(AngleInStream, WithoutAStreamItIsTheGeometricAngleOfAttack) {
  // docs/kinematics.md: α on the downstroke, 180° − α on the upstroke, for any stroke plane
  // and a constant deviation (cases/hover.toml: eq. 8 of the rotation-phase paper).
  p::Case c = p::load_case_file(std::string(FLAPSIM_SOURCE_DIR) + "/cases/hover.toml");
  for (double deviation_deg : {0.0, 10.0}) {
    c.kinematics.deviation = flapsim::mbd::PeriodicSignal::harmonic(deviation_deg * kDegToRad, {}, {});
    for (double s : {0.1, 0.25, 0.4, 0.6, 0.75, 0.9}) {
      const double t = s / c.kinematics.frequency;
      const auto w = p::angle_of_attack_in_stream(c.kinematics, Eigen::Vector3d::Zero(), 0.03, t);
      ASSERT_TRUE(w);
      EXPECT_NEAR(w->angle, *p::geometric_angle_of_attack(c.kinematics.angles(t)), 1e-12) << s;
      // The point's speed: |φ̇| r cos θ, the circle it sweeps (φ̇ = f dφ/ds, φ = 10° + 50° cos 2πs).
      const double rate = c.kinematics.frequency * 50.0 * kDegToRad * 2.0 * std::numbers::pi *
                          std::abs(std::sin(2.0 * std::numbers::pi * s));
      EXPECT_NEAR(w->speed, rate * 0.03 * std::cos(deviation_deg * kDegToRad), 1e-12) << s;
    }
  }
  // At stroke reversal the point stands still: no angle.
  EXPECT_FALSE(p::angle_of_attack_in_stream(c.kinematics, Eigen::Vector3d::Zero(), 0.03, 0.0));
}

TEST(AngleInStream, AFixedWingMeetsTheStreamAtItsPitch) {
  // No flapping, the chord pitched nose up by α about the span (α = 5°: chord (cos α, 0, sin α)
  // at φ = 0): in a stream along −x the angle of attack is α and the speed the stream's.
  const p::Case c = case_from_text(
      "wing = \"valid_tiny_wing.toml\"\n[kinematics]\nfrequency_hz = 10.0\nsweep = 0.0\n"
      "rotation = 5.0\n[air]\nfreestream = [-4.0, 0.0, 0.0]\n[structure]\nkind = \"rigid\"\n");
  for (double t : {0.0, 0.013, 0.07}) {
    const auto w = p::angle_of_attack_in_stream(c.kinematics, c.air.freestream, 0.02, t);
    ASSERT_TRUE(w);
    EXPECT_NEAR(w->angle * kRadToDeg, 5.0, 1e-12);
    EXPECT_NEAR(w->speed, 4.0, 1e-12);
  }
}

TEST(AngleInStream, AWingFlappingDownInForwardFlightMeetsTheAirFromBelow) {
  // Mid-downstroke (s = 0.25, φ = 0): the point at r moves down at |φ̇| r = 2π f Φ r and the
  // air comes at it from ahead at U = 6 m/s: angle atan(2π f Φ r / U), speed √(U² + (2π f Φ r)²).
  const p::Case c = case_from_text(kFlappingInForwardFlight);
  const double r = 0.2, down = 2.0 * std::numbers::pi * 4.0 * 30.0 * kDegToRad * r;  // 2.632 m/s
  const auto mid_down = p::angle_of_attack_in_stream(c.kinematics, c.air.freestream, r, 0.25 / 4.0);
  ASSERT_TRUE(mid_down);
  EXPECT_NEAR(mid_down->angle, std::atan(down / 6.0), 1e-12);  // 23.68°
  EXPECT_NEAR(mid_down->speed, std::hypot(6.0, down), 1e-12);
  // Mid-upstroke: the air now from above, pushing the wing down: the same angle, negative.
  const auto mid_up = p::angle_of_attack_in_stream(c.kinematics, c.air.freestream, r, 0.75 / 4.0);
  ASSERT_TRUE(mid_up);
  EXPECT_NEAR(mid_up->angle, -std::atan(down / 6.0), 1e-12);
  // Pitched nose up by 10° (rotation 100°): 10° + 28.68° down, 28.68° − 10° up (negative).
  p::Case pitched = c;
  pitched.kinematics.rotation = flapsim::mbd::PeriodicSignal::harmonic(100.0 * kDegToRad, {}, {});
  const double inflow = std::atan(down / 6.0) * kRadToDeg;
  EXPECT_NEAR(
      p::angle_of_attack_in_stream(pitched.kinematics, c.air.freestream, r, 0.25 / 4.0)->angle * kRadToDeg,
      10.0 + inflow, 1e-10);
  EXPECT_NEAR(
      p::angle_of_attack_in_stream(pitched.kinematics, c.air.freestream, r, 0.75 / 4.0)->angle * kRadToDeg,
      -(inflow - 10.0), 1e-10);
  EXPECT_NEAR(p::angle_of_attack_in_stream(pitched.kinematics, c.air.freestream, r, 0.0)->angle * kRadToDeg,
              10.0, 1e-10);
  // At the stroke's top (s = 0, φ = 30°) the wing stands still and the chord lies along the
  // stream: zero angle at the stream's speed, where the geometric column says "reversal".
  const auto top = p::angle_of_attack_in_stream(c.kinematics, c.air.freestream, r, 0.0);
  ASSERT_TRUE(top);
  EXPECT_NEAR(top->angle, 0.0, 1e-12);
  EXPECT_NEAR(top->speed, 6.0, 1e-12);
}

TEST(AngleInStream, CheckAddsTheColumnOnlyInAStream) {
  const std::string forward = p::describe_case(case_from_text(kFlappingInForwardFlight), 0.2);
  EXPECT_NE(forward.find("in stream"), std::string::npos) << forward;
  EXPECT_NE(forward.find("23.68"), std::string::npos) << forward;  // the mid-downstroke above
  EXPECT_NE(forward.find("r2 = 200 mm"), std::string::npos) << forward;
  // Hover: the geometric angle is the angle the air meets; no column. Nor without a radius.
  const std::string hover =
      p::describe_case(p::load_case_file(std::string(FLAPSIM_SOURCE_DIR) + "/cases/hover.toml"), 0.03);
  EXPECT_EQ(hover.find("in stream"), std::string::npos) << hover;
  EXPECT_EQ(p::describe_case(case_from_text(kFlappingInForwardFlight)).find("in stream"), std::string::npos);
}
