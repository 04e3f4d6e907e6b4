#pragma once
/// \file angle_units.hpp
/// \brief Degrees and radians. Inputs and outputs speak degrees (case files, history.csv,
/// `flapsim check`); everything inside flapsim computes in radians.
///   angle_rad = angle_deg * kDegToRad,   angle_deg = angle_rad * kRadToDeg

namespace flapsim {

// π spelled out (the same double as C++20's std::numbers::pi) so that C++17 code, the
// Simbody test, can include this header too.
inline constexpr double kDegToRad = 3.141592653589793238462643383279502884 / 180.0;  ///< [rad/deg]
inline constexpr double kRadToDeg = 180.0 / 3.141592653589793238462643383279502884;  ///< [deg/rad]

}  // namespace flapsim
