#include "pipeline/app/film_wrinkle_warning.hpp"

#include "fem/nonlinear_dynamics.hpp"
#include "wings/loader/planform_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

namespace flapsim::app {

double mesh_wrinkle_strain(double thickness, double poisson_ratio, double wavelength) {
  const double tk = 2.0 * std::numbers::pi * thickness / wavelength;
  return tk * tk / (12.0 * (1.0 - poisson_ratio * poisson_ratio));
}

std::optional<MembraneWrinkle> typical_membrane_wrinkle(const fem::StructuralModel& model) {
  const fem::Mesh& mesh = model.mesh;
  std::vector<MembraneWrinkle> elements;
  elements.reserve(mesh.triangles.size());
  for (std::size_t e = 0; e < mesh.triangles.size() && e < model.shell.size(); ++e) {
    const double size = mesh.triangle_mean_edge(e);
    const fem::ShellProperties& p = model.shell[e];
    if (!(size > 0.0) || !(p.thickness > 0.0)) continue;
    elements.push_back({mesh_wrinkle_strain(p.thickness, p.poisson_ratio, size), p.thickness, size});
  }
  if (elements.empty()) return std::nullopt;
  // The median in the order of the mesh-resolution warning's median size (the strain falls as
  // the size grows: largest strain first is smallest size first), so that on a membrane of one
  // thickness both warnings of a check name the same element size: they said 10.8 and 14.1 mm
  // of one six-triangle mesh (fem_mesh_resolution_warning.cpp).
  auto median = elements.begin() + static_cast<std::ptrdiff_t>(elements.size() / 2);
  std::nth_element(elements.begin(), median, elements.end(),
                   [](const MembraneWrinkle& a, const MembraneWrinkle& b) { return a.strain > b.strain; });
  return *median;
}

std::string film_wrinkle_warning(const io::Case& c, const FsiSetup& setup) {
  if (!setup.fem_structure) return "";
  const std::optional<MembraneWrinkle> median = typical_membrane_wrinkle(setup.fem_structure->structural);
  const double mean_chord =
      setup.wing ? wings::planform_properties(setup.wing->outline).mean_chord : 0.0;  // [m]
  if (!is_thin_film(median, mean_chord)) return "";
  char why[200];
  if (median->strain < kFilmWrinkleStrain)
    std::snprintf(why, sizeof why,
                  "buckles into wrinkles of the mesh's own wavelength under %.2g %% of compression",
                  100.0 * median->strain);
  else
    std::snprintf(why, sizeof why,
                  "is %.2g of the wing's mean chord thin (a film below %.2g, whatever its mesh)",
                  median->thickness / mean_chord, kFilmThicknessOverChord);
  char text[1400];
  std::snprintf(
      text, sizeof text,
      "the FEM's membrane (%.3g um on elements of %.3g mm) %s, a thin film: where the flapping compresses "
      "it (a bending rod: ~0.06 %%) the FEM splits its steps (docs/fsi.md, \"Step halving of the FEM\"), and "
      "such runs "
      "took 8x (the 75 mm film wing), 16x (the MAV film wing), 70x (a 55 mm swept 15 um film), some "
      "500x (a 13 mm wing of a 4 um membrane at 150 Hz) and over 1000x (a 2.5 mm wing of a 0.5 um "
      "cuticle at 200 Hz: 2 steps in 31 s, the third unsolved after 90 s more, against 1.5 s for 20) "
      "the time estimated here, and up to "
      "%.0f MB more memory for a Newton matrix kept for each piece (docs/fsi.md, \"Film wings\")",
      median->thickness * 1e6, median->size * 1e3, why,
      2.0 * fem::kKeptMatricesBytes / 1e6);  // each may hold an LDLᵀ beside its LLᵀ
  std::string out = text;
  std::string defaults;
  if (!c.numerics.rho_infinity_written) defaults += "numerics.rho_infinity = 0";
  if (!c.structure.fem_geometric_terms_written)
    defaults +=
        std::string(defaults.empty() ? "" : " and ") + "structure.newton_geometric_terms = \"current\"";
  if (!defaults.empty())
    out += "; left out of the case, it takes a film's " + defaults + " (docs/case_file.md, \"[structure]\")";
  if (c.numerics.rho_infinity_written && c.numerics.rho_infinity > kFilmRhoInfinity) {
    std::snprintf(
        text, sizeof text,
        "; numerics.rho_infinity = %g leaves its wrinkles ringing, where a film's default 0 removes them "
        "within a step",
        c.numerics.rho_infinity);
    out += text;
  }
  return out;
}

}  // namespace flapsim::app
