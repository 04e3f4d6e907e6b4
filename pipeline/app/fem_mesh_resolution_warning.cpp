#include "pipeline/app/fem_mesh_resolution_warning.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "wings/loader/planform_geometry.hpp"

namespace flapsim::app {

std::string fem_mesh_resolution_warning(const FsiSetup& setup) {
  if (!setup.fem_structure || !setup.wing) return "";
  const fem::Mesh& mesh = setup.fem_structure->structural.mesh;
  std::vector<double> sizes;  // [m]
  sizes.reserve(mesh.triangles.size());
  for (std::size_t e = 0; e < mesh.triangles.size(); ++e) sizes.push_back(mesh.triangle_mean_edge(e));
  if (sizes.empty()) return "";
  const auto median = sizes.begin() + static_cast<std::ptrdiff_t>(sizes.size() / 2);
  std::nth_element(sizes.begin(), median, sizes.end());
  const double chord = wings::planform_properties(setup.wing->outline).mean_chord;  // [m]
  const double across = chord / *median;
  if (!(*median > 0.0) || !(chord > 0.0) || across >= kMinFemElementsAcrossChord) return "";
  char text[700];
  std::snprintf(text, sizeof text,
                "the FEM's mesh has %.1f elements across the wing's mean chord (elements of %.3g mm, mean chord "
                "%.3g mm; %zu nodes): too coarse for the camber and chordwise twist a film wing's lift comes from, "
                "and the lattice follows its flat facets; make [structure] element_size_mm (or the wing file's "
                "[mesh] sizes) at most a quarter of the chord (docs/case_file.md, \"[structure]\")",
                across, *median * 1e3, chord * 1e3, mesh.nodes.size());
  return text;
}

}  // namespace flapsim::app
