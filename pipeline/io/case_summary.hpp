#pragma once
/// \file case_summary.hpp
/// \brief A short human-readable summary of a case (what `flapsim check` prints):
/// the wing-base kinematics at a few phases, air, structure, numerics, outputs.

#include <optional>
#include <string>

#include "mbd/wing_kinematics.hpp"
#include "pipeline/io/case_model.hpp"

namespace flapsim::io {

/// Geometric angle of attack [rad] in the stroke plane, deviation ignored: α on the
/// downstroke (φ̇ < 0), π − α on the upstroke (φ̇ > 0); nullopt at stroke reversal
/// (|φ̇| below 1e-9 rad/s plus a millionth of 2π f, the rate of a 1 rad sweep at the
/// wingbeat's frequency f [Hz]: a measured wingbeat's spline stops at its reversal to
/// round-off, −2.4e-9 rad/s at 26.1 Hz), where the wing does not translate.
std::optional<double> geometric_angle_of_attack(const mbd::WingKinematics::Angles& angles,
                                                double frequency_hz = 0.0);

/// The angle of attack of the wing's span axis at a radius r [m] from the pivot in the air
/// that moves at `freestream` [m/s] (ground frame), at time t [s]: the air's velocity
/// relative to the point, w = U∞ − (v_pivot + ω × R_GW (0, r, 0)), its part normal to the
/// span, and the angle [rad] between the leading edge's direction c = R_GW x̂ and the way
/// the point moves through the air, −w: |α| = atan2(|w·n|, −w·c) in [0, π], n = R_GW ẑ;
/// negative where the air's push on the wing, along (w·n) n, points down (the air meets
/// the upper face: a forward-flying wing's upstroke). With U∞ = 0 and a fixed pivot in a
/// horizontal stroke plane it is geometric_angle_of_attack wherever the deviation is constant;
/// nullopt where the air's relative speed normal to the span is below 1e-9 of |U∞| + 2π f r
/// (stroke reversal in hover).
struct AngleInStream {
  double angle = 0.0;  ///< [rad]
  double speed = 0.0;  ///< |w| normal to the span [m/s]
};
std::optional<AngleInStream> angle_of_attack_in_stream(const mbd::WingKinematics& kinematics,
                                                       const Eigen::Vector3d& freestream, double radius,
                                                       double t);

/// Multi-line text; the kinematics table lists phases s = f·t of 0, 0.25, 0.5, 0.75. With
/// `stream_radius` (r2·R [m]) and a case in air with a free stream or a translating pivot,
/// the table adds the angle of attack in the stream at that radius (angle_of_attack_in_stream).
std::string describe_case(const Case& c, std::optional<double> stream_radius = std::nullopt);

}  // namespace flapsim::io
