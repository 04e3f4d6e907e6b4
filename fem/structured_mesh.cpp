#include "fem/structured_mesh.hpp"

#include <stdexcept>

namespace flapsim::fem {

Mesh grid_mesh(int nx, int ny, const std::function<Eigen::Vector3d(double, double)>& map,
               Diagonal diagonal) {
  if (nx < 1 || ny < 1) throw std::invalid_argument("grid_mesh: need at least one cell each way");
  Mesh m;
  m.nodes.reserve(static_cast<size_t>((nx + 1) * (ny + 1)));
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      m.nodes.push_back(map(static_cast<double>(i) / nx, static_cast<double>(j) / ny));
  auto id = [nx](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      const bool flip = diagonal == Diagonal::Alternating && ((i + j) % 2 == 1);
      if (!flip) {
        m.triangles.push_back({a, b, c});
        m.triangles.push_back({a, c, d});
      } else {
        m.triangles.push_back({a, b, d});
        m.triangles.push_back({b, c, d});
      }
    }
  return m;
}

Mesh rectangle_mesh(double x0, double y0, double lx, double ly, int nx, int ny, Diagonal diagonal) {
  return grid_mesh(nx, ny, [=](double u, double v) {
    return Eigen::Vector3d(x0 + u * lx, y0 + v * ly, 0.0);
  }, diagonal);
}

Mesh line_mesh(const Eigen::Vector3d& a, const Eigen::Vector3d& b, int n) {
  if (n < 1) throw std::invalid_argument("line_mesh: need at least one element");
  Mesh m;
  for (int i = 0; i <= n; ++i) m.nodes.push_back(a + (b - a) * (static_cast<double>(i) / n));
  for (int i = 0; i < n; ++i) m.beams.push_back({{i, i + 1}, 0});
  m.vein_names.push_back("beam");
  return m;
}

}  // namespace flapsim::fem
