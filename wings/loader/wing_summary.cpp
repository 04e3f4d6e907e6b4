#include "wings/loader/wing_summary.hpp"

#include <cstdio>
#include <string>
#include <utility>

#include "wings/loader/planform_geometry.hpp"
#include "wings/loader/wing_mass_properties.hpp"

namespace flapsim::wings {

namespace {

template <typename... Args>
std::string line(const char* format, Args... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, format, args...);
  return std::string(buf) + "\n";
}

}  // namespace

std::string describe_wing(const Wing& wing) {
  const PlanformProperties p = planform_properties(wing.outline);
  const WingMassEstimate m = estimate_wing_mass(wing);
  std::string s = "wing '" + wing.name + "' (" + wing.source_file + ")\n";
  s += line("  span R                 %10.3f mm", p.span * 1e3);
  s += line("  area S                 %10.3f mm^2", p.area * 1e6);
  s += line("  mean chord S/R         %10.3f mm", p.mean_chord * 1e3);
  s += line("  aspect ratio R^2/S     %10.4f", p.aspect_ratio);
  s += line("  r2/R                   %10.4f", p.r2);
  s += line("  root y (outline min)   %10.3f mm", p.root_y * 1e3);
  s += line("  outline points         %10zu", wing.outline.size());
  if (!wing.drawing.empty()) s += "  drawn                  " + wing.drawing + "\n";
  s += line("  veins                  %10zu", wing.veins.size());
  // In um below 0.1 mm (a fruit fly's 0.5 um membrane read "0.0005 mm", one digit).
  const bool thin = wing.membrane.thickness < 1e-4;
  s += line("  membrane thickness     %10.4f %s (E %.3g GPa, nu %.3g, rho %.4g kg/m^3)",
            wing.membrane.thickness * (thin ? 1e6 : 1e3), thin ? "um" : "mm",
            wing.membrane.material.youngs_modulus * 1e-9, wing.membrane.material.poisson_ratio,
            wing.membrane.material.density);
  // In mg, or ug / ng for a wing below 0.1 mg (a 1 mm wing of a 2 um film is a fraction of a
  // microgram: "0.000 mg" hid it), g from 10 g and kg from 10 kg (a wing file in mm written as
  // metres weighs tonnes: "2700000000000.000 mg").
  const double total = m.total();
  const auto [mass_unit, per_kg] = total >= 10.0    ? std::pair{"kg", 1.0}
                                   : total >= 1e-2  ? std::pair{"g", 1e3}
                                   : total >= 1e-7  ? std::pair{"mg", 1e6}
                                   : total >= 1e-10 ? std::pair{"ug", 1e9}
                                                    : std::pair{"ng", 1e12};
  s += line("  estimated mass         %10.3f %s (membrane %.3f, non-structural %.3f, veins %.3f)", total * per_kg,
            mass_unit, m.membrane * per_kg, m.nonstructural * per_kg, m.veins * per_kg);
  s += line("  root clamp             y <= %.3f mm", wing.clamp_y * 1e3);
  s += line("  mesh size              %10.3f mm (veins %.3f mm)", wing.mesh.element_size * 1e3,
            wing.mesh.vein_element_size * 1e3);
  return s;
}

}  // namespace flapsim::wings
