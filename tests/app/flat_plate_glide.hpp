#pragma once
/// \file
/// \brief The case text of wings/flat_plate.toml (AR 4, chord 10 mm) held at a fixed
/// incidence in U∞ = 5 m/s along −x, without flapping: a rigid wing, 4 × 8 panels, a flat
/// wake, no ParaView output (tests app.FreeStreamCase.*, app.DivergedForce.*).

#include <cstdio>
#include <string>

namespace flapsim::test {

/// `numerics`: more lines for [numerics] (each ending in a newline).
inline std::string flat_plate_glide_case(const std::string& name, double frequency_hz, double rotation_deg,
                                         int steps_per_cycle, int cycles, const std::string& numerics = "") {
  char kinematics[128];
  std::snprintf(kinematics, sizeof kinematics, "[kinematics]\nfrequency_hz = %.1f\nsweep = 0.0\nrotation = %.1f\n",
                frequency_hz, rotation_deg);
  return "name = \"" + name + "\"\nwing = \"" + std::string(FLAPSIM_SOURCE_DIR) + "/wings/flat_plate.toml\"\n" +
         kinematics + "[air]\nfreestream = [-5.0, 0.0, 0.0]\n[structure]\nkind = \"rigid\"\n[numerics]\nsteps_per_cycle = " +
         std::to_string(steps_per_cycle) + "\ncycles = " + std::to_string(cycles) +
         "\nchordwise_panels = 4\nspanwise_panels = 8\nfree_wake = false\n" + numerics + "[output]\nvtk_every = 0\n";
}

}  // namespace flapsim::test
