#include "pipeline/io/trajectory_vtk.hpp"

#include <stdexcept>

namespace flapsim::io {

PolyDataMesh trajectory_mesh(const Trajectory& path, double period) {
  if (path.times.size() != path.points.size())
    throw std::invalid_argument("trajectory_mesh: " + std::to_string(path.times.size()) + " times for " +
                                std::to_string(path.points.size()) + " points");
  if (!(period > 0.0)) throw std::invalid_argument("trajectory_mesh: the period must be > 0");
  const Eigen::Index n = static_cast<Eigen::Index>(path.points.size());
  PolyDataMesh mesh;
  mesh.points.resize(3, n);
  Eigen::VectorXd t(n), phase(n);
  std::vector<int> line(static_cast<std::size_t>(n));
  for (Eigen::Index k = 0; k < n; ++k) {
    mesh.points.col(k) = path.points[static_cast<std::size_t>(k)];
    t(k) = path.times[static_cast<std::size_t>(k)];
    phase(k) = t(k) / period;
    line[static_cast<std::size_t>(k)] = static_cast<int>(k);
  }
  if (n >= 2) mesh.lines.push_back(std::move(line));
  mesh.point_data.add_scalar("t_s", t);
  mesh.point_data.add_scalar("t_over_T", phase);
  mesh.field_data.add_text("point", path.name);
  return mesh;
}

}  // namespace flapsim::io
