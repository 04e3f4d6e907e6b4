#pragma once
// Test helper of the app tests: a film wing and a case that flaps it rigidly for one short
// wingbeat (25 Hz, ±60° sweep, rotation 90° ∓ 45°, 20 steps), for comparing two ways of
// giving the same wing (a drawing against points, --wing against the case's 'wing').

#include <filesystem>
#include <fstream>
#include <string>

namespace flapsim::test {

/// The [materials] and [membrane] of a 10 µm film (E 4 GPa, ρ 1400 kg/m³).
inline constexpr const char* kFilmWingMaterials =
    "[materials.film]\nyoungs_modulus = 4.0e9\npoisson_ratio = 0.3\ndensity = 1400.0\n"
    "[membrane]\nthickness = 0.01\nmaterial = \"film\"\n";

/// A wing file (mm) of that film with \p planform_keys (e.g. "outline = [[0, 0], ...]").
inline void write_film_wing(const std::filesystem::path& file, const std::string& planform_keys) {
  std::ofstream(file) << "length_unit = \"mm\"\n[planform]\n"
                      << planform_keys << "\nclamp_y = 0.5\n"
                      << kFilmWingMaterials;
}

/// A case named \p name flapping \p wing (a path from the case's folder) rigidly for one wingbeat.
inline void write_rigid_wingbeat_case(const std::filesystem::path& file, const std::string& name,
                                      const std::string& wing) {
  std::ofstream(file) << "name = \"" << name << "\"\nwing = \"" << wing
                      << "\"\n[kinematics]\nfrequency_hz = 25\nsweep = { cos_deg = [60.0] }\n"
                         "rotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n[structure]\nkind = \"rigid\"\n"
                         "[numerics]\nsteps_per_cycle = 20\ncycles = 1\n";
}

}  // namespace flapsim::test
