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
/// (|φ̇| below 1e-9 rad/s), where the wing does not translate.
std::optional<double> geometric_angle_of_attack(const mbd::WingKinematics::Angles& angles);

/// Multi-line text; the kinematics table lists phases s = f·t of 0, 0.25, 0.5, 0.75.
std::string describe_case(const Case& c);

}  // namespace flapsim::io
