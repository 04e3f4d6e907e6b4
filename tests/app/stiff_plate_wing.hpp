#pragma once
// The stiff FEM plate shared by the FEM-structure tests (app.FemStructureCase.*,
// app.RunViewFields.*): 40 mm × 10 mm, 1 mm thick, E = 700 GPa, ρ = 2700 kg/m³ (a
// fictitious, very stiff material): EI = E t³ c / 12 = 5.8e-4 N m², m' = ρ t c = 0.027 kg/m,
// first bending of the cantilever f₁ = (1.875²/2π) √(EI/(m' R⁴)) = 162 Hz (Blevins 1979,
// table 8-1), 6.2 × 26.1 Hz. Meshed at 2.5 mm: nodes on the tip edge at x = 2.5, 0, −2.5, … mm.

#include <string>

namespace flapsim::test {

inline constexpr const char* kStiffPlateWing = R"(name = "stiff_plate"
length_unit = "mm"
[planform]
outline = [[2.5, 0.0], [2.5, 40.0], [-7.5, 40.0], [-7.5, 0.0]]
clamp_y = 0.0
[materials.stiff]
youngs_modulus = 7.0e11
poisson_ratio = 0.3
density = 2700.0
[membrane]
thickness = 1.0
material = "stiff"
[mesh]
element_size = 2.5
vein_element_size = 2.5
)";

// A case flapping the plate as wing.toml beside it (one cycle of 8 steps, kind = "fem", no
// ParaView series); `structure_keys` follow kind = "fem" on line 9, so a first one is on
// line 10 (the sweep's and optimize's keys-that-change-nothing tests).
inline std::string stiff_fem_plate_case(const std::string& structure_keys) {
  return "name = \"stiff_fem\"\nwing = \"wing.toml\"\n"
         "[kinematics]\nfrequency_hz = 26.1\nrotation_phase = -0.1\n"
         "sweep = { mean_deg = 10.0, cos_deg = [20.0] }\nrotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"
         "[structure]\nkind = \"fem\"\n" +
         structure_keys +
         "[numerics]\nsteps_per_cycle = 8\ncycles = 1\nchordwise_panels = 3\nspanwise_panels = 4\n"
         "core_radius = 0.2\nrho_infinity = 0.0\n[output]\nvtk_every = 0\n";
}

}  // namespace flapsim::test
