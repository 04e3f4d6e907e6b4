#include "fem/structural_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fem/section_properties.hpp"

namespace flapsim::fem {

ShellProperties shell_properties(const wings::Membrane& membrane) {
  ShellProperties s;
  s.thickness = membrane.thickness;
  s.youngs_modulus = membrane.material.youngs_modulus;
  s.poisson_ratio = membrane.material.poisson_ratio;
  s.density = membrane.material.density;
  s.nonstructural_mass_per_area = membrane.nonstructural_mass_per_area;
  return s;
}

double polyline_arc_fraction(const std::vector<Eigen::Vector2d>& line, const Eigen::Vector2d& p) {
  if (line.size() < 2) return 0.0;
  double total = 0.0, best_s = 0.0, best_d = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i + 1 < line.size(); ++i) {
    const Eigen::Vector2d a = line[i], d = line[i + 1] - line[i];
    const double len = d.norm();
    const double t = len > 0.0 ? std::clamp((p - a).dot(d) / (len * len), 0.0, 1.0) : 0.0;
    const double dist = (a + t * d - p).norm();
    if (dist < best_d) {
      best_d = dist;
      best_s = total + t * len;
    }
    total += len;
  }
  return total > 0.0 ? best_s / total : 0.0;
}

StructuralModel wing_structural_model(const wings::Wing& wing, Mesh mesh) {
  StructuralModel model;
  model.shell.assign(mesh.triangles.size(), shell_properties(wing.membrane));
  model.frame.reserve(mesh.beams.size());
  for (const BeamElement& b : mesh.beams) {
    const wings::Vein& vein = wing.veins.at(static_cast<size_t>(b.vein));
    const Eigen::Vector3d mid = 0.5 * (mesh.nodes[b.nodes[0]] + mesh.nodes[b.nodes[1]]);
    const double s = polyline_arc_fraction(vein.points, mid.head<2>());
    FrameProperties f;
    f.youngs_modulus = vein.material.youngs_modulus;
    f.shear_modulus = vein.material.youngs_modulus / (2.0 * (1.0 + vein.material.poisson_ratio));
    f.density = vein.material.density;
    f.section = section_properties(interpolate_section(vein.root_section, vein.tip_section, s));
    f.up = Eigen::Vector3d::UnitZ();
    model.frame.push_back(f);
  }
  model.mesh = std::move(mesh);
  return model;
}

}  // namespace flapsim::fem
