#pragma once
// The stiff FEM plate shared by the FEM-structure tests (app.FemStructureCase.*,
// app.RunViewFields.*): 40 mm × 10 mm, 1 mm thick, E = 700 GPa, ρ = 2700 kg/m³ (a
// fictitious, very stiff material): EI = E t³ c / 12 = 5.8e-4 N m², m' = ρ t c = 0.027 kg/m,
// first bending of the cantilever f₁ = (1.875²/2π) √(EI/(m' R⁴)) = 162 Hz (Blevins 1979,
// table 8-1), 6.2 × 26.1 Hz. Meshed at 2.5 mm: nodes on the tip edge at x = 2.5, 0, −2.5, … mm.

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

}  // namespace flapsim::test
