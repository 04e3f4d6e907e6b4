#pragma once
/// \file kinematics_samples.hpp
/// \brief The wing base's angles, rates and accelerations over one wingbeat at the run's steps,
/// as a CSV table (`flapsim check CASE --kinematics FILE`): what a run flies, to plot beside a
/// measured wingbeat (docs/case_file.md, "Measured kinematics").

#include <filesystem>
#include <string>
#include <vector>

#include "mbd/wing_kinematics.hpp"

namespace flapsim::io {

/// The table's columns: phase f t, t [s], then φ, θ, α [deg], their rates [deg/s] and their
/// accelerations [deg/s²] (the rotation phase δψ applied, as the run's angles).
std::vector<std::string> kinematics_samples_header();

/// \p steps_per_cycle + 1 rows, t = k / (f · steps_per_cycle), k = 0 … steps_per_cycle (the last
/// row the next wingbeat's start), written atomically.
/// \throws OutputError when the file cannot be written (nothing is left under its name)
void write_kinematics_samples(const std::filesystem::path& path, const mbd::WingKinematics& kinematics,
                              int steps_per_cycle);

}  // namespace flapsim::io
