#pragma once
// A user's swept wing shared by the large-motion and step-halving tests: 5 outline points
// swept back about 30°, 15 µm PET, a solid carbon rod 0.8 → 0.4 mm along the leading edge
// (docs/reduction.md, "Measured limitation"), and its 20 Hz case (sweep ±55°, rotation
// 90° ∓ 45°, 6 bodies reduced in process) in vacuum.

#include <fstream>
#include <string>

#include "common/scratch_dir.hpp"

namespace flapsim::test {

inline constexpr const char* kSweptWing =
    "length_unit = \"mm\"\n[planform]\noutline = [[3, 0], [-8, 30], [-14, 32], [-16, 28], [-8, 0]]\n"
    "clamp_y = 0.5\n[materials.film]\nyoungs_modulus = 4.0e9\npoisson_ratio = 0.38\ndensity = 1390.0\n"
    "[materials.carbon]\nyoungs_modulus = 1.2e11\npoisson_ratio = 0.3\ndensity = 1600.0\n"
    "[membrane]\nthickness = 0.015\nmaterial = \"film\"\n[[veins]]\nname = \"spar\"\n"
    "shape = \"solid_circle\"\npoints = [[2.5, 0.2], [-8.5, 29.5]]\ndiameter = [0.8, 0.4]\nmaterial = \"carbon\"\n";

/// DIR/swept.toml and DIR/case.toml: the wing above flapped at 20 Hz in vacuum, 40 steps per
/// cycle, `cycles` cycles.
inline void write_swept_vacuum_case(const ScratchDir& dir, int cycles) {
  std::ofstream(dir / "swept.toml") << kSweptWing;
  std::ofstream(dir / "case.toml")
      << "air = \"none\"\nwing = \"swept.toml\"\n[kinematics]\nfrequency_hz = 20\n"
         "sweep = { mean_deg = 0.0, cos_deg = [55.0] }\nrotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"
         "[structure]\nkind = \"flexible\"\nbodies = 6\n[numerics]\nsteps_per_cycle = 40\ncycles = "
      << cycles << "\n[output]\nvtk_every = 0\n";
}

}  // namespace flapsim::test
