#include "pipeline/app/fem_mesh_resolution_warning.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "wings/planform_geometry.hpp"

namespace flapsim::app {

std::string fem_mesh_resolution_warning(const FsiSetup& setup) {
  if (!setup.fem_structure || !setup.wing) return "";
  const fem::Mesh& mesh = setup.fem_structure->structural.mesh;
  std::vector<double> sizes;  // [m]
  sizes.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    sizes.push_back(((mesh.nodes[t[1]] - mesh.nodes[t[0]]).norm() + (mesh.nodes[t[2]] - mesh.nodes[t[1]]).norm() +
                     (mesh.nodes[t[0]] - mesh.nodes[t[2]]).norm()) / 3.0);
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
