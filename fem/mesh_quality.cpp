#include "fem/mesh_quality.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "wings/loader/vein_junctions.hpp"

namespace flapsim::fem {

SmallestAngle smallest_triangle_angle(const Mesh& mesh) {
  SmallestAngle out;
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d& a = mesh.nodes[static_cast<std::size_t>(t[k])];
      const Eigen::Vector3d u = mesh.nodes[static_cast<std::size_t>(t[(k + 1) % 3])] - a;
      const Eigen::Vector3d v = mesh.nodes[static_cast<std::size_t>(t[(k + 2) % 3])] - a;
      // atan2(|u × v|, u · v): accurate for the thinnest angles, where acos loses digits.
      const double deg = std::atan2(u.cross(v).norm(), u.dot(v)) * 180.0 / std::numbers::pi;
      if (deg < out.degrees) {
        out.degrees = deg;
        out.centroid = (a + u / 3.0 + v / 3.0);
        out.longest_edge = std::max({u.norm(), v.norm(), (u - v).norm()});
      }
    }
  }
  return out;
}

std::string sliver_warning(const Mesh& mesh, const wings::Wing& wing) {
  const SmallestAngle s = smallest_triangle_angle(mesh);
  if (!(s.degrees < wings::kSliverAngleDeg)) return "";
  char text[900];
  std::snprintf(
      text, sizeof text,
      "%s: the wing's mesh has a sliver triangle, %.3g deg at its thinnest, %.3g mm long, near (x, y) = "
      "(%.4g, %.4g) mm: the FEM's Newton can stall on it. Slivers come from a vein's end or point a "
      "hair's breadth from the outline or from another vein (ends closer than tan(%.1f deg) times the "
      "vein element size are moved onto it), two veins close and nearly parallel, or two outline points "
      "a hair's breadth apart (a digitising duplicate): move the point onto the line it should meet, or "
      "apart, or drop it (docs/wing_file.md, \"Slivers\")",
      wing.source_file.c_str(), s.degrees, s.longest_edge * 1e3, s.centroid.x() * 1e3, s.centroid.y() * 1e3,
      wings::kSliverAngleDeg);
  return text;
}

}  // namespace flapsim::fem
