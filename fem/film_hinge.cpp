#include "fem/film_hinge.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include <Eigen/Geometry>

namespace flapsim::fem {

double film_hinge_angle(const std::array<Eigen::Vector3d, 4>& x, Eigen::Matrix<double, 12, 1>* grad) {
  const Eigen::Vector3d& a = x[0];
  const Eigen::Vector3d& b = x[1];
  const Eigen::Vector3d& c = x[2];
  const Eigen::Vector3d& d = x[3];
  const Eigen::Vector3d e = b - a;
  const double le = e.norm();
  const Eigen::Vector3d n1 = e.cross(c - a);  // triangle (a, b, c), |n1| = 2 A_c
  const Eigen::Vector3d n2 = (d - a).cross(e);  // triangle (b, a, d), same orientation when flat
  const double q1 = n1.squaredNorm(), q2 = n2.squaredNorm();
  if (!(q1 > 0.0 && q2 > 0.0 && le > 0.0)) throw std::invalid_argument("film_hinge_angle: degenerate hinge");
  // θ > 0 when d lies on the side n1 points to (the hinge folds toward n1).
  const double theta = std::atan2(n1.cross(n2).dot(e) / le, n1.dot(n2));
  if (grad != nullptr) {
    // ∂θ/∂c = −|e| n1/|n1|², ∂θ/∂d = −|e| n2/|n2|² (Bridson et al. 2003, §4, with this
    // sign of θ), and the edge's corners by the lever rule along e.
    const Eigen::Vector3d gc = -le * n1 / q1, gd = -le * n2 / q2;
    const double sc = (c - a).dot(e) / (le * le), sd = (d - a).dot(e) / (le * le);
    grad->segment<3>(6) = gc;
    grad->segment<3>(9) = gd;
    grad->segment<3>(0) = -(1.0 - sc) * gc - (1.0 - sd) * gd;
    grad->segment<3>(3) = -sc * gc - sd * gd;
  }
  return theta;
}

std::vector<FilmHinge> make_film_hinges(const std::vector<std::array<int, 3>>& triangles,
                                        const std::vector<double>& bending_stiffness,
                                        const std::vector<Eigen::Vector3d>& X) {
  if (bending_stiffness.size() != triangles.size())
    throw std::invalid_argument("make_film_hinges: one bending stiffness per triangle is required");
  // edge (lo, hi) → the triangles that have it, with their third corner
  std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> edges;
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int i = triangles[t][k], j = triangles[t][(k + 1) % 3], o = triangles[t][(k + 2) % 3];
      edges[{std::min(i, j), std::max(i, j)}].emplace_back(static_cast<int>(t), o);
    }
  std::vector<FilmHinge> hinges;
  for (const auto& [edge, sides] : edges) {
    if (sides.size() != 2) continue;
    const auto& t1 = triangles[static_cast<std::size_t>(sides[0].first)];
    // orient the edge as triangle 1 runs it, so (a, b, c) is triangle 1's orientation
    int a = edge.first, b = edge.second;
    for (int k = 0; k < 3; ++k)
      if (t1[k] == edge.second && t1[(k + 1) % 3] == edge.first) std::swap(a, b);
    FilmHinge h;
    h.nodes = {a, b, sides[0].second, sides[1].second};
    const std::array<Eigen::Vector3d, 4> p{X[a], X[b], X[h.nodes[2]], X[h.nodes[3]]};
    const double e2 = (p[1] - p[0]).squaredNorm();
    const double areas = 0.5 * ((p[1] - p[0]).cross(p[2] - p[0]).norm() + (p[1] - p[0]).cross(p[3] - p[0]).norm());
    const double D = 0.5 * (bending_stiffness[static_cast<std::size_t>(sides[0].first)] +
                            bending_stiffness[static_cast<std::size_t>(sides[1].first)]);
    h.stiffness = D * e2 / areas;
    h.rest_angle = film_hinge_angle(p, nullptr);
    hinges.push_back(h);
  }
  return hinges;
}

double film_hinge_force(const FilmHinge& h, const std::array<Eigen::Vector3d, 4>& x, Eigen::Matrix<double, 12, 1>& f,
                        Eigen::Matrix<double, 12, 12>* K) {
  Eigen::Matrix<double, 12, 1> g;
  double dtheta = film_hinge_angle(x, &g) - h.rest_angle;
  // the angle is continuous through ±π only modulo 2π
  if (dtheta > M_PI) dtheta -= 2.0 * M_PI;
  if (dtheta < -M_PI) dtheta += 2.0 * M_PI;
  f = h.stiffness * dtheta * g;
  if (K != nullptr) K->noalias() = h.stiffness * g * g.transpose();
  return 0.5 * h.stiffness * dtheta * dtheta;
}

}  // namespace flapsim::fem
